// A creep run as a case file describes it (rfmems-creep): a plate structure (the keys of
// physics/plate/plate_scene.hpp: mesh, material, model.structure: plate, thickness,
// boundaries, pressure; model.geometric_nonlinearity: the von Karman plate, whose membrane
// the plastic strains relax too, physics/creep/plate_creep_system.hpp), optionally the switch's
// actuation (physics/electrostatics/parallel_plate_field.hpp keys: gap, electrode, control,
// dielectric, fringing) with a hold voltage, and the creep section:
//
//   creep:
//     law: {A: 8.33e-6, B: 1.8e8, m: 2, n: 2, sigma_y0: 1 GPa}   # A [1/s] (number or Hz)
//     thickness_points: 21        # Simpson points through the thickness (odd, >= 3; 21)
//     integration: implicit       # implicit (IDA) | explicit (forward Euler, fixed dt)
//     dt: 1 h                     # explicit: the step
//     rtol: 1e-6                  # implicit: IDA tolerances (atol on strains and metres)
//     atol: 1e-12
//     end_time: 500 h             # times: a number [s] or "<x> s|ms|h|d"
//     outputs: 50                 # output times end_time k / outputs (k = 1..outputs),
//                                 # also the restart points of the integrator
//     lifetime:                   # needs actuation.gap
//       gap_threshold: 0 um       # stop when the smallest gap reaches it (0: touch-down)
//       collapse: true            # stop at the creep-induced pull-in (hold voltage; default
//       collapse_fraction: 1e-3   #   true with a voltage), see creep_run.hpp
//     checkpoint: {every_steps: 0, every_seconds: 0}   # 0: off (command-line flags override)
//   actuation:
//     gap: 3.75 um
//     control: [205 um, 5 um]
//     voltage: 100 V              # the hold voltage (0 or absent: pressure loads only)
//
// Probes (`probes:`, io/probes.hpp) name the deflections the time series records; without
// probes and with an actuation, the control point is the probe "control".
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/case_file.hpp"
#include "io/probes.hpp"
#include "materials/creep_law.hpp"
#include "physics/creep/creep_hold_voltage.hpp"
#include "physics/creep/creep_run.hpp"
#include "physics/plate/plate_scene.hpp"
#include "physics/structure/structural_model.hpp"

namespace rfmems {

struct CreepCase {
  std::unique_ptr<StructuralModel> structure;  // a PlateScene
  PlateScene* plate = nullptr;                 // the same, typed
  CreepLaw law;
  int thickness_intervals = 20;
  bool shear_creep = false;  // creep.shear_creep: transverse shear creeps too (KLU, no Schur)
  // The gap (actuation present): the gap elements over the electrode and g0.
  bool has_gap = false;
  std::vector<GapElement> gap_elements;
  Real initial_gap = 0;
  ParallelPlateLaw gap_law;              // the actuation's parallel-plate law
  std::optional<CreepHoldVoltage> hold;  // voltage > 0
  std::vector<Probe> probes;
  CreepRunSettings settings;  // without checkpoint path and hash (the driver's)
};

// Reads the keys above. InputError (one line: file, key, value) on anything wrong.
CreepCase read_creep_case(const CaseNode& root, const std::string& case_dir);

// A time key: a number [s], a Time quantity ("36 s", "10 ms") or "<x> h" / "<x> d" (hours,
// days: creep runs are long).
Real read_duration(const CaseNode& node, const std::string& key);
Real read_duration(const CaseNode& node, const std::string& key, Real default_value);

// The keys read_creep_case reads, the plate's, actuation's and probes' included
// (creep_case.keys.yaml; io/case_schema.hpp).
CaseSchema creep_case_keys();

}  // namespace rfmems

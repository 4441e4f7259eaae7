// The immersed-boundary switch as a case file describes it (issue 8; rfmems-pullin runs it
// when the case has an `immersed` block), and the study it asks for.
//
//   mesh / material / model / boundaries   the beam, as for rfmems-solid (model.structure:
//                                          plane; the anchor patch fixed, the others free)
//   immersed:
//     background: {lower: [0 um, 0 um], upper: [75 um, 10 um], cells: [150, 50]}
//     electrode: {x: [0 um, 45 um]}   # on the background's bottom (potential 0); the rest
//                                     # of the bottom, the sides and the top: zero flux
//     anchor_patch: left              # beam patch clamped in the wall (default left)
//     facing_patch: bottom            # beam patch over the electrode (default bottom)
//     anchor_extension: 0.5 um        # the anchored face pushed into the wall (default one
//                                     # background cell)
//     control: [45 um, 1.5 um]        # the point whose deflection is reported and
//                                     # controlled (the tip), read from its cell's
//                                     # reconstruction, not at the cell's centroid
//     electrostatics_distributed: false  # under mpirun: the field solved over the ranks
//                                     # (GMRES + additive Schwarz KLU; every rank runs the
//                                     # switch), else redundantly by KLU on every rank
//   pull_in:
//     mode: dynamic                   # dynamic | transient | static | quasi_static
//     contact_gap: 0.3 um             # touch-down gap (default 1.5 background cell heights:
//                                     # the IB layer cannot resolve a thinner gap)
//     dynamic: {bracket: [100 V, 140 V], tolerance: 1 V, end_time: 6 us}
//       time_check: 0.1               # the upper end's step once more to contact at this
//                                     # fraction of the solver's tolerances: the pull-in
//                                     # time's error estimate (0: none; default 0.1, 0 with
//                                     # the esbgk gas, where it is one more 10-40 min run)
//     transient: {voltage: 80 V, end_time: 4 us, output_interval: 0.01 us}
//     static: {voltage: 50 V}
//     quasi_static: {points: 16, max_fraction: 0.6, voltage_tolerance: 0.05 V}
//   coupling: {scheme: staggered}     # staggered (IBM load refreshed after every IDA step)
//                                     # | implicit (IBM load inside every residual)
//                                     # | strong (Aitken-relaxed iterations per step on the
//                                     # electrostatic load, the step redone until
//     tolerance: 1e-6                 # |F_IBM - F_applied| <= tolerance |F_IBM|, at most
//     max_iterations: 20              # max_iterations per step)
//     gas_every: 1                    # the gas advanced over every k-th accepted step (one
//                                     # gas step spanning k structure steps, force held)
//     strong_gas: false               # scheme strong: true puts the gas inside the
//                                     # iterations (redone per iterate, the fixed point on
//                                     # the electrostatic + gas load; gas_every 1)
//   gas:                              # the gas slot: none (default) | reynolds | esbgk
//     model: reynolds                 # 1D film under the beam, open at the tip
//     pressure: 1.36e4 Pa
//     temperature: 300 K
//     viscosity: 1.712e-5 Pa*s        # mu0 at 273.15 K, times (T / 273.15)^omega
//     omega: 0.74
//     rarefaction: veijola            # veijola (default) | none
//     # esbgk (immersed_esbgk_gas.hpp): the kinetic gas on the background; electrode,
//     # substrate and left diffuse at T, top and right pressure (p, T)
//     collision: esbgk                # esbgk (default) | bgk
//     velocities: 10                  # per direction (n^3 grid), extent velocity_extent
//     velocity_extent: 3.5            # half-width in thermal speeds sqrt(2 R T)
//     step_tolerance: 1e-5            # the gas step's residual / ||alpha V h / dt||
//     smoother: point                 # point (COMET cell solve) | downwind | both
//     predictor: true                 # start each step from the extrapolated f
//     max_step_sweeps: 2000
//     transport: first_order          # | second_order, with limiter, limiter_k and
//                                     # boundary_reconstruction as for rfmems-gas's solver
//                                     # (kinetic_case.hpp; immersed_kinetic_gas.hpp)
//   solver: {rtol: 1e-4, atol: 1.5e-11 m, max_order: 2}
//     fixed_step: 0                   # > 0: IDA at this fixed step (no error test; cut to
//                                     # 1e-4 of it only after a failed Newton solve)
#pragma once
#include <memory>
#include <string>

#include "coupling/immersed_switch.hpp"
#include "io/case_file.hpp"
#include "io/json_summary.hpp"
#include "io/result_writer.hpp"
#include "physics/elasticity/elasticity_scene.hpp"

namespace rfmems {

struct ImmersedSwitchCase {
  std::unique_ptr<ElasticityScene> beam;
  ImmersedSwitchGeometry geometry;
  std::unique_ptr<ImmersedSwitch> scene;
  std::unique_ptr<ImmersedGasModel> gas;  // null: none
  std::string mode;
  ImmersedRunOptions run;
  Real bracket_low = 0, bracket_high = 0, tolerance = 1;
  Real time_check = 0.1;  // pull_in.dynamic.time_check (pull_in_study.hpp's key)
  Real voltage = 0;  // transient / static
  QuasiStaticOptions quasi_static;
  Real mean_free_path = 0;  // gas: at the ambient pressure
};

ImmersedSwitchCase read_immersed_switch_case(const CaseNode& root, const std::string& case_dir);

// A fresh gas model of the case (each run starts the gas at rest); null for none.
std::unique_ptr<ImmersedGasModel> make_case_gas(const CaseNode& root, const ImmersedSwitch& scene,
                                                const ImmersedSwitchGeometry& geometry,
                                                Real* mean_free_path = nullptr);

// Runs the case's study; writes the curve and histories (pull_in_results.hpp; the contact
// force is 0) and the beam's displacement at the end (field 0); returns
// the --json summary part, with the CPU per physics, the gas's largest Knudsen number and
// validity_warnings (contact gap below a background cell; Reynolds film at Kn > 1 or followed
// below half the gap).
Json run_immersed_switch_study(ImmersedSwitchCase& c, const CaseNode& root, ResultWriter& writer);

}  // namespace rfmems

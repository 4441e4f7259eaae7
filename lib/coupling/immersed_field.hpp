// The immersed-boundary field of a switch (actuation.electrostatics: immersed, switch_scene.hpp):
// a plane beam on its own mesh moving through a fixed Cartesian background that carries the
// potential and the gas (ibm/immersed_boundary_field.hpp), as the case describes it:
//
//   actuation:
//     electrostatics: immersed
//     electrode: {x: [0 um, 45 um]}   # on the background's bottom (potential 0); the rest
//                                     # of the bottom, the sides and the top: zero flux
//     facing_patch: bottom            # beam patch over the electrode (default bottom)
//     control: [45 um, 1.5 um]        # the point whose deflection is reported and controlled
//                                     # (the tip), read from its cell's reconstruction
//     immersed:
//       background: {lower: [0 um, 0 um], upper: [75 um, 10 um], cells: [150, 50]}
//       anchor_patch: left            # beam patch clamped in the wall (default left)
//       anchor_extension: 0.5 um      # the anchored face pushed into the wall (default one
//                                     # background cell)
//       electrostatics_distributed: false  # under mpirun: the field solved over the ranks
//                                     # (GMRES + additive Schwarz KLU; every rank runs the
//                                     # switch), else redundantly by KLU on every rank
//   gas:                              # none (default) | reynolds | esbgk
//     model: reynolds                 # 1D film under the beam, open at the tip
//     pressure: 1.36e4 Pa             # and temperature, viscosity, omega, mean_free_path,
//                                     # rarefaction: physics/gas/ambient_gas.hpp
//     # esbgk (ibm/immersed_esbgk_gas.hpp): the kinetic gas on the background; electrode,
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
//     stepper: sweeps                 # | ida: IDA over each gas step (BDF at ida_rtol,
//     ida_rtol: 1e-6                  # GMRES with COMET's arrowhead preconditioner); one rank
#pragma once
#include <memory>
#include <string>

#include "coupling/scene_combinations.hpp"
#include "ibm/immersed_boundary_field.hpp"
#include "ibm/immersed_esbgk_gas.hpp"
#include "io/case_file.hpp"
#include "materials/gas_properties.hpp"
#include "physics/elasticity/elasticity_scene.hpp"

namespace rfmems {

// The gas section of an immersed scene, read once (every key, whatever the model).
struct ImmersedGasSettings {
  GasModel model = GasModel::None;
  GasProperties film;             // reynolds (film.mean_free_path: at the ambient pressure)
  ImmersedEsbgkSettings kinetic;  // esbgk
};

struct ImmersedField {
  ImmersedBoundaryGeometry geometry;
  std::unique_ptr<ImmersedBoundaryField> sw;
  ImmersedGasSettings gas;
  // A fresh gas of the case around the beam's surface (each run starts the gas at rest); null
  // for none.
  std::unique_ptr<StructureGas> make_gas() const;
};

// actuation (electrode, facing_patch, control, immersed) and the gas section (its model, as
// read_scene_choice read it), for `beam`.
std::unique_ptr<ImmersedField> read_immersed_field(const CaseNode& root, ElasticityScene& beam,
                                                   GasModel gas);

// actuation.immersed.electrostatics_distributed: under mpirun, the field solved over the ranks
// (every rank runs the switch).
bool immersed_electrostatics_distributed(const CaseNode& root);

// The keys read_immersed_field reads besides the actuation's electrode and control
// (immersed_field.keys.yaml; io/case_schema.hpp).
CaseSchema immersed_case_keys();

}  // namespace rfmems

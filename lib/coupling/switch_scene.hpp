// An electrostatically actuated switch as a case file describes it: the structure
// (model.structure: plate | plane, physics/structure/structure_from_case.hpp), the field that
// pulls it (actuation), the gas under it (gas) and the analysis (pull_in.mode), one model per
// slot from the table of scene_combinations.hpp.
//
//   actuation:
//     electrostatics: parallel_plate  # parallel_plate (default) | laplace | immersed
//     gap: 3.75 um                    # air gap at rest, structure to electrode (parallel_plate,
//                                     # laplace; immersed: from the beam's place in the
//                                     # background)
//     electrode: {x: [160 um, 240 um], y: [0 um, 40 um]}   # optional; default: everywhere
//                                     # (y: plates only; immersed: x required)
//     electrodes:                     # or several (parallel_plate): the electrodes at the
//       - {x: [0 um, 40 um]}          # voltage, e.g. the two actuation electrodes of a
//       - {x: [260 um, 300 um]}       # varactor; they must not overlap
//     facing_patch: bottom            # plane structures: the beam face over the electrode
//     control: [200 um, 20 um]        # the point whose deflection is controlled and reported
//     dielectric: {thickness: 0.1 um, permittivity: 7.6}   # parallel_plate, optional
//     fringing: 0.65                  # parallel_plate, optional first-order fringing factor
//                                     # (plates: width = the mesh's extent in y)
//     contact:                        # parallel_plate, optional: the structure can rest on
//       gap: 75 nm                    # the dielectric; air gap at which the surfaces touch
//                                     # (default 2 % of gap)
//       penetration: 7.5 nm           # penalty's penetration tolerance (default 10 %, at most
//                                     # 20 % of the contact gap; contact_penalty.hpp)
//     laplace: {gap_cells: 16}        # laplace: cells across the gap mesh
//     immersed:                       # immersed: the background mesh and the beam's anchor
//       background: {lower: [0 um, 0 um], upper: [75 um, 10 um], cells: [150, 50]}
//       anchor_patch: left            # beam patch clamped in the wall (default left)
//       anchor_extension: 0.5 um      # the anchored face pushed into the wall (default one
//                                     # background cell)
//       electrostatics_distributed: false  # under mpirun: the field solved over the ranks
//
//   gas:                              # optional (default none)
//     model: reynolds                 # none | reynolds | esbgk (scene_combinations.hpp)
//     ...                             # parallel_plate: the film under the plate (below);
//                                     # immersed: immersed_field.hpp
//     pressure: 1 atm                 # ambient pressure; temperature, viscosity, omega,
//                                     # mean_free_path, rarefaction: physics/gas/ambient_gas.hpp
//     boundaries: {left: wall, right: wall, top: open, bottom: open}
//                                     # default per plate edge: open where the plate edge is
//                                     # free or loaded, wall where it is supported
//
// The structure hangs above the electrode: its gap-facing unknown (a plate's w, a plane
// beam's u_y) positive opens the gap. The parallel-plate and Laplace fields control the
// unknown of the cell nearest the control point; the immersed field reads the deflection at
// the point itself, from its cell's reconstruction.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "coupling/immersed_field.hpp"
#include "coupling/scene_combinations.hpp"
#include "io/case_file.hpp"
#include "physics/electrostatics/laplace_gap_field.hpp"
#include "physics/electrostatics/parallel_plate_field.hpp"
#include "physics/gas/reynolds_film.hpp"
#include "physics/structure/structural_model.hpp"

namespace rfmems {

struct SwitchScene {
  SceneChoice choice;
  std::unique_ptr<StructuralModel> structure;
  Real gap = 0;        // at rest
  Index control = -1;  // parallel_plate, laplace: the controlled unknown
  std::unique_ptr<ParallelPlateActuation> actuation;  // parallel_plate, laplace
  std::unique_ptr<ReynoldsFilm> film;                 // parallel_plate with gas: reynolds
  std::unique_ptr<LaplaceGapField> laplace;           // laplace
  std::unique_ptr<ImmersedField> immersed;            // immersed (with its gas)

  FieldModel field() const { return choice.models.field; }
  // actuation.contact, the parallel-plate field's (penetration 0: none).
  ContactPenalty contact() const { return actuation ? actuation->contact() : ContactPenalty{}; }
  GasModel gas() const { return choice.models.gas; }
  // The smallest gap the field resolves: the immersed boundary's layer fills 1.5 background
  // cells (the touch-down cannot be thinner); 0 for the others.
  Real resolvable_gap() const;
};

// Reads the scene (the slots checked against the table first, scene_combinations.hpp; the
// parallel-plate and Laplace fields' common keys by read_parallel_plate_field).
SwitchScene build_switch_scene(const CaseNode& root, const std::string& case_dir);

// The keys build_switch_scene reads, its structure's, field's and gas's included
// (switch_scene.keys.yaml; io/case_schema.hpp).
CaseSchema switch_case_keys();

}  // namespace rfmems

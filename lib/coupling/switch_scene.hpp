// An electrostatically actuated switch as a case file describes it: the structure
// (model.structure: plate | plane, physics/structure/structure_from_case.hpp), the electrode
// under it, the electrostatics model and the control point.
//
//   actuation:
//     gap: 3.75 um                    # air gap at rest, between the structure and the electrode
//     electrostatics: parallel_plate  # parallel_plate (default) | laplace (plane structures)
//     electrode: {x: [160 um, 240 um], y: [0 um, 40 um]}   # optional; default: everywhere
//     electrodes:                     # or several (parallel_plate): the electrodes at the
//       - {x: [0 um, 40 um]}          # voltage, e.g. the two actuation electrodes of a
//       - {x: [260 um, 300 um]}       # varactor; they must not overlap
//     facing_patch: bottom            # plane structures: the beam face over the electrode
//     control: [200 um, 20 um]        # the point whose deflection is controlled and reported
//     dielectric: {thickness: 0.1 um, permittivity: 7.6}   # parallel_plate, optional
//     fringing: 0.65                  # parallel_plate, optional first-order fringing factor
//                                     # (plates: width = the mesh's extent in y)
//     contact:                        # optional: the structure can rest on the dielectric
//       gap: 75 nm                    # air gap at which the surfaces touch (default 2 % of gap)
//       penetration: 7.5 nm           # penalty's penetration tolerance (default 10 %, at most
//                                     # 20 % of the contact gap; contact_penalty.hpp)
//     laplace: {gap_cells: 16}        # laplace: cells across the gap mesh
//
//   gas:                              # optional (default none): the squeeze film under a plate
//     model: reynolds                 # none | reynolds
//     pressure: 1 atm                 # ambient pressure
//     viscosity: 1.85e-5 Pa*s         # air at 300 K (default)
//     mean_free_path: 68 nm           # at 1 atm (default; scales as 1/p)
//     rarefaction: veijola            # veijola (default) | none
//     boundaries: {left: wall, right: wall, top: open, bottom: open}
//                                     # default per plate edge: open where the plate edge is
//                                     # free or loaded, wall where it is supported
//
// The structure hangs above the electrode: its gap-facing unknown (a plate's w, a plane
// beam's u_y) positive opens the gap. The control point selects the cell nearest to it; its
// deflection is what the quasi-static continuation prescribes and the dynamic runs report.
#pragma once
#include <memory>
#include <string>

#include "coupling/parallel_plate_actuation.hpp"
#include "coupling/switch_system.hpp"
#include "physics/gas/reynolds_film.hpp"
#include "io/case_file.hpp"
#include "physics/structure/structural_model.hpp"

namespace rfmems {

enum class ElectrostaticsModel { ParallelPlate, Laplace };

struct SwitchScene {
  std::unique_ptr<StructuralModel> structure;
  ElectrostaticsModel electrostatics = ElectrostaticsModel::ParallelPlate;
  Real gap = 0;
  ElectrodeExtent electrode;                // the first of `electrodes` (laplace: the only one)
  std::vector<ElectrodeExtent> electrodes;  // at least one
  std::string facing_patch;       // plane structures
  Vec3 control_point = Vec3::Zero();
  Index control = -1;             // the controlled unknown
  int laplace_gap_cells = 16;
  ContactPenalty contact;         // actuation.contact (penetration 0: none)
  std::unique_ptr<ParallelPlateActuation> actuation;  // parallel_plate (also built for laplace
                                                     // scenes: the dynamic model)
  std::unique_ptr<ReynoldsFilm> film;                 // gas: reynolds
  // The switch's transient system: ActuatedStructureSystem, or SqueezeFilmSwitchSystem with
  // a film.
  std::unique_ptr<SwitchSystem> make_transient_system() const;
};

SwitchScene build_switch_scene(const CaseNode& root, const std::string& case_dir,
                               AnalysisType analysis);

}  // namespace rfmems

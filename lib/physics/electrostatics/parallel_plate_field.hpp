// The parallel-plate field of a structure over its electrodes, as a case describes it (the
// actuation section; every key in coupling/switch_scene.hpp): the gap at rest, the electrodes,
// the law (dielectric, fringing), the control point and the contact with the dielectric. The
// pull-in study and the creep run's hold voltage read it here, one reader for both.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "io/case_file.hpp"
#include "physics/electrostatics/parallel_plate_actuation.hpp"
#include "physics/structure/structural_model.hpp"

namespace rfmems {

struct ParallelPlateField {
  Real gap = 0;                             // at rest
  std::vector<ElectrodeExtent> electrodes;  // at least one
  std::string facing_patch;                 // plane structures (default bottom)
  Vec3 control_point = Vec3::Zero();
  Index control_cell = -1;
  Index control = -1;      // the controlled unknown: structure.gap_unknown(control_cell)
  ContactPenalty contact;  // contact (penetration 0: none)
  std::unique_ptr<ParallelPlateActuation> actuation;
};

// actuation: gap, electrode | electrodes, facing_patch, control, dielectric, fringing, contact.
ParallelPlateField read_parallel_plate_field(const CaseNode& actuation, StructuralModel& structure);

// The electrodes of an actuation section: `electrode` (one; default everywhere) or
// `electrodes` (a list of non-overlapping ones); y extents only for a plate.
std::vector<ElectrodeExtent> read_electrodes(const CaseNode& actuation, bool plate);

// The keys read_parallel_plate_field reads (parallel_plate_field.keys.yaml; io/case_schema.hpp).
CaseSchema parallel_plate_case_keys();

}  // namespace rfmems

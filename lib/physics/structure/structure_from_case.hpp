// The structural model a case asks for, by name:
//
//   model:
//     structure: plane     # plane stress/strain continuum on a 2D mesh (default for 2D meshes)
//              | solid3d   # 3D continuum (default for 3D meshes)
//              | plate     # Mindlin-Reissner plate on a 2D mid-surface mesh
//
// See physics/elasticity/elasticity_scene.hpp and physics/plate/plate_scene.hpp for the keys
// of each.
#pragma once
#include <memory>
#include <string>

#include "io/case_file.hpp"
#include "physics/structure/structural_model.hpp"

namespace rfmems {

std::unique_ptr<StructuralModel> build_structure(const CaseNode& root, const std::string& case_dir,
                                                 AnalysisType analysis);

// The keys build_structure reads for either model, the mesh's included
// (structure_from_case.keys.yaml; io/case_schema.hpp).
CaseSchema structure_case_keys();

}  // namespace rfmems

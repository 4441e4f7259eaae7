#include "physics/structure/structure_from_case.hpp"

#include "io/case_schema_yaml.hpp"
#include "io/mesh_from_case.hpp"
#include "physics/elasticity/elasticity_scene.hpp"
#include "physics/plate/plate_scene.hpp"

namespace rfmems {

std::unique_ptr<StructuralModel> build_structure(const CaseNode& root, const std::string& case_dir,
                                                 AnalysisType analysis) {
  // The one reader of model.structure; absent, the continuum the mesh's dimension says.
  const CaseNode model = root.child("model");
  const std::string structure =
      model.has("structure") ? model.get_choice("structure", {"plane", "solid3d", "plate"}) : "";
  // The one reader of model.geometric_nonlinearity: the von Karman plate, or the total
  // Lagrangian continuum.
  const bool nonlinear = model.get_bool("geometric_nonlinearity", false);
  if (structure == "plate")
    return std::make_unique<PlateScene>(build_plate_scene(root, case_dir, analysis, nonlinear));
  return std::make_unique<ElasticityScene>(
      build_elasticity_scene(root, case_dir, analysis, structure, nonlinear));
}

CaseSchema structure_case_keys() {
  return join_schemas(
      {mesh_case_keys(), embedded_case_schema("physics/structure/structure_from_case.keys.yaml")});
}

}  // namespace rfmems

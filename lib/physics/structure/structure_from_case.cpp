#include "physics/structure/structure_from_case.hpp"

#include "physics/elasticity/elasticity_scene.hpp"
#include "physics/plate/plate_scene.hpp"

namespace rfmems {

std::unique_ptr<StructuralModel> build_structure(const CaseNode& root, const std::string& case_dir,
                                                 AnalysisType analysis) {
  const CaseNode model = root.child("model");
  // The continuum scene reads (and checks) plane/solid3d itself against the mesh.
  const bool plate = model.has("structure") &&
                     model.get_choice("structure", {"plane", "solid3d", "plate"}) == "plate";
  if (plate) return std::make_unique<PlateScene>(build_plate_scene(root, case_dir, analysis));
  return std::make_unique<ElasticityScene>(build_elasticity_scene(root, case_dir, analysis));
}

}  // namespace rfmems

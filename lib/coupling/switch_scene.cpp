#include "coupling/switch_scene.hpp"

#include <fmt/format.h>

#include "coupling/coupling_settings.hpp"
#include "coupling/immersed_field.hpp"
#include "coupling/scene_combinations.hpp"
#include "io/case_schema_yaml.hpp"
#include "physics/elasticity/elasticity_scene.hpp"
#include "physics/electrostatics/parallel_plate_field.hpp"
#include "physics/gas/ambient_gas.hpp"
#include "physics/plate/plate_operator.hpp"
#include "physics/structure/structure_from_case.hpp"

namespace rfmems {

namespace {

// The squeeze film under a plate (see the header); null without one.
std::unique_ptr<ReynoldsFilm> read_gas(const CaseNode& root, const SwitchScene& s) {
  if (!root.has("gas")) return nullptr;
  const CaseNode gas = root.child("gas");
  // model: none switches the film off but still checks its keys (a case toggled by --set).
  const bool none = s.gas() == GasModel::None;
  const GasProperties g = read_ambient_gas(gas, !none).film;
  const Mesh& mesh = s.structure->structure_mesh();
  const CaseNode bcs = root.child("boundaries");
  const CaseNode given = gas.child_or_empty("boundaries");
  for (const std::string& key : given.keys())
    if (mesh.find_patch(key) < 0) given.fail(key, "the mesh has no such patch");
  std::vector<FilmBoundary> film_bcs;
  for (const Patch& p : mesh.patches()) {
    const std::string structural = bcs.child(p.name).get_string("type");
    const std::string fallback = structural == "free" || structural == "load" ? "open" : "wall";
    const std::string kind = given.get_choice(p.name, {"open", "wall"}, fallback);
    film_bcs.push_back({kind == "open" ? FilmBoundary::Kind::Open : FilmBoundary::Kind::Wall});
  }
  if (none) return nullptr;
  return std::make_unique<ReynoldsFilm>(mesh, g, std::move(film_bcs));
}

}  // namespace

Real SwitchScene::resolvable_gap() const {
  return immersed ? std::min(1.5 * immersed->sw->background_cell_height(), 0.5 * gap) : 0.0;
}

SwitchScene build_switch_scene(const CaseNode& root, const std::string& case_dir) {
  SwitchScene s;
  s.choice = read_scene_choice(root);
  // The immersed field's turning root and velocity weights need the beam's density always.
  const bool inertia =
      steps_in_time(s.choice.analysis) || s.choice.models.field == FieldModel::Immersed;
  s.structure =
      build_structure(root, case_dir, inertia ? AnalysisType::Transient : AnalysisType::Static);
  const bool plate = s.structure->kind() == "plate";
  // The switch's solvers stop above the plate's round-off floor (IDA's tolerances, KINSOL's
  // floor): its residual as one product with its stiffness, the dearest part of an IDA step
  // after the LU otherwise.
  if (auto* op = dynamic_cast<PlateOperator*>(&s.structure->structure()))
    op->set_residual_by_stiffness(true);
  const Mesh& mesh = s.structure->structure_mesh();
  root.child("model").require(plate || mesh.dim() == 2, "structure",
                              "a switch is a plate or a plane (2D) beam");
  const CaseNode act = root.child("actuation");
  // Each field's own physics only with that field (the Laplace gap mesh's resolution is read
  // whatever the field, so that a plane case switches between parallel_plate and laplace by
  // --set).
  const std::vector<std::pair<std::string, FieldModel>> own = {
      {"dielectric", FieldModel::ParallelPlate},
      {"fringing", FieldModel::ParallelPlate},
      {"contact", FieldModel::ParallelPlate},
      {"electrodes", FieldModel::ParallelPlate},
      {"immersed", FieldModel::Immersed}};
  for (const auto& [key, field] : own)
    act.require(s.field() == field || !act.has(key), key,
                "only with actuation.electrostatics: " + field_name(field));
  // The Laplace and immersed fields find equilibria by fixed points on the stiffness at rest
  // (field_coupled_structure.hpp): a linear structure's.
  if (const auto* beam = dynamic_cast<const ElasticityScene*>(s.structure.get()))
    root.child("model").require(
        !beam->op->geometric_nonlinearity() || s.field() == FieldModel::ParallelPlate,
        "geometric_nonlinearity",
        "the Laplace and immersed fields couple a linear structure (use actuation.electrostatics: "
        "parallel_plate)");
  if (s.field() == FieldModel::Immersed) {
    auto* beam = dynamic_cast<ElasticityScene*>(s.structure.get());
    s.immersed = read_immersed_field(root, *beam, s.gas());
    s.gap = s.immersed->sw->rest_gap();
    return s;
  }
  ParallelPlateField field = read_parallel_plate_field(act, *s.structure);
  s.gap = field.gap;
  s.control = field.control;
  s.actuation = std::move(field.actuation);
  LaplaceGapOptions laplace;
  laplace.gap_cells = static_cast<int>(
      act.child_or_empty("laplace").get_int("gap_cells", 16, Range::closed(2, 10000)));
  if (s.field() == FieldModel::Laplace)
    s.laplace = std::make_unique<LaplaceGapField>(*dynamic_cast<ElasticityScene&>(*s.structure).op,
                                                  field.facing_patch, s.gap,
                                                  field.electrodes.front(), laplace);
  s.film = read_gas(root, s);
  return s;
}

CaseSchema switch_case_keys() {
  return join_schemas({scene_choice_case_keys(), structure_case_keys(), parallel_plate_case_keys(),
                       ambient_gas_case_keys(),
                       embedded_case_schema("coupling/switch_scene.keys.yaml"),
                       immersed_case_keys(), coupling_case_keys()});
}

}  // namespace rfmems

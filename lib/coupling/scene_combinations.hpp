// What a switch scene combines, and the one table of the combinations rfmems runs. A case names
// one model per slot, in the same keys for every scene:
//
//   model.structure            plate | plane                        the structure
//   actuation.electrostatics   parallel_plate | laplace | immersed  the field (default
//                                                                   parallel_plate)
//   gas.model                  none | reynolds | esbgk              the gas (default none)
//   pull_in.mode               static | quasi_static | dynamic | transient   the analysis
//   coupling.scheme            monolithic | staggered | implicit | strongly_coupled
//
// The field models: parallel_plate, the local law p = eps V^2 / (2 g^2) on the structure's
// facing side (exact Jacobian blocks); laplace, the field in a gap mesh that follows a plane
// beam; immersed, the field on a fixed background mesh through which the beam's surface moves
// (the immersed boundary). The gas models: reynolds, the squeeze film (on a plate's mesh with
// parallel_plate; a 1D film along the beam's facing side with immersed); esbgk, the kinetic gas
// on the immersed field's background.
//
// The coupling schemes of the time-stepping analyses (dynamic, transient):
//   monolithic        one IDA system of every model with the exact coupled Jacobian (every model
//                     gives exact blocks: the parallel-plate law and the Reynolds film);
//   staggered         what gives no exact blocks refreshed once per accepted structural step:
//                     the field's load lagged with the parallel-plate gap scaling inside the
//                     step (laplace, immersed), the gas advanced and its force held over the
//                     next step (every gas; the parallel-plate field stays exact in the
//                     structure);
//   implicit          the field solved inside every residual of the structure;
//   strongly_coupled  each step redone with Aitken-relaxed iterations on the interface load
//                     (field, and gas where it is iterated) until it converges.
// The first scheme a row lists is its default. The static analyses (static, quasi_static) solve
// the coupled equilibrium to convergence and use no scheme: a scheme in the case is then not
// used, so that a case switched between analyses by --set stays valid.
//
// Anything outside the table is bad input: the key whose value leaves it is named with the
// values that are allowed instead (read_scene_choice).
#pragma once
#include <string>
#include <vector>

#include "io/case_file.hpp"

namespace rfmems {

enum class StructureModel { Plate, Plane };
enum class FieldModel { ParallelPlate, Laplace, Immersed };
enum class GasModel { None, Reynolds, Esbgk };
enum class Analysis { Static, QuasiStatic, Dynamic, Transient, Harmonic };
enum class CouplingScheme { Monolithic, Staggered, Implicit, StronglyCoupled };

// The case-file spellings.
std::string structure_name(StructureModel structure);
std::string field_name(FieldModel field);
std::string gas_name(GasModel gas);
std::string analysis_name(Analysis analysis);
std::string coupling_scheme_name(CouplingScheme scheme);

// Dynamic and transient step in time (and take a coupling scheme); the others do not.
bool steps_in_time(Analysis analysis);

struct SceneModels {
  StructureModel structure = StructureModel::Plate;
  FieldModel field = FieldModel::ParallelPlate;
  GasModel gas = GasModel::None;
  bool operator==(const SceneModels&) const = default;
};

// One row of the table: a combination of models, an analysis it runs and the schemes it steps
// with (the first the default; empty for the static analyses).
struct SceneRow {
  SceneModels models;
  Analysis analysis;
  std::vector<CouplingScheme> schemes;
};
const std::vector<SceneRow>& scene_table();

// The table as Markdown (one line per combination of models: its analyses and schemes).
std::string scene_table_markdown();

struct SceneChoice {
  SceneModels models;
  Analysis analysis = Analysis::QuasiStatic;
  CouplingScheme scheme = CouplingScheme::Monolithic;  // steps_in_time(analysis) only
};

// Reads the five slots (keys above) and checks them against the table, in the order structure,
// field, gas, analysis, scheme: the first value that leaves the table is bad input naming its
// key and the values allowed there with the slots before it. model.structure (absent: plane, the
// continuum the structure reader builds) is left for the structure reader to check.
SceneChoice read_scene_choice(const CaseNode& root);

// The keys read_scene_choice reads: the scene's models, analysis and scheme
// (scene_combinations.keys.yaml; io/case_schema.hpp).
CaseSchema scene_choice_case_keys();

}  // namespace rfmems

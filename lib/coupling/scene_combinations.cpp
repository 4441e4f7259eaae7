#include "coupling/scene_combinations.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "io/case_schema_yaml.hpp"

namespace rfmems {

namespace {

const std::vector<std::string> kStructures = {"plate", "plane"};
const std::vector<std::string> kFields = {"parallel_plate", "laplace", "immersed"};
const std::vector<std::string> kGases = {"none", "reynolds", "esbgk"};
const std::vector<std::string> kAnalyses = {"static", "quasi_static", "dynamic", "transient",
                                            "harmonic"};
const std::vector<std::string> kSchemes = {"monolithic", "staggered", "implicit",
                                           "strongly_coupled"};

template <class E>
E from_name(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  return static_cast<E>(it - names.begin());
}

std::vector<SceneRow> build_table() {
  using S = StructureModel;
  using F = FieldModel;
  using G = GasModel;
  using A = Analysis;
  using C = CouplingScheme;
  std::vector<SceneRow> rows;
  auto add = [&](SceneModels m, std::vector<A> analyses, std::vector<C> schemes) {
    for (A a : analyses) rows.push_back({m, a, steps_in_time(a) ? schemes : std::vector<C>{}});
  };
  // The parallel-plate law and the Reynolds film give exact Jacobian blocks: one IDA system,
  // which the harmonic analysis linearises. Partitioned, the film is split from the plate.
  const std::vector<A> exact = {A::QuasiStatic, A::Dynamic, A::Transient, A::Harmonic};
  add({S::Plate, F::ParallelPlate, G::None}, exact, {C::Monolithic});
  add({S::Plate, F::ParallelPlate, G::Reynolds}, exact,
      {C::Monolithic, C::Staggered, C::StronglyCoupled});
  add({S::Plane, F::ParallelPlate, G::None}, exact, {C::Monolithic});
  // The Laplace field in the moving gap mesh and the immersed field give no exact blocks: the
  // field-coupled structure's schemes (field_coupled_structure.hpp).
  add({S::Plane, F::Laplace, G::None}, {A::Static, A::QuasiStatic, A::Dynamic, A::Transient},
      {C::Staggered, C::Implicit, C::StronglyCoupled});
  for (G gas : {G::None, G::Reynolds, G::Esbgk})
    add({S::Plane, F::Immersed, gas}, {A::Static, A::QuasiStatic, A::Dynamic, A::Transient},
        {C::Staggered, C::Implicit, C::StronglyCoupled});
  return rows;
}

std::string join(const std::vector<std::string>& names, const std::string& separator = " | ") {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : separator) + n;
  return out;
}

// The names of `all` that some row matching `match` has (in the order of `all`).
template <class Match, class Value>
std::vector<std::string> allowed(const std::vector<std::string>& all, Match match, Value value) {
  std::vector<std::string> out;
  for (const SceneRow& row : scene_table())
    if (match(row)) {
      const std::string name = all[static_cast<std::size_t>(value(row))];
      if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
    }
  std::vector<std::string> ordered;
  for (const std::string& n : all)
    if (std::find(out.begin(), out.end(), n) != out.end()) ordered.push_back(n);
  return ordered;
}

// Reads node.key (one of `all`, default `fallback`; none: required) and checks that it is one of
// `ok`, which the slots named in `with` allow.
std::string read_slot(const CaseNode& node, const std::string& key,
                      const std::vector<std::string>& all, const std::string& fallback,
                      const std::vector<std::string>& ok, const std::string& with) {
  const std::string value =
      fallback.empty() ? node.get_choice(key, all) : node.get_choice(key, all, fallback);
  if (std::find(ok.begin(), ok.end(), value) == ok.end())
    node.fail(key,
              fmt::format("not with {}; allowed: {} (rfmems-pullin --scenes)", with, join(ok)));
  return value;
}

// Keys and values this vocabulary renamed: bad input with the new name.
void reject_renamed_keys(const CaseNode& root) {
  root.require(!root.has("immersed"), "immersed",
               "the immersed field is actuation.electrostatics: immersed, its settings "
               "actuation.immersed (electrode, control and facing_patch directly in actuation)");
  const CaseNode pull_in = root.child_or_empty("pull_in");
  for (const char* mode : {"dynamic", "transient"}) {
    const CaseNode node = pull_in.child_or_empty(mode);
    node.require(!node.has("contact_gap"), "contact_gap",
                 "the touch-down gap of every analysis is pull_in.contact_gap");
    node.require(!node.has("laplace_coupling"), "laplace_coupling",
                 "the Laplace field's staggered or implicit stepping is coupling.scheme");
  }
  const CaseNode coupling = root.child_or_empty("coupling");
  coupling.require(!coupling.has("macro_step"), "macro_step",
                   "the gas exchanges with the structure at every accepted step; every k-th: "
                   "coupling.gas_every");
  if (coupling.has("scheme") && coupling.get_string("scheme") == "strong")
    coupling.fail("scheme", "strong is spelt strongly_coupled");
}

}  // namespace

std::string structure_name(StructureModel s) { return kStructures[static_cast<int>(s)]; }
std::string field_name(FieldModel f) { return kFields[static_cast<int>(f)]; }
std::string gas_name(GasModel g) { return kGases[static_cast<int>(g)]; }
std::string analysis_name(Analysis a) { return kAnalyses[static_cast<int>(a)]; }
std::string coupling_scheme_name(CouplingScheme c) { return kSchemes[static_cast<int>(c)]; }

bool steps_in_time(Analysis analysis) {
  return analysis == Analysis::Dynamic || analysis == Analysis::Transient;
}

const std::vector<SceneRow>& scene_table() {
  static const std::vector<SceneRow> table = build_table();
  return table;
}

std::string scene_table_markdown() {
  std::string out =
      "| structure | field | gas | analyses | coupling schemes (first: default) |\n"
      "|---|---|---|---|---|\n";
  std::vector<SceneModels> seen;
  for (const SceneRow& row : scene_table()) {
    if (std::find(seen.begin(), seen.end(), row.models) != seen.end()) continue;
    seen.push_back(row.models);
    std::string analyses, schemes;
    for (const SceneRow& r : scene_table()) {
      if (!(r.models == row.models)) continue;
      analyses += (analyses.empty() ? "" : ", ") + analysis_name(r.analysis);
      if (r.schemes.empty()) continue;
      std::vector<std::string> names;
      for (CouplingScheme c : r.schemes) names.push_back(coupling_scheme_name(c));
      schemes +=
          (schemes.empty() ? "" : "; ") + analysis_name(r.analysis) + ": " + join(names, ", ");
    }
    out += fmt::format("| {} | {} | {} | {} | {} |\n", structure_name(row.models.structure),
                       field_name(row.models.field), gas_name(row.models.gas), analyses, schemes);
  }
  return out;
}

SceneChoice read_scene_choice(const CaseNode& root) {
  SceneChoice c;
  const CaseNode model = root.child_or_empty("model");
  // The structure reader checks model.structure's own values (solid3d is a structure, not a
  // switch's); a switch is a plate or, by default, a plane beam.
  const bool plate = model.has("structure") && model.get_string("structure") == "plate";
  c.models.structure = plate ? StructureModel::Plate : StructureModel::Plane;
  const std::string structure = structure_name(c.models.structure);

  reject_renamed_keys(root);
  const CaseNode act = root.child_or_empty("actuation");
  const auto same_structure = [&](const SceneRow& r) {
    return r.models.structure == c.models.structure;
  };
  c.models.field = from_name<FieldModel>(
      kFields,
      read_slot(act, "electrostatics", kFields, "parallel_plate",
                allowed(kFields, same_structure, [](const SceneRow& r) { return r.models.field; }),
                "model.structure: " + structure));
  const std::string field = field_name(c.models.field);

  const CaseNode gas = root.child_or_empty("gas");
  const auto same_field = [&](const SceneRow& r) {
    return same_structure(r) && r.models.field == c.models.field;
  };
  c.models.gas = from_name<GasModel>(
      kGases, read_slot(gas, "model", kGases, "none",
                        allowed(kGases, same_field, [](const SceneRow& r) { return r.models.gas; }),
                        fmt::format("model.structure: {}, actuation.electrostatics: {}", structure,
                                    field)));

  const CaseNode pull_in = root.child("pull_in");
  const auto same_models = [&](const SceneRow& r) { return r.models == c.models; };
  const std::string with =
      fmt::format("model.structure: {}, actuation.electrostatics: {}, gas.model: {}", structure,
                  field, gas_name(c.models.gas));
  c.analysis = from_name<Analysis>(
      kAnalyses,
      read_slot(pull_in, "mode", kAnalyses, "",
                allowed(kAnalyses, same_models, [](const SceneRow& r) { return r.analysis; }),
                with));

  const SceneRow& row =
      *std::find_if(scene_table().begin(), scene_table().end(),
                    [&](const SceneRow& r) { return same_models(r) && r.analysis == c.analysis; });
  const CaseNode coupling = root.child_or_empty("coupling");
  if (!steps_in_time(c.analysis)) {
    // Not used; its spelling is still checked.
    coupling.get_choice("scheme", kSchemes, kSchemes.front());
    return c;
  }
  std::vector<std::string> schemes;
  for (CouplingScheme s : row.schemes) schemes.push_back(coupling_scheme_name(s));
  c.scheme = from_name<CouplingScheme>(
      kSchemes, read_slot(coupling, "scheme", kSchemes, schemes.front(), schemes,
                          with + ", pull_in.mode: " + analysis_name(c.analysis)));
  return c;
}

CaseSchema scene_choice_case_keys() {
  return embedded_case_schema("coupling/scene_combinations.keys.yaml");
}

}  // namespace rfmems

#include "coupling/coupling_settings.hpp"

#include "io/case_schema_yaml.hpp"

namespace rfmems {

CouplingOptions read_coupling_options(const CaseNode& root, const SceneChoice& choice) {
  CouplingOptions o;
  o.scheme = choice.scheme;
  const CaseNode node = root.child_or_empty("coupling");
  o.tolerance = node.get_real("tolerance", o.tolerance, Range::open(0.0, 1.0));
  o.max_iterations =
      static_cast<int>(node.get_int("max_iterations", o.max_iterations, Range::closed(1, 100000)));
  const FieldModel field = choice.models.field;
  node.require(choice.models.gas != GasModel::None || !node.has("gas_every"), "gas_every",
               "only with a gas (gas.model)");
  node.require(field == FieldModel::Immersed || !node.has("strong_gas"), "strong_gas",
               "only with actuation.electrostatics: immersed (with the parallel_plate field the "
               "strongly_coupled scheme iterates on the gas alone)");
  o.gas_every = static_cast<int>(node.get_int("gas_every", 1, Range::closed(1, 1000)));
  o.strong_gas = node.get_bool("strong_gas", false);
  if (!steps_in_time(choice.analysis)) return o;
  node.require(!o.strong_gas || o.scheme == CouplingScheme::StronglyCoupled, "strong_gas",
               "strong_gas: true needs scheme: strongly_coupled (the gas inside its iterations)");
  const bool gas_iterated = o.scheme == CouplingScheme::StronglyCoupled &&
                            (o.strong_gas || field != FieldModel::Immersed);
  node.require(!gas_iterated || o.gas_every == 1, "gas_every",
               "the strongly coupled iteration advances the gas over every step: gas_every "
               "must be 1");
  return o;
}

CaseSchema coupling_case_keys() {
  return embedded_case_schema("coupling/coupling_settings.keys.yaml");
}

}  // namespace rfmems

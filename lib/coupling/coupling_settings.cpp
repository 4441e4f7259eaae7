#include "coupling/coupling_settings.hpp"

namespace rfmems {

CouplingOptions read_coupling_options(const CaseNode& root, const SceneChoice& choice) {
  CouplingOptions o;
  o.scheme = choice.scheme;
  const CaseNode node = root.child_or_empty("coupling");
  o.tolerance = node.get_real("tolerance", o.tolerance, Range::open(0.0, 1.0));
  o.max_iterations =
      static_cast<int>(node.get_int("max_iterations", o.max_iterations, Range::closed(1, 100000)));
  const FieldModel field = choice.models.field;
  const bool film_partitioned =
      field == FieldModel::ParallelPlate && choice.models.gas == GasModel::Reynolds;
  node.require(field == FieldModel::ParallelPlate || !node.has("macro_step"), "macro_step",
               "only for the parallel_plate field's partitioned schemes (the laplace and "
               "immersed fields exchange at every IDA step)");
  o.macro_step = node.get_quantity("macro_step", Dimension::Time, 0.0, Range::positive());
  for (const char* key : {"gas_every", "strong_gas"})
    node.require(field == FieldModel::Immersed || !node.has(key), key,
                 "only with actuation.electrostatics: immersed");
  o.gas_every = static_cast<int>(node.get_int("gas_every", 1, Range::closed(1, 1000)));
  o.strong_gas = node.get_bool("strong_gas", false);
  if (!steps_in_time(choice.analysis)) return o;
  node.require(!o.strong_gas || o.scheme == CouplingScheme::StronglyCoupled, "strong_gas",
               "strong_gas: true needs scheme: strongly_coupled (the gas inside its iterations)");
  node.require(!o.strong_gas || o.gas_every == 1, "strong_gas",
               "strong_gas: true advances the gas over every step: gas_every must be 1");
  const bool partitioned = film_partitioned && o.scheme != CouplingScheme::Monolithic;
  node.require(!partitioned || o.macro_step > 0, "macro_step",
               "a partitioned scheme needs macro_step (e.g. 0.1 us)");
  return o;
}

CaseSchema coupling_case_keys() {
  return {{"coupling",
           "the coupling scheme's settings",
           {
               {"tolerance", "number", "1e-06", "in (0, 1)",
                "iterated schemes: the relative change at which a step's iteration stops"},
               {"max_iterations", "integer", "20", "in [1, 100000]",
                "iterated schemes: the cap per step"},
               {"macro_step", "time", "(required for the film's partitioned schemes)", "> 0",
                "parallel_plate field with a Reynolds film: the exchange step"},
               {"gas_every", "integer", "1", "in [1, 1000]",
                "immersed field: advance the gas every this many structural steps"},
               {"strong_gas", "bool", "false", "",
                "immersed field, strongly_coupled: the gas inside the step's iterations"},
           }}};
}

}  // namespace rfmems

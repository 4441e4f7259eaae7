#include "coupling/coupling_settings.hpp"

namespace rfmems {

std::string coupling_scheme_name(CouplingScheme scheme) {
  switch (scheme) {
    case CouplingScheme::Staggered:
      return "staggered";
    case CouplingScheme::StronglyCoupled:
      return "strongly_coupled";
    case CouplingScheme::Monolithic:
      break;
  }
  return "monolithic";
}

PartitionedOptions read_coupling_options(const CaseNode& root, const SwitchScene& scene,
                                         bool transient) {
  PartitionedOptions o;
  o.scheme = CouplingScheme::Monolithic;
  if (!root.has("coupling")) return o;
  const CaseNode node = root.child("coupling");
  const std::string scheme =
      node.get_choice("scheme", {"monolithic", "staggered", "strongly_coupled"}, "monolithic");
  o.scheme = scheme == "staggered"          ? CouplingScheme::Staggered
             : scheme == "strongly_coupled" ? CouplingScheme::StronglyCoupled
                                            : CouplingScheme::Monolithic;
  const bool partitioned = o.scheme != CouplingScheme::Monolithic;
  // Every key is checked whatever the scheme (a case switched with --set stays valid).
  o.macro_step = node.get_quantity("macro_step", Dimension::Time, 0.0, Range::positive());
  o.tolerance = node.get_real("tolerance", 1e-6, Range::open(0.0, 1.0));
  o.max_iterations = static_cast<int>(node.get_int("max_iterations", 50, Range::closed(1, 100000)));
  if (!partitioned) return o;
  // The partitioned schemes split the plate from its squeeze film: without the film there is
  // nothing to partition; the Laplace field's staggered/implicit choice is
  // pull_in.dynamic.laplace_coupling (laplace_dynamic_switch.hpp).
  node.require(scene.electrostatics == ElectrostaticsModel::ParallelPlate, "scheme",
               "a partitioned scheme needs actuation.electrostatics: parallel_plate (a laplace "
               "scene's dynamic study sets pull_in.dynamic.laplace_coupling instead)");
  node.require(scene.film != nullptr, "scheme",
               "a partitioned scheme needs a gas film (gas.model: reynolds); without one the "
               "switch is a single field, use monolithic");
  node.require(transient, "scheme",
               "a partitioned scheme drives pull_in.mode: transient only (the bisections and "
               "the quasi-static curve are monolithic)");
  node.require(o.macro_step > 0, "macro_step",
               "a partitioned scheme needs macro_step (e.g. 0.1 us)");
  return o;
}

}  // namespace rfmems

#include "coupling/state_tolerances.hpp"

namespace rfmems {

std::vector<Real> absolute_tolerances(const std::vector<StateKind>& kinds, const StateTolerances& t,
                                      Real scalar_atol) {
  auto or_scalar = [scalar_atol](Real v) { return v > 0 ? v : scalar_atol; };
  const Real displacement = or_scalar(t.displacement);
  const Real velocity = t.velocity_rate > 0 ? displacement * t.velocity_rate : scalar_atol;
  std::vector<Real> atols;
  atols.reserve(kinds.size());
  for (const StateKind k : kinds) {
    switch (k) {
      case StateKind::Displacement:
        atols.push_back(displacement);
        break;
      case StateKind::Velocity:
        atols.push_back(velocity);
        break;
      case StateKind::Pressure:
        atols.push_back(or_scalar(t.pressure));
        break;
      case StateKind::QuasiStatic:
        atols.push_back(or_scalar(t.quasi_static));
        break;
    }
  }
  return atols;
}

IdaOptions with_state_tolerances(IdaOptions ida, const SwitchSystem& system,
                                 const StateTolerances& tolerances) {
  if (!tolerances.enabled() || ida.fixed_step > 0) return ida;
  const std::vector<StateKind> kinds = system.state_kinds();
  if (kinds.empty()) return ida;
  ida.atols = absolute_tolerances(kinds, tolerances, ida.atol);
  ida.suppress_algebraic = tolerances.suppress_quasi_static;
  return ida;
}

}  // namespace rfmems

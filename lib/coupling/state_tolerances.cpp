#include "coupling/state_tolerances.hpp"

#include <cmath>

#include "coupling/switch_scene.hpp"

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

StateTolerances per_kind_tolerances(const SwitchScene& scene, Real displacement,
                                    Real velocity_rate) {
  StateTolerances t;
  t.displacement = displacement;
  t.velocity_rate = velocity_rate;
  // The isothermal film (p g = const) answers a gap error d with d p_a / g0.
  if (scene.film) t.pressure = displacement * scene.film->gas().ambient_pressure / scene.gap;
  const Mesh& mesh = scene.structure->structure_mesh();
  Real area = 0;
  for (Index c = 0; c < mesh.n_cells(); ++c) area += mesh.cell_volume(c);
  t.quasi_static = displacement / std::sqrt(area / static_cast<Real>(mesh.n_cells()));
  t.suppress_quasi_static = true;
  return t;
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

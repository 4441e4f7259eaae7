#include "coupling/switch_system.hpp"

#include "coupling/squeeze_film_switch_system.hpp"
#include "coupling/switch_scene.hpp"

namespace rfmems {

ActuatedStructureSystem::ActuatedStructureSystem(ParallelPlateActuation& actuation,
                                                 std::vector<bool> quasi_static)
    : actuation_(actuation), system_(actuation, std::move(quasi_static)) {}

void ActuatedStructureSystem::initial_state(Real t0, std::vector<Real>& y, std::vector<Real>& yp) {
  y.assign(size(), 0.0);
  yp = system_.consistent_derivative(t0, y);
}

std::vector<StateKind> reduced_inertia_state_kinds(const ReducedInertiaSystem& system, Index n) {
  std::vector<StateKind> kinds(system.size(), StateKind::Velocity);
  for (Index i = 0; i < n; ++i)
    kinds[i] = system.velocity_index(i) >= 0 ? StateKind::Displacement : StateKind::QuasiStatic;
  return kinds;
}

std::vector<StateKind> ActuatedStructureSystem::state_kinds() const {
  return reduced_inertia_state_kinds(system_, actuation_.size());
}

Real ActuatedStructureSystem::velocity(std::span<const Real> y, std::span<const Real> yp,
                                       Index i) const {
  const Index v = system_.velocity_index(i);
  return v >= 0 ? y[v] : yp[i];
}

std::vector<Index> film_unknowns(const SwitchScene& scene) {
  std::vector<Index> w_dof;
  if (scene.film)
    for (const GapElement& e : scene.structure->gap_elements("")) w_dof.push_back(e.dof);
  return w_dof;
}

std::unique_ptr<SwitchSystem> make_switch_system(SwitchScene& scene) {
  const std::vector<bool> quasi_static = scene.structure->quasi_static_components();
  if (!scene.film) return std::make_unique<ActuatedStructureSystem>(*scene.actuation, quasi_static);
  return std::make_unique<SqueezeFilmSwitchSystem>(*scene.actuation, quasi_static, *scene.film,
                                                   film_unknowns(scene));
}

}  // namespace rfmems

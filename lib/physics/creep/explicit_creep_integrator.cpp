#include "physics/creep/explicit_creep_integrator.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.hpp"

namespace rfmems {

ExplicitCreepIntegrator::ExplicitCreepIntegrator(CreepSystem& system, Real dt)
    : system_(system), dt_(dt) {
  if (!(dt > 0)) throw InputError(fmt::format("explicit creep: time step must be > 0, got {}", dt));
}

void ExplicitCreepIntegrator::initialize(Real t0, std::span<const Real> state) {
  if (static_cast<Index>(state.size()) != system_.size())
    throw InputError("explicit creep: state size does not match the system");
  t_ = t0;
  steps_ = 0;
  state_.assign(state.begin(), state.end());
  rates_.resize(system_.size() - system_.structural_size());
}

void ExplicitCreepIntegrator::advance(Real t_out) {
  const Index ns = system_.structural_size();
  while (t_ < t_out) {
    // A step within 1e-9 dt of t_out lands on it (no sliver steps from round-off).
    const Real dt = (t_out - t_ <= dt_ * (1 + 1e-9)) ? t_out - t_ : dt_;
    system_.creep_rates(t_, state_, rates_);
    for (std::size_t k = 0; k < rates_.size(); ++k) state_[ns + k] += dt * rates_[k];
    t_ = (dt == t_out - t_) ? t_out : t_ + dt;
    system_.equilibrate(t_, state_);
    ++steps_;
  }
}

}  // namespace rfmems

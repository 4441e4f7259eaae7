// The thesis's creep time integration (ch. 4, its steps 1-8), kept as the baseline: forward
// Euler on the creep states with a fixed step,
//   q^{N+1} = q^N + dt g(t^N, u^N, q^N),   then u^{N+1} from R(t^{N+1}, u, q^{N+1}) = 0,
// the structure re-solved after every update (for the plate one back-substitution: its matrix
// is factorised once). First order in dt, and only conditionally stable: the hardening law's
// rate Jacobian dg/deps_eff = -m n B eps_dot / (1 + B eps_eff) can be large at t = 0 (see
// docs/creep.md), where a fixed dt overshoots.
#pragma once
#include <vector>

#include "physics/creep/creep_system.hpp"

namespace rfmems {

class ExplicitCreepIntegrator {
 public:
  ExplicitCreepIntegrator(CreepSystem& system, Real dt);
  // state: an equilibrated state (CreepSystem::initial_state).
  void initialize(Real t0, std::span<const Real> state);
  // Steps of dt up to t_out; the last one is shortened to land on t_out.
  void advance(Real t_out);
  Real time() const { return t_; }
  std::span<const Real> state() const { return state_; }
  long steps() const { return steps_; }

 private:
  CreepSystem& system_;
  Real dt_;
  Real t_ = 0;
  long steps_ = 0;
  std::vector<Real> state_, rates_;
};

}  // namespace rfmems

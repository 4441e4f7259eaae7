// What the creep integrators (implicit IDA, explicit Euler baseline) need of a quasi-static
// creep model, independent of the structure (plate now; plane/3D later).
//
// State layout: [structural unknowns u (structural_size()) | creep states q (the rest)].
// The model is the semi-explicit index-1 DAE
//   F_u = R(t, u, q) = 0          (algebraic: quasi-static equilibrium, inertia neglected
//                                  since creep is slow)
//   F_q = q' - g(t, u, q)         (differential: the creep law at the integration points)
// as a SystemOperator (for IDA), plus the two pieces the explicit baseline uses: the creep
// rates g and the equilibrium solve for u at fixed q.
#pragma once
#include <span>

#include "core/system_operator.hpp"

namespace rfmems {

class CreepSystem : public SystemOperator {
 public:
  // Number of structural unknowns (the first entries of the state).
  virtual Index structural_size() const = 0;
  // g(t, u, q) into rates (size() - structural_size() entries).
  virtual void creep_rates(Real t, std::span<const Real> state, std::span<Real> rates) = 0;
  // Solves R(t, u, q) = 0 for u at the state's q (in place).
  virtual void equilibrate(Real t, std::span<Real> state) = 0;

  // A consistent initial state at t: u in equilibrium with the given q (zero by default),
  // q' = g, and u' from differentiating the equilibrium (dR/du u' + dR/dq q' = 0; explicit
  // time dependence of the loads neglected).
  virtual void initial_state(Real t, std::vector<Real>& state, std::vector<Real>& state_dot) = 0;
};

}  // namespace rfmems

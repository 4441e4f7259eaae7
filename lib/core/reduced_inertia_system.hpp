// First-order form of a structural system M y'' + R(t, y) = 0 in which the inertia of chosen
// components is neglected: they become quasi-static (algebraic) unknowns. For IDA.
//
//   inertial i      F_i       = y_i' - v_k           (differential)
//                   F_{n+k}   = M_i v_k' + (C v)_i + R_i(t, y)  (differential)
//   quasi-static i  F_i       = R_i(t, y)             (algebraic, IDASetId 0)
//
// State Y = [y (n); v (m)], one velocity per inertial component, k numbering them in order.
// Jacobian rows: inertial i [c_j at i, -1 at n+k]; quasi-static i the stiffness row i;
// n+k the stiffness row i plus c_j M_i at n+k (and with the operator's damping C = beta K,
// which needs every component inertial, beta times the stiffness row i in the v columns).
// Index 1 as long as the stiffness block of the quasi-static components is non-singular
// (true for the plate's rotations: bending plus shear).
//
// Why (the Mindlin plate): rotary inertia rho h^3/12 puts a thickness-shear branch at
// omega = sqrt(12 k G / rho) / h (5.5e9 rad/s for a 2 um steel plate, 1e4 times the first
// bending frequency of a 400 um membrane). It is undamped, a step load excites it, and an
// adaptive BDF integrator with error control on every component then resolves it (measured:
// steps of 1e-11 s, IDA_TOO_MUCH_WORK). Its effect on bending is O((h/L)^2) (1e-4 at
// L/h = 200), so neglecting rotary inertia is the standard thin-plate choice for transients;
// with it IDA takes steps set by the bending dynamics. FirstOrderSystem (core) keeps the full
// mass for fixed-step or reference runs.
#pragma once
#include <vector>

#include "core/system_operator.hpp"

namespace rfmems {

class ReducedInertiaSystem : public SystemOperator {
 public:
  // quasi_static[i]: neglect the inertia of component i (its mass entry is ignored); empty:
  // none (the full first-order form).
  ReducedInertiaSystem(SecondOrderOperator& op, std::vector<bool> quasi_static);

  Index size() const override { return n_ + static_cast<Index>(inertial_.size()); }
  std::vector<Real> differential_components() const override;
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override;
  const CsrPattern& jacobian_pattern() const override { return pattern_; }
  void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> values) override;

  // Index in Y of the velocity of component i, or -1 if i is quasi-static.
  Index velocity_index(Index i) const { return velocity_[i]; }
  // Y' consistent with a state Y whose quasi-static components satisfy R_i(t, y) = 0:
  // y_i' = v_k, v_k' = -(R_i(t, y) + (C v)_i)/M_i, zero for the quasi-static components.
  std::vector<Real> consistent_derivative(Real t, std::span<const Real> y);

 private:
  // r_ = R(t, y) + C v (the damping's part only with it).
  void internal_forces(Real t, std::span<const Real> y);

  SecondOrderOperator& op_;
  Index n_;
  std::vector<Real> mass_;
  std::vector<Index> inertial_;  // component of each velocity
  std::vector<Index> velocity_;  // per component: n + k, or -1
  CsrPattern pattern_;
  std::vector<Index> row_stiffness_offset_;  // per row: where the stiffness row starts, or -1
  std::vector<Index> mass_position_;         // per velocity: value index of c_j M_i
  Real beta_ = 0;                            // the operator's damping C = beta K
  std::vector<Index> damping_position_;      // per stiffness entry: value index of beta K in
                                             // the v columns (-1: the diagonal, at the mass's)
  std::vector<Index> damping_diagonal_;      // per velocity: the stiffness entry of (i, i)
  std::vector<Real> k_values_, r_, v_;
};

}  // namespace rfmems

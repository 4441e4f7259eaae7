// A structure under an electrostatic load that is recomputed only once per time step (a
// field solve is too expensive for every residual call), for IDA:
//
//   M u'' + R(u) - f(u) - f_held = 0,   f_i = F_i off the gap unknowns,
//   f_c(u) = F_c (g_ref,c / g_c(u))^2 on gap unknown c,   g_c = g0 + u_c,
//
// F the field's force at the reference state u_ref (the state after the last accepted step)
// with g_ref,c = g0 + u_y,c(u_ref): inside a step the load follows the dominant gap
// dependence of the parallel-plate law, and the Jacobian carries the electrostatic spring
// softening d(-f_c)/du_c = 2 F_c g_ref^2 / g^3 (F_c < 0: softening). The staggered scheme
// refreshes F after every step IDA accepts; its error is first order in the step. f_held is a
// load held fixed over the step (the lagged gas force; zero unless set).
//
// With set_exact(load), the residual uses the exact load at u instead (the field solved in
// every residual call: the implicit, strongly coupled reference), and the scaled lagged model
// stays in the Jacobian (an inexact Newton).
//
// It is the structure of the field-coupled structure's time loop (field_coupled_structure.hpp).
#pragma once
#include <functional>
#include <span>
#include <vector>

#include "core/system_operator.hpp"

namespace rfmems {

class GapScaledLaggedLoad : public SecondOrderOperator {
 public:
  using ExactLoad = std::function<std::vector<Real>(std::span<const Real>)>;
  // A trial state with a loaded cell's gap below this fraction of g0 is rejected. Well below
  // the touch-down roots (2 % of g0 by default), so that a step that carries the gap through
  // the root is accepted and the root located inside it (with 2 % itself, the step that would
  // cross the root failed every time and IDA cut its step without end).
  static constexpr Real kClosedFraction = 1e-3;

  // structure: its operator; gap_unknowns: the unknown that crosses the gap in each facing cell
  // (a plane beam's u_y, a plate's w); gap0: the gap at rest; closed_fraction: see
  // kClosedFraction (the immersed switch keeps its 2 %).
  GapScaledLaggedLoad(SecondOrderOperator& structure, std::vector<Index> gap_unknowns, Real gap0,
                      Real closed_fraction = kClosedFraction);

  // The field's force per unknown at the reference state u_ref [N/m].
  void set_reference(std::vector<Real> force, std::span<const Real> u_ref);
  void set_exact(ExactLoad exact) { exact_ = std::move(exact); }
  // f_held per unknown [N/m], applied as it is until set again.
  void set_held(std::vector<Real> held) { held_ = std::move(held); }
  // The field load the residual applies at u (the scaled lagged model, without f_held).
  std::vector<Real> applied(std::span<const Real> u) const;

  Index size() const override { return structure_.size(); }
  void internal_residual(Real t, std::span<const Real> u, std::span<Real> r) override;
  const CsrPattern& stiffness_pattern() const override { return structure_.stiffness_pattern(); }
  void stiffness(Real t, std::span<const Real> u, std::span<Real> values) override;
  std::vector<Real> mass_diagonal() const override { return structure_.mass_diagonal(); }
  Real damping_time() const override { return structure_.damping_time(); }
  void add_damping_force(Real t, std::span<const Real> v, std::span<Real> r) override {
    structure_.add_damping_force(t, v, r);
  }

 private:
  // (g_ref / g)^2 of facing cell c; a gap below closed_fraction g0 is a failed trial state (IDA
  // retries).
  Real scale(std::size_t c, std::span<const Real> u) const;
  SecondOrderOperator& structure_;
  Real gap0_, closed_fraction_;
  std::vector<Index> gap_unknowns_;
  std::vector<Real> force_, held_, reference_gap_;
  std::vector<Index> diagonal_;  // value index of (u_c, u_c) in the stiffness
  std::vector<char> on_gap_;     // per unknown: a gap unknown
  ExactLoad exact_;
};

}  // namespace rfmems

// Adaptors from a SecondOrderOperator (M y'' + R(t, y) = 0) to the SystemOperator contract.
#pragma once
#include "core/first_order_layout.hpp"
#include "core/system_operator.hpp"

namespace rfmems {

// Static equilibrium R(t, y) = 0 (no y' terms): what KINSOL solves.
class StaticSystem : public SystemOperator {
 public:
  explicit StaticSystem(SecondOrderOperator& op) : op_(op) {}
  Index size() const override { return op_.size(); }
  std::vector<Real> differential_components() const override;
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override;
  const CsrPattern& jacobian_pattern() const override { return op_.stiffness_pattern(); }
  void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> values) override;

 private:
  SecondOrderOperator& op_;
};

// First-order form for IDA, state Y = [y; v] (n + n), as core/first_order_layout.hpp:
//   F_y = y' - v,   F_v = M v' + C v + R(t, y).
// Jacobian rows y: [c_j I, -I]; rows v: [dR/dy, c_j M + C].
class FirstOrderSystem : public SystemOperator {
 public:
  explicit FirstOrderSystem(SecondOrderOperator& op);
  Index size() const override { return 2 * layout_.n(); }
  std::vector<Real> differential_components() const override;
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override;
  const CsrPattern& jacobian_pattern() const override { return layout_.pattern(); }
  void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> values) override;

 private:
  SecondOrderOperator& op_;
  FirstOrderLayout layout_;
  std::vector<Real> k_values_;
};

}  // namespace rfmems

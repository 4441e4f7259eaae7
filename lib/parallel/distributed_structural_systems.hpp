// Adaptors from a DistributedSecondOrderOperator (M y'' + R(t, y) = 0, y distributed) to the
// DistributedSystem contract: the distributed counterparts of core/structural_systems.hpp,
// row for row the same equations on the owned unknowns.
#pragma once
#include "core/first_order_layout.hpp"
#include "parallel/distributed_system.hpp"

namespace rfmems {

// Static equilibrium R(t, y) = 0 (KINSOL).
class DistributedStaticSystem : public DistributedSystem {
 public:
  explicit DistributedStaticSystem(DistributedSecondOrderOperator& op) : op_(op) {}
  const Communicator& communicator() const override { return op_.communicator(); }
  Index owned_size() const override { return op_.owned_size(); }
  Index local_columns() const override { return op_.local_columns(); }
  std::vector<Real> differential_components() const override;
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override;
  const CsrPattern& jacobian_pattern() const override { return op_.stiffness_pattern(); }
  void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> values) override;
  void exchange_ghosts(std::span<Real> x) const override { op_.exchange_ghosts(x); }
  const CsrPattern* overlap_pattern() const override { return op_.overlap_stiffness_pattern(); }
  void overlap_jacobian(Real t, Real, std::span<const Real> y, std::span<const Real>,
                        std::span<Real> values) override {
    op_.overlap_stiffness(t, y, values);
  }
  int unknowns_per_cell() const override { return op_.unknowns_per_cell(); }
  bool matrix_free() const override { return op_.matrix_free(); }
  void jacobian_product(Real t, std::span<const Real> y, std::span<const Real> v,
                        std::span<Real> jv) override {
    op_.stiffness_product(t, y, v, jv);
  }
  const CsrPattern& preconditioner_pattern() const override { return op_.preconditioner_pattern(); }
  void preconditioner_jacobian(Real t, std::span<const Real> y, std::span<Real> values) override {
    op_.preconditioner_stiffness(t, y, values);
  }

 private:
  DistributedSecondOrderOperator& op_;
};

// First-order form for IDA, owned state Y = [y; v] (n + n, this rank's owned unknowns), as
// core/first_order_layout.hpp:
//   F_y = y' - v,   F_v = M v' + C v + R(t, y).
// Local columns: [y owned; v owned; y ghosts] (only R reaches ghosts), and the v ghosts after
// them when the operator has damping C.
class DistributedFirstOrderSystem : public DistributedSystem {
 public:
  explicit DistributedFirstOrderSystem(DistributedSecondOrderOperator& op);
  const Communicator& communicator() const override { return op_.communicator(); }
  Index owned_size() const override { return 2 * layout_.n(); }
  Index local_columns() const override {
    return 2 * layout_.n() + (layout_.damping_time() > 0 ? 2 : 1) * n_ghost_;
  }
  std::vector<Real> differential_components() const override;
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override;
  const CsrPattern& jacobian_pattern() const override { return layout_.pattern(); }
  void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> values) override;
  void exchange_ghosts(std::span<Real> x) const override;
  DistributedSecondOrderOperator* second_order() override { return &op_; }

 private:
  DistributedSecondOrderOperator& op_;
  FirstOrderLayout layout_;
  Index n_ghost_;
  std::vector<Real> k_values_;
  mutable std::vector<Real> column_work_;
};

}  // namespace rfmems

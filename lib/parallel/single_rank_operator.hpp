// A serial structural operator seen as a DistributedSecondOrderOperator on one rank: every
// unknown owned, no ghosts, gathers and exchanges that do nothing. It lets the distributed
// Krylov solvers (GMRES with algebraic multigrid) run on one rank on the operator itself,
// without the copy a one-part DistributedLocalOperator would build.
//
// With a compact operator (the same equations on a smaller stencil: the linear instead of the
// quadratic or cubic reconstruction) and an operator that multiplies by its stiffness without
// the matrix, it is matrix-free: the Krylov solver multiplies by the operator's own Jacobian
// and preconditions with the compact one's matrix (PETSc's Amat and Pmat), and the wide
// stencil's matrix is never assembled.
#pragma once
#include "core/system_operator.hpp"
#include "parallel/distributed_system.hpp"

namespace rfmems {

class SingleRankOperator : public DistributedSecondOrderOperator {
 public:
  // `op` (and `compact`, if given) must outlive this; `unknowns_per_cell`: its unknowns per
  // cell, interleaved.
  SingleRankOperator(SecondOrderOperator& op, int unknowns_per_cell,
                     SecondOrderOperator* compact = nullptr)
      : op_(op), compact_(compact), comm_(Communicator::serial()), block_(unknowns_per_cell) {}
  const Communicator& communicator() const override { return comm_; }
  Index owned_size() const override { return op_.size(); }
  Index local_columns() const override { return op_.size(); }
  Index global_size() const override { return op_.size(); }
  void internal_residual(Real t, std::span<const Real> y, std::span<Real> r) override {
    op_.internal_residual(t, y, r);
  }
  const CsrPattern& stiffness_pattern() const override { return op_.stiffness_pattern(); }
  void stiffness(Real t, std::span<const Real> y, std::span<Real> values) override {
    op_.stiffness(t, y, values);
  }
  std::vector<Real> mass_diagonal() const override { return op_.mass_diagonal(); }
  void exchange_ghosts(std::span<Real>) const override {}
  Real damping_time() const override { return op_.damping_time(); }
  void add_damping_force(Real t, std::span<const Real> v, std::span<Real> r) override {
    op_.add_damping_force(t, v, r);
  }
  std::vector<Real> gather_to_root(std::span<const Real> owned) const override {
    return {owned.begin(), owned.end()};
  }
  std::vector<Real> owned_part(std::span<const Real> global) const override {
    return {global.begin(), global.end()};
  }
  int unknowns_per_cell() const override { return block_; }
  bool matrix_free() const override { return compact_ && op_.has_stiffness_product(); }
  void stiffness_product(Real t, std::span<const Real> y, std::span<const Real> v,
                         std::span<Real> kv) override {
    op_.stiffness_product(t, y, v, kv);
  }
  const CsrPattern& preconditioner_pattern() const override {
    return compact_ ? compact_->stiffness_pattern() : op_.stiffness_pattern();
  }
  void preconditioner_stiffness(Real t, std::span<const Real> y, std::span<Real> values) override {
    (compact_ ? *compact_ : op_).stiffness(t, y, values);
  }

 private:
  SecondOrderOperator& op_;
  SecondOrderOperator* compact_;
  Communicator comm_;
  int block_;
};

}  // namespace rfmems

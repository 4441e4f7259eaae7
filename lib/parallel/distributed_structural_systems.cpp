#include "parallel/distributed_structural_systems.hpp"

#include <algorithm>

namespace rfmems {

std::vector<Real> DistributedStaticSystem::differential_components() const {
  return std::vector<Real>(op_.owned_size(), 0.0);
}

void DistributedStaticSystem::residual(Real t, std::span<const Real> y, std::span<const Real>,
                                       std::span<Real> r) {
  op_.internal_residual(t, y, r);
}

void DistributedStaticSystem::jacobian(Real t, Real, std::span<const Real> y, std::span<const Real>,
                                       std::span<Real> values) {
  op_.stiffness(t, y, values);
}

DistributedFirstOrderSystem::DistributedFirstOrderSystem(DistributedSecondOrderOperator& op)
    : op_(op),
      layout_(op.stiffness_pattern(), op.mass_diagonal(), op.damping_time(),
              op.local_columns() - op.owned_size()),
      n_ghost_(op.local_columns() - op.owned_size()),
      k_values_(op.stiffness_pattern().nnz()),
      column_work_(op.local_columns()) {}

std::vector<Real> DistributedFirstOrderSystem::differential_components() const {
  return std::vector<Real>(owned_size(), 1.0);
}

void DistributedFirstOrderSystem::residual(Real t, std::span<const Real> y,
                                           std::span<const Real> yp, std::span<Real> r) {
  const Index n = layout_.n();
  op_.internal_residual(t, y.subspan(0, n), r.subspan(n, n));
  if (layout_.damping_time() > 0) op_.add_damping_force(t, y.subspan(n, n), r.subspan(n, n));
  layout_.complete_residual(y, yp, r);
}

void DistributedFirstOrderSystem::jacobian(Real t, Real c_j, std::span<const Real> y,
                                           std::span<const Real>, std::span<Real> values) {
  op_.stiffness(t, y.subspan(0, layout_.n()), k_values_);
  layout_.jacobian(c_j, k_values_, values);
}

void DistributedFirstOrderSystem::exchange_ghosts(std::span<Real> x) const {
  // The structure's columns are [y owned; y ghosts]: exchange those; v has ghosts (after the
  // y ghosts) only with damping, C v reaching the neighbours' velocities.
  const Index n = layout_.n();
  std::copy(x.begin(), x.begin() + n, column_work_.begin());
  op_.exchange_ghosts(column_work_);
  std::copy(column_work_.begin() + n, column_work_.end(), x.begin() + 2 * n);
  if (layout_.damping_time() > 0) {
    std::copy(x.begin() + n, x.begin() + 2 * n, column_work_.begin());
    op_.exchange_ghosts(column_work_);
    std::copy(column_work_.begin() + n, column_work_.end(), x.begin() + 2 * n + n_ghost_);
  }
}

}  // namespace rfmems

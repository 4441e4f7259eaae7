#include "core/structural_systems.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace rfmems {

Index CsrPattern::find(Index row, Index col) const {
  auto first = col_idx.begin() + row_ptr[row];
  auto last = col_idx.begin() + row_ptr[row + 1];
  auto it = std::lower_bound(first, last, col);
  return (it != last && *it == col) ? static_cast<Index>(it - col_idx.begin()) : -1;
}

std::vector<Real> StaticSystem::differential_components() const {
  return std::vector<Real>(op_.size(), 0.0);
}

void StaticSystem::residual(Real t, std::span<const Real> y, std::span<const Real>,
                            std::span<Real> r) {
  op_.internal_residual(t, y, r);
}

void StaticSystem::jacobian(Real t, Real, std::span<const Real> y, std::span<const Real>,
                            std::span<Real> values) {
  op_.stiffness(t, y, values);
}

FirstOrderSystem::FirstOrderSystem(SecondOrderOperator& op)
    : op_(op),
      layout_(op.stiffness_pattern(), op.mass_diagonal(), op.damping_time()),
      k_values_(op.stiffness_pattern().nnz()) {}

std::vector<Real> FirstOrderSystem::differential_components() const {
  return std::vector<Real>(size(), 1.0);
}

void FirstOrderSystem::residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                                std::span<Real> r) {
  const Index n = layout_.n();
  op_.internal_residual(t, y.subspan(0, n), r.subspan(n, n));
  if (layout_.damping_time() > 0) op_.add_damping_force(t, y.subspan(n, n), r.subspan(n, n));
  layout_.complete_residual(y, yp, r);
}

void FirstOrderSystem::jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real>,
                                std::span<Real> values) {
  op_.stiffness(t, y.subspan(0, layout_.n()), k_values_);
  layout_.jacobian(c_j, k_values_, values);
}

}  // namespace rfmems

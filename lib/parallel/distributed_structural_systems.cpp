#include "parallel/distributed_structural_systems.hpp"

#include <algorithm>
#include <utility>

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
      n_(op.owned_size()),
      n_ghost_(op.local_columns() - op.owned_size()),
      mass_(op.mass_diagonal()),
      r_(op.owned_size()) {
  const CsrPattern& k = op_.stiffness_pattern();
  k_values_.resize(k.nnz());
  stiffness_position_.resize(k.nnz());
  mass_position_.resize(n_);
  // Rows y: (i, i) c_j and (i, n + i) -1. Rows v: R's columns (ghosts moved past the v
  // block) and the mass diagonal, in ascending column order.
  auto column_of = [&](Index j) { return j < n_ ? j : j + n_; };
  for (Index i = 0; i < n_; ++i) {
    pattern_.col_idx.push_back(i);
    pattern_.col_idx.push_back(n_ + i);
    pattern_.row_ptr.push_back(pattern_.nnz());
  }
  for (Index i = 0; i < n_; ++i) {
    std::vector<std::pair<Index, Index>> row;  // (column, stiffness entry or -1: mass)
    for (Index e = k.row_ptr[i]; e < k.row_ptr[i + 1]; ++e)
      row.emplace_back(column_of(k.col_idx[e]), e);
    row.emplace_back(n_ + i, -1);
    std::sort(row.begin(), row.end());
    for (const auto& [col, e] : row) {
      (e >= 0 ? stiffness_position_[e] : mass_position_[i]) = pattern_.nnz();
      pattern_.col_idx.push_back(col);
    }
    pattern_.row_ptr.push_back(pattern_.nnz());
  }
  column_work_.resize(op.local_columns());
}

std::vector<Real> DistributedFirstOrderSystem::differential_components() const {
  return std::vector<Real>(2 * n_, 1.0);
}

void DistributedFirstOrderSystem::residual(Real t, std::span<const Real> y,
                                           std::span<const Real> yp, std::span<Real> r) {
  for (Index i = 0; i < n_; ++i) r[i] = yp[i] - y[n_ + i];
  op_.internal_residual(t, y.subspan(0, n_), r_);
  for (Index i = 0; i < n_; ++i) r[n_ + i] = mass_[i] * yp[n_ + i] + r_[i];
}

void DistributedFirstOrderSystem::jacobian(Real t, Real c_j, std::span<const Real> y,
                                           std::span<const Real>, std::span<Real> values) {
  std::fill(values.begin(), values.end(), 0.0);
  for (Index i = 0; i < n_; ++i) {
    values[2 * i] = c_j;
    values[2 * i + 1] = -1.0;
  }
  op_.stiffness(t, y.subspan(0, n_), k_values_);
  for (std::size_t e = 0; e < k_values_.size(); ++e) values[stiffness_position_[e]] = k_values_[e];
  for (Index i = 0; i < n_; ++i) values[mass_position_[i]] = c_j * mass_[i];
}

void DistributedFirstOrderSystem::exchange_ghosts(std::span<Real> x) const {
  // The structure's columns are [y owned; y ghosts]: exchange those, v has no ghosts.
  std::copy(x.begin(), x.begin() + n_, column_work_.begin());
  op_.exchange_ghosts(column_work_);
  std::copy(column_work_.begin() + n_, column_work_.end(), x.begin() + 2 * n_);
}

}  // namespace rfmems

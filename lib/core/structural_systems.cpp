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
    : op_(op), n_(op.size()), mass_(op.mass_diagonal()) {
  const CsrPattern& k = op_.stiffness_pattern();
  k_values_.resize(k.nnz());
  // Rows of F_y: columns i and n + i.
  for (Index i = 0; i < n_; ++i) {
    pattern_.col_idx.push_back(i);
    pattern_.col_idx.push_back(n_ + i);
    pattern_.row_ptr.push_back(pattern_.nnz());
  }
  // Rows of F_v: the stiffness row, then the mass diagonal (column n + i sorts last).
  mass_position_.resize(n_);
  for (Index i = 0; i < n_; ++i) {
    for (Index p = k.row_ptr[i]; p < k.row_ptr[i + 1]; ++p) pattern_.col_idx.push_back(k.col_idx[p]);
    mass_position_[i] = pattern_.nnz();
    pattern_.col_idx.push_back(n_ + i);
    pattern_.row_ptr.push_back(pattern_.nnz());
  }
}

std::vector<Real> FirstOrderSystem::differential_components() const {
  return std::vector<Real>(2 * n_, 1.0);
}

void FirstOrderSystem::residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                                std::span<Real> r) {
  auto u = y.subspan(0, n_);
  auto v = y.subspan(n_, n_);
  auto rv = r.subspan(n_, n_);
  for (Index i = 0; i < n_; ++i) r[i] = yp[i] - v[i];
  op_.internal_residual(t, u, rv);
  for (Index i = 0; i < n_; ++i) rv[i] += mass_[i] * yp[n_ + i];
}

void FirstOrderSystem::jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real>,
                                std::span<Real> values) {
  for (Index i = 0; i < n_; ++i) {
    values[2 * i] = c_j;
    values[2 * i + 1] = -1.0;
  }
  op_.stiffness(t, y.subspan(0, n_), k_values_);
  const CsrPattern& k = op_.stiffness_pattern();
  for (Index i = 0; i < n_; ++i) {
    Index row_start = pattern_.row_ptr[n_ + i];
    for (Index p = k.row_ptr[i]; p < k.row_ptr[i + 1]; ++p)
      values[row_start + (p - k.row_ptr[i])] = k_values_[p];
    values[mass_position_[i]] = c_j * mass_[i];
  }
}

}  // namespace rfmems

#include "core/first_order_layout.hpp"

#include <algorithm>
#include <utility>

namespace rfmems {

FirstOrderLayout::FirstOrderLayout(const CsrPattern& k, std::vector<Real> mass)
    : n_(static_cast<Index>(mass.size())), mass_(std::move(mass)) {
  stiffness_position_.resize(k.nnz());
  mass_position_.resize(n_);
  // Rows y: (i, i) c_j and (i, n + i) -1. Rows v: R's columns (those past the y block moved
  // past the v block) and the mass diagonal, in ascending column order.
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
}

void FirstOrderLayout::complete_residual(std::span<const Real> y, std::span<const Real> yp,
                                         std::span<Real> r) const {
  for (Index i = 0; i < n_; ++i) r[i] = yp[i] - y[n_ + i];
  for (Index i = 0; i < n_; ++i) r[n_ + i] += mass_[i] * yp[n_ + i];
}

void FirstOrderLayout::jacobian(Real c_j, std::span<const Real> stiffness_values,
                                std::span<Real> values) const {
  for (Index i = 0; i < n_; ++i) {
    values[2 * i] = c_j;
    values[2 * i + 1] = -1.0;
  }
  for (std::size_t e = 0; e < stiffness_values.size(); ++e)
    values[stiffness_position_[e]] = stiffness_values[e];
  for (Index i = 0; i < n_; ++i) values[mass_position_[i]] = c_j * mass_[i];
}

}  // namespace rfmems

#include "core/first_order_layout.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

namespace rfmems {

FirstOrderLayout::FirstOrderLayout(const CsrPattern& k, std::vector<Real> mass, Real damping_time,
                                   Index ghosts)
    : n_(static_cast<Index>(mass.size())), mass_(std::move(mass)), beta_(damping_time) {
  stiffness_position_.resize(k.nnz());
  if (beta_ > 0) {
    damping_position_.resize(k.nnz());
    damping_diagonal_.assign(n_, -1);
  }
  mass_position_.resize(n_);
  // Rows y: (i, i) c_j and (i, n + i) -1. Rows v: R's columns (those past the y block moved
  // past the v block), with damping the same columns in the v blocks, and the mass diagonal,
  // in ascending column order.
  auto y_column = [&](Index j) { return j < n_ ? j : j + n_; };
  auto v_column = [&](Index j) { return j < n_ ? n_ + j : j + n_ + ghosts; };
  for (Index i = 0; i < n_; ++i) {
    pattern_.col_idx.push_back(i);
    pattern_.col_idx.push_back(n_ + i);
    pattern_.row_ptr.push_back(pattern_.nnz());
  }
  enum Entry { Stiffness, Damping, Mass };
  for (Index i = 0; i < n_; ++i) {
    std::vector<std::tuple<Index, Entry, Index>> row;  // (column, what, stiffness entry)
    for (Index e = k.row_ptr[i]; e < k.row_ptr[i + 1]; ++e) {
      row.emplace_back(y_column(k.col_idx[e]), Stiffness, e);
      if (beta_ > 0 && k.col_idx[e] != i) row.emplace_back(v_column(k.col_idx[e]), Damping, e);
    }
    row.emplace_back(n_ + i, Mass, -1);
    std::sort(row.begin(), row.end());
    for (const auto& [col, what, e] : row) {
      const Index position = pattern_.nnz();
      if (what == Stiffness) stiffness_position_[e] = position;
      if (what == Damping) damping_position_[e] = position;
      if (what == Mass) mass_position_[i] = position;
      pattern_.col_idx.push_back(col);
    }
    // The diagonal of beta K shares the mass's position (n + i, n + i).
    if (beta_ > 0)
      for (Index e = k.row_ptr[i]; e < k.row_ptr[i + 1]; ++e)
        if (k.col_idx[e] == i) {
          damping_position_[e] = -1;
          damping_diagonal_[i] = e;
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
  for (std::size_t e = 0; e < damping_position_.size(); ++e)
    if (damping_position_[e] >= 0) values[damping_position_[e]] = beta_ * stiffness_values[e];
  for (Index i = 0; i < static_cast<Index>(damping_diagonal_.size()); ++i)
    if (damping_diagonal_[i] >= 0)
      values[mass_position_[i]] += beta_ * stiffness_values[damping_diagonal_[i]];
}

}  // namespace rfmems

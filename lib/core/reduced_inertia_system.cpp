#include "core/reduced_inertia_system.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "core/error.hpp"

namespace rfmems {

ReducedInertiaSystem::ReducedInertiaSystem(SecondOrderOperator& op, std::vector<bool> quasi_static)
    : op_(op), n_(op.size()), mass_(op.mass_diagonal()), velocity_(op.size(), -1) {
  if (quasi_static.empty()) quasi_static.assign(n_, false);  // no quasi-static component
  if (static_cast<Index>(quasi_static.size()) != n_)
    throw InputError(
        fmt::format("reduced inertia: {} flags for {} unknowns", quasi_static.size(), n_));
  for (Index i = 0; i < n_; ++i)
    if (!quasi_static[i]) {
      if (!(mass_[i] > 0))
        throw InputError(fmt::format("reduced inertia: component {} has no mass", i));
      velocity_[i] = n_ + static_cast<Index>(inertial_.size());
      inertial_.push_back(i);
    }

  const CsrPattern& k = op_.stiffness_pattern();
  row_stiffness_offset_.assign(size(), -1);
  auto copy_stiffness_row = [&](Index row, Index i) {
    row_stiffness_offset_[row] = pattern_.nnz();
    for (Index p = k.row_ptr[i]; p < k.row_ptr[i + 1]; ++p)
      pattern_.col_idx.push_back(k.col_idx[p]);
  };
  for (Index i = 0; i < n_; ++i) {
    if (velocity_[i] >= 0) {
      pattern_.col_idx.push_back(i);
      pattern_.col_idx.push_back(velocity_[i]);
    } else {
      copy_stiffness_row(i, i);
    }
    pattern_.row_ptr.push_back(pattern_.nnz());
  }
  // Damping C = beta K: row v_i also reaches the velocities of row i's stiffness columns
  // (every component inertial), after the stiffness columns (all < n), its diagonal sharing
  // the mass's position.
  beta_ = op_.damping_time();
  if (beta_ > 0 && static_cast<Index>(inertial_.size()) != n_)
    throw InputError("reduced inertia: damping needs every component inertial");
  if (beta_ > 0) damping_position_.assign(k.nnz(), -1);
  for (Index i : inertial_) {
    copy_stiffness_row(velocity_[i], i);
    // (velocity column, stiffness entry of its damping or -1), the mass's column included.
    std::vector<std::pair<Index, Index>> v_columns{{velocity_[i], -1}};
    if (beta_ > 0)
      for (Index p = k.row_ptr[i]; p < k.row_ptr[i + 1]; ++p)
        if (k.col_idx[p] != i) v_columns.emplace_back(velocity_[k.col_idx[p]], p);
    std::sort(v_columns.begin(), v_columns.end());
    for (const auto& [column, p] : v_columns) {
      (p >= 0 ? damping_position_[p] : mass_position_.emplace_back()) = pattern_.nnz();
      pattern_.col_idx.push_back(column);
    }
    damping_diagonal_.push_back(beta_ > 0 ? k.find(i, i) : -1);
    pattern_.row_ptr.push_back(pattern_.nnz());
  }
  k_values_.resize(k.nnz());
  r_.resize(n_);
  if (beta_ > 0) v_.resize(n_);
}

void ReducedInertiaSystem::internal_forces(Real t, std::span<const Real> y) {
  op_.internal_residual(t, y.subspan(0, n_), r_);
  if (beta_ > 0) {
    for (Index i = 0; i < n_; ++i) v_[i] = y[velocity_[i]];
    op_.add_damping_force(t, v_, r_);
  }
}

std::vector<Real> ReducedInertiaSystem::differential_components() const {
  std::vector<Real> id(size(), 1.0);
  for (Index i = 0; i < n_; ++i)
    if (velocity_[i] < 0) id[i] = 0.0;
  return id;
}

void ReducedInertiaSystem::residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                                    std::span<Real> r) {
  internal_forces(t, y);
  for (Index i = 0; i < n_; ++i) {
    const Index v = velocity_[i];
    if (v < 0) {
      r[i] = r_[i];
    } else {
      r[i] = yp[i] - y[v];
      r[v] = mass_[i] * yp[v] + r_[i];
    }
  }
}

void ReducedInertiaSystem::jacobian(Real t, Real c_j, std::span<const Real> y,
                                    std::span<const Real>, std::span<Real> values) {
  op_.stiffness(t, y.subspan(0, n_), k_values_);
  const CsrPattern& k = op_.stiffness_pattern();
  auto copy_stiffness_row = [&](Index row, Index i) {
    const Index start = row_stiffness_offset_[row];
    for (Index p = k.row_ptr[i]; p < k.row_ptr[i + 1]; ++p)
      values[start + (p - k.row_ptr[i])] = k_values_[p];
  };
  for (Index i = 0; i < n_; ++i) {
    const Index v = velocity_[i];
    if (v < 0) {
      copy_stiffness_row(i, i);
    } else {
      values[pattern_.row_ptr[i]] = c_j;
      values[pattern_.row_ptr[i] + 1] = -1.0;
      copy_stiffness_row(v, i);
    }
  }
  for (std::size_t k_ = 0; k_ < inertial_.size(); ++k_)
    values[mass_position_[k_]] = c_j * mass_[inertial_[k_]];
  if (beta_ > 0) {
    for (std::size_t p = 0; p < damping_position_.size(); ++p)
      if (damping_position_[p] >= 0) values[damping_position_[p]] = beta_ * k_values_[p];
    for (std::size_t k_ = 0; k_ < inertial_.size(); ++k_)
      if (damping_diagonal_[k_] >= 0)
        values[mass_position_[k_]] += beta_ * k_values_[damping_diagonal_[k_]];
  }
}

std::vector<Real> ReducedInertiaSystem::consistent_derivative(Real t, std::span<const Real> y) {
  std::vector<Real> yp(size(), 0.0);
  internal_forces(t, y);
  for (Index i : inertial_) {
    yp[i] = y[velocity_[i]];
    yp[velocity_[i]] = -r_[i] / mass_[i];
  }
  return yp;
}

}  // namespace rfmems

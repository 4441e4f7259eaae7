#include "physics/creep/continuum_creep_preconditioner.hpp"

#include <Eigen/Dense>
#include <algorithm>

#include "core/error.hpp"

namespace rfmems {

ContinuumCreepPreconditioner::ContinuumCreepPreconditioner(const CsrPattern& pattern,
                                                           Index structural_size, int n_components)
    : pattern_(pattern),
      ns_(structural_size),
      nc_(n_components),
      n_cells_((pattern.n_rows() - structural_size) / n_components) {
  if (nc_ < 1 || nc_ > 16 || ns_ + n_cells_ * nc_ != pattern.n_rows())
    throw SolverError("ContinuumCreepPreconditioner: rows are not u then whole cells of q");
  first_creep_column_.resize(ns_);
  for (Index row = 0; row < ns_; ++row) {
    const auto begin = pattern.col_idx.begin() + pattern.row_ptr[row];
    const auto end = pattern.col_idx.begin() + pattern.row_ptr[row + 1];
    if (!std::is_sorted(begin, end))
      throw SolverError("ContinuumCreepPreconditioner: structural rows must be sorted");
    first_creep_column_[row] = std::lower_bound(begin, end, ns_) - pattern.col_idx.begin();
  }
  // Each q row may reach its own cell's creep states only (D block diagonal).
  for (Index c = 0; c < n_cells_; ++c)
    for (int j = 0; j < nc_; ++j) {
      const Index row = ns_ + nc_ * c + j;
      for (Index k = pattern.row_ptr[row]; k < pattern.row_ptr[row + 1]; ++k) {
        const Index col = pattern.col_idx[k];
        if (col >= ns_ && (col - ns_) / nc_ != c)
          throw SolverError("ContinuumCreepPreconditioner: a creep row reaches another cell");
      }
    }
  values_.resize(pattern.nnz());
  block_inverse_.resize(static_cast<std::size_t>(n_cells_) * nc_ * nc_);
  rq_.resize(static_cast<std::size_t>(n_cells_) * nc_);
  zu_.resize(ns_);
}

void ContinuumCreepPreconditioner::setup() {
  Eigen::MatrixXd D(nc_, nc_);
  for (Index c = 0; c < n_cells_; ++c) {
    D.setZero();
    for (int j = 0; j < nc_; ++j) {
      const Index row = ns_ + nc_ * c + j;
      for (Index k = pattern_.row_ptr[row]; k < pattern_.row_ptr[row + 1]; ++k) {
        const Index col = pattern_.col_idx[k];
        if (col >= ns_) D(j, col - ns_ - nc_ * c) += values_[k];
      }
    }
    Eigen::Map<Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        block_inverse_.data() + static_cast<std::size_t>(c) * nc_ * nc_, nc_, nc_) =
        D.partialPivLu().inverse();
  }
}

void ContinuumCreepPreconditioner::apply_block_inverse(std::span<Real> xq) const {
  Real local[16];
  for (Index c = 0; c < n_cells_; ++c) {
    Real* x = xq.data() + nc_ * c;
    const Real* inverse = block_inverse_.data() + static_cast<std::size_t>(c) * nc_ * nc_;
    for (int j = 0; j < nc_; ++j) {
      Real sum = 0;
      for (int l = 0; l < nc_; ++l) sum += inverse[nc_ * j + l] * x[l];
      local[j] = sum;
    }
    std::copy(local, local + nc_, x);
  }
}

void ContinuumCreepPreconditioner::solve(std::span<const Real> r, std::span<Real> z,
                                         const StructuralSolve& structural) {
  // D^-1 r_q, then r_u - B D^-1 r_q.
  std::copy(r.begin() + ns_, r.end(), rq_.begin());
  apply_block_inverse(rq_);
  for (Index row = 0; row < ns_; ++row) {
    Real sum = r[row];
    for (Index k = first_creep_column_[row]; k < pattern_.row_ptr[row + 1]; ++k)
      sum -= values_[k] * rq_[pattern_.col_idx[k] - ns_];
    zu_[row] = sum;
  }
  structural(zu_);
  // z_q = D^-1 (r_q - E z_u); r is read before z is written (they may alias).
  for (Index row = ns_; row < pattern_.n_rows(); ++row) {
    Real sum = r[row];
    for (Index k = pattern_.row_ptr[row]; k < pattern_.row_ptr[row + 1]; ++k) {
      const Index col = pattern_.col_idx[k];
      if (col < ns_) sum -= values_[k] * zu_[col];
    }
    rq_[row - ns_] = sum;
  }
  apply_block_inverse(rq_);
  std::copy(zu_.begin(), zu_.end(), z.begin());
  std::copy(rq_.begin(), rq_.end(), z.begin() + ns_);
}

}  // namespace rfmems

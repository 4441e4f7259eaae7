#include "solvers/harmonic_response.hpp"

#include "core/error.hpp"

namespace rfmems {

HarmonicResponse::HarmonicResponse(SystemOperator& op, Real t, std::span<const Real> y0)
    : n_(op.size()), op_pattern_(op.jacobian_pattern()) {
  if (static_cast<Index>(y0.size()) != n_)
    throw std::invalid_argument("HarmonicResponse: the state's size is not the operator's");
  const std::vector<Real> rate(n_, 0.0);
  a_.assign(op_pattern_.nnz(), 0.0);
  b_.assign(op_pattern_.nnz(), 0.0);
  op.jacobian(t, 0.0, y0, rate, a_);
  op.jacobian(t, 1.0, y0, rate, b_);
  for (std::size_t k = 0; k < a_.size(); ++k) b_[k] -= a_[k];
  // Rows i of [A, -w B] and n + i of [w B, A]: both blocks on every row, the same pattern.
  pattern_.row_ptr.assign(1, 0);
  for (int half = 0; half < 2; ++half)
    for (Index i = 0; i < n_; ++i) {
      for (int block = 0; block < 2; ++block)
        for (Index k = op_pattern_.row_ptr[i]; k < op_pattern_.row_ptr[i + 1]; ++k)
          pattern_.col_idx.push_back(op_pattern_.col_idx[k] + block * n_);
      pattern_.row_ptr.push_back(pattern_.nnz());
    }
  values_.assign(pattern_.nnz(), 0.0);
}

void HarmonicResponse::fill_values(Real omega) {
  std::size_t out = 0;
  for (int half = 0; half < 2; ++half)
    for (Index i = 0; i < n_; ++i)
      for (int block = 0; block < 2; ++block)
        for (Index k = op_pattern_.row_ptr[i]; k < op_pattern_.row_ptr[i + 1]; ++k)
          values_[out++] = half == block ? a_[k] : (half == 0 ? -omega : omega) * b_[k];
}

std::vector<std::complex<Real>> HarmonicResponse::solve(Real omega, std::span<const Real> b_value,
                                                        std::span<const Real> b_rate) {
  if (static_cast<Index>(b_value.size()) != n_ || static_cast<Index>(b_rate.size()) != n_)
    throw std::invalid_argument("HarmonicResponse: the forcing's size is not the operator's");
  fill_values(omega);
  if (!lu_)
    lu_ = std::make_unique<KluFactorization>(pattern_, values_);
  else
    lu_->refactor(values_);
  std::vector<Real> rhs(2 * n_);
  for (Index i = 0; i < n_; ++i) {
    rhs[i] = -b_value[i];
    rhs[n_ + i] = -omega * b_rate[i];
  }
  lu_->solve(rhs);
  std::vector<std::complex<Real>> x(n_);
  for (Index i = 0; i < n_; ++i) x[i] = {rhs[i], rhs[n_ + i]};
  return x;
}

}  // namespace rfmems

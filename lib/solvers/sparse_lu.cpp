#include "solvers/sparse_lu.hpp"

namespace rfmems {

SparseLu::SparseLu(const CsrPattern& pattern, std::span<const Real> values, Index umfpack_from)
    : pattern_(pattern), values_(values.begin(), values.end()) {
  if (pattern.n_rows() >= umfpack_from)
    umfpack_ = std::make_unique<UmfpackFactorization>(pattern, values);
  else
    klu_ = std::make_unique<KluFactorization>(pattern, values);
}

void SparseLu::refactor(std::span<const Real> values) {
  values_.assign(values.begin(), values.end());
  if (umfpack_)
    umfpack_->refactor(values);
  else
    klu_->refactor(values);
}

void SparseLu::solve(std::span<Real> b) {
  if (umfpack_)
    umfpack_->solve(b);
  else
    klu_->solve(b);
}

void SparseLu::solve_refined(std::span<Real> b) {
  const std::vector<Real> rhs(b.begin(), b.end());
  std::vector<Real> r(rhs.size());
  solve(b);
  for (int step = 0; step < 2; ++step) {
    multiply(pattern_, values_, b, r);
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = rhs[i] - r[i];
    solve(r);
    for (std::size_t i = 0; i < r.size(); ++i) b[i] += r[i];
  }
}

long SparseLu::factor_entries() const {
  return umfpack_ ? umfpack_->factor_entries() : klu_->factor_entries();
}

}  // namespace rfmems

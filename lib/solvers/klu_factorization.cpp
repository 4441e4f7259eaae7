#include "solvers/klu_factorization.hpp"

#include <klu.h>
#include <vector>

#include "core/error.hpp"

namespace rfmems {

// KLU factorises compressed-column matrices; a CSR matrix is the CSC form of its transpose,
// so we factorise A^T and solve with klu_l_tsolve.
struct KluFactorization::Impl {
  std::vector<SuiteSparse_long> ptr, idx;
  std::vector<Real> values;
  klu_l_common common;
  klu_l_symbolic* symbolic = nullptr;
  klu_l_numeric* numeric = nullptr;
  SuiteSparse_long n = 0;
};

KluFactorization::KluFactorization(const CsrPattern& pattern, std::span<const Real> values,
                                   KluOrdering ordering)
    : impl_(new Impl) {
  Impl& k = *impl_;
  k.n = pattern.n_rows();
  k.ptr.assign(pattern.row_ptr.begin(), pattern.row_ptr.end());
  k.idx.assign(pattern.col_idx.begin(), pattern.col_idx.end());
  k.values.assign(values.begin(), values.end());
  klu_l_defaults(&k.common);
  k.common.ordering = ordering == KluOrdering::Colamd ? 1 : 0;
  k.symbolic = klu_l_analyze(k.n, k.ptr.data(), k.idx.data(), &k.common);
  if (k.symbolic)
    k.numeric = klu_l_factor(k.ptr.data(), k.idx.data(), k.values.data(), k.symbolic, &k.common);
  if (!k.numeric) {
    klu_l_free_symbolic(&k.symbolic, &k.common);
    delete impl_;
    throw SolverError("KLU factorisation failed (singular matrix?)");
  }
}

KluFactorization::~KluFactorization() {
  klu_l_free_numeric(&impl_->numeric, &impl_->common);
  klu_l_free_symbolic(&impl_->symbolic, &impl_->common);
  delete impl_;
}

void KluFactorization::refactor(std::span<const Real> values) {
  Impl& k = *impl_;
  if (static_cast<std::size_t>(values.size()) != k.values.size())
    throw SolverError("KLU refactor: value count differs from the pattern");
  k.values.assign(values.begin(), values.end());
  // The threshold: KLU's cheap estimate min|U_ii| / max|U_ii| (klu_rcond).
  constexpr Real kPoorPivots = 1e-12;
  bool ok = klu_l_refactor(k.ptr.data(), k.idx.data(), k.values.data(), k.symbolic, k.numeric,
                           &k.common) &&
            klu_l_rcond(k.symbolic, k.numeric, &k.common) && k.common.rcond > kPoorPivots;
  if (ok) return;
  klu_l_free_numeric(&k.numeric, &k.common);
  k.numeric = klu_l_factor(k.ptr.data(), k.idx.data(), k.values.data(), k.symbolic, &k.common);
  if (!k.numeric) throw SolverError("KLU refactorisation failed (singular matrix?)");
}

void KluFactorization::solve(std::span<Real> b) {
  klu_l_tsolve(impl_->symbolic, impl_->numeric, impl_->n, 1, b.data(), &impl_->common);
}

}  // namespace rfmems

#include "solvers/klu_factorization.hpp"

#include <klu.h>
#include <metis.h>

#include <algorithm>
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

namespace {

// KLU's user ordering (klu_common.user_order): METIS_NodeND on the graph of A + A^T of the
// compressed-column matrix (Ap, Ai); returns 1 on success, as KLU expects.
SuiteSparse_long nested_dissection(SuiteSparse_long n, SuiteSparse_long* Ap, SuiteSparse_long* Ai,
                                   SuiteSparse_long* Perm, klu_l_common*) {
  std::vector<std::vector<idx_t>> adjacent(n);
  for (SuiteSparse_long c = 0; c < n; ++c)
    for (SuiteSparse_long k = Ap[c]; k < Ap[c + 1]; ++k)
      if (Ai[k] != c) {
        adjacent[Ai[k]].push_back(static_cast<idx_t>(c));
        adjacent[c].push_back(static_cast<idx_t>(Ai[k]));
      }
  std::vector<idx_t> xadj{0}, adjncy;
  for (auto& a : adjacent) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    adjncy.insert(adjncy.end(), a.begin(), a.end());
    xadj.push_back(static_cast<idx_t>(adjncy.size()));
    a = {};
  }
  idx_t nodes = static_cast<idx_t>(n);
  std::vector<idx_t> perm(n), inverse(n);
  if (METIS_NodeND(&nodes, xadj.data(), adjncy.data(), nullptr, nullptr, perm.data(),
                   inverse.data()) != METIS_OK)
    return 0;
  std::copy(perm.begin(), perm.end(), Perm);
  return 1;
}

}  // namespace

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
  if (ordering == KluOrdering::NestedDissection) {
    k.common.ordering = 3;  // user ordering
    k.common.user_order = nested_dissection;
  }
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

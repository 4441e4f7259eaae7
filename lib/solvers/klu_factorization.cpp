#include "solvers/klu_factorization.hpp"

#include <klu.h>
#include <metis.h>

#include <algorithm>
#include <cmath>
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
  KluSystem system = KluSystem::Uniform;
  Real fresh_rcond = 0;  // klu_rcond at the last factorisation with fresh pivoting
  long fresh = 0, refactors = 0;

  std::vector<Real> row_scale;  // equilibration of A's rows (empty: none)

  // The values, each row of A divided by its largest entry when equilibrating.
  void load(std::span<const Real> v) {
    values.assign(v.begin(), v.end());
    if (system != KluSystem::MixedUnits) return;
    row_scale.assign(n, 1.0);
    for (SuiteSparse_long i = 0; i < n; ++i) {
      Real largest = 0;
      for (SuiteSparse_long p = ptr[i]; p < ptr[i + 1]; ++p)
        largest = std::max(largest, std::abs(values[p]));
      if (largest > 0) row_scale[i] = 1.0 / largest;
      for (SuiteSparse_long p = ptr[i]; p < ptr[i + 1]; ++p) values[p] *= row_scale[i];
    }
  }

  // klu_rcond of the current numeric factorisation (0 if KLU cannot tell).
  Real rcond() { return klu_l_rcond(symbolic, numeric, &common) ? common.rcond : 0.0; }
};

namespace {

// KLU's user ordering (klu_common.user_order): nested_dissection_order of the compressed-column
// matrix (Ap, Ai), whose A + A^T graph is that of the CSR matrix with the same arrays; returns 1
// on success, as KLU expects.
SuiteSparse_long nested_dissection(SuiteSparse_long n, SuiteSparse_long* Ap, SuiteSparse_long* Ai,
                                   SuiteSparse_long* Perm, klu_l_common*) {
  CsrPattern pattern;
  pattern.row_ptr.assign(Ap, Ap + n + 1);
  pattern.col_idx.assign(Ai, Ai + Ap[n]);
  try {
    const std::vector<Index> order = nested_dissection_order(pattern);
    std::copy(order.begin(), order.end(), Perm);
  } catch (const SolverError&) {
    return 0;
  }
  return 1;
}

}  // namespace

std::vector<Index> nested_dissection_order(const CsrPattern& pattern) {
  const Index n = pattern.n_rows();
  std::vector<std::vector<idx_t>> adjacent(n);
  for (Index r = 0; r < n; ++r)
    for (Index k = pattern.row_ptr[r]; k < pattern.row_ptr[r + 1]; ++k)
      if (pattern.col_idx[k] != r) {
        adjacent[pattern.col_idx[k]].push_back(static_cast<idx_t>(r));
        adjacent[r].push_back(static_cast<idx_t>(pattern.col_idx[k]));
      }
  const double dense = std::max(16.0, 10.0 * std::sqrt(static_cast<double>(n)));
  std::vector<idx_t> local(n, -1), dense_nodes, sparse_nodes;
  for (Index i = 0; i < n; ++i) {
    std::sort(adjacent[i].begin(), adjacent[i].end());
    adjacent[i].erase(std::unique(adjacent[i].begin(), adjacent[i].end()), adjacent[i].end());
    if (static_cast<double>(adjacent[i].size()) > dense) {
      dense_nodes.push_back(static_cast<idx_t>(i));
    } else {
      local[i] = static_cast<idx_t>(sparse_nodes.size());
      sparse_nodes.push_back(static_cast<idx_t>(i));
    }
  }
  std::vector<idx_t> xadj{0}, adjncy;
  for (const idx_t i : sparse_nodes) {
    for (const idx_t j : adjacent[i])
      if (local[j] >= 0) adjncy.push_back(local[j]);
    xadj.push_back(static_cast<idx_t>(adjncy.size()));
    adjacent[i] = {};
  }
  idx_t nodes = static_cast<idx_t>(sparse_nodes.size());
  std::vector<idx_t> perm(nodes), inverse(nodes);
  if (nodes > 0 && METIS_NodeND(&nodes, xadj.data(), adjncy.data(), nullptr, nullptr, perm.data(),
                                inverse.data()) != METIS_OK)
    throw SolverError("METIS_NodeND failed");
  std::vector<Index> order;
  order.reserve(n);
  for (const idx_t k : perm) order.push_back(sparse_nodes[k]);
  order.insert(order.end(), dense_nodes.begin(), dense_nodes.end());
  return order;
}

KluFactorization::KluFactorization(const CsrPattern& pattern, std::span<const Real> values,
                                   KluOrdering ordering, KluSystem system)
    : impl_(new Impl) {
  Impl& k = *impl_;
  k.n = pattern.n_rows();
  k.ptr.assign(pattern.row_ptr.begin(), pattern.row_ptr.end());
  k.idx.assign(pattern.col_idx.begin(), pattern.col_idx.end());
  k.system = system;
  k.load(values);
  klu_l_defaults(&k.common);
  if (ordering == KluOrdering::BySize)
    ordering = k.n < 1000 ? KluOrdering::Amd : KluOrdering::NestedDissection;
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
  k.fresh = 1;
  k.fresh_rcond = k.rcond();
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
  k.load(values);
  constexpr Real kAbsoluteFloor = 1e-12, kRelativeDecay = 1e-3;
  bool ok =
      klu_l_refactor(k.ptr.data(), k.idx.data(), k.values.data(), k.symbolic, k.numeric, &k.common);
  if (ok) {
    const Real rcond = k.rcond();
    ok = k.system == KluSystem::Uniform ? rcond > kAbsoluteFloor
                                        : rcond >= kRelativeDecay * k.fresh_rcond;
  }
  if (ok) {
    ++k.refactors;
    return;
  }
  klu_l_free_numeric(&k.numeric, &k.common);
  k.numeric = klu_l_factor(k.ptr.data(), k.idx.data(), k.values.data(), k.symbolic, &k.common);
  if (!k.numeric) throw SolverError("KLU refactorisation failed (singular matrix?)");
  ++k.fresh;
  k.fresh_rcond = k.rcond();
}

long KluFactorization::fresh_factorizations() const { return impl_->fresh; }
long KluFactorization::refactorizations() const { return impl_->refactors; }
long KluFactorization::factor_entries() const {
  const klu_l_numeric* f = impl_->numeric;
  return f ? f->lnz + f->unz - impl_->n + f->nzoff : 0;  // the diagonal is in both
}

void KluFactorization::solve(std::span<Real> b) {
  for (std::size_t i = 0; i < impl_->row_scale.size(); ++i) b[i] *= impl_->row_scale[i];
  klu_l_tsolve(impl_->symbolic, impl_->numeric, impl_->n, 1, b.data(), &impl_->common);
}

}  // namespace rfmems

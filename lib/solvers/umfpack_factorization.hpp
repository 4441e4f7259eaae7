// A sparse LU factorisation with SuiteSparse UMFPACK (multifrontal: dense frontal matrices
// through BLAS), factorised once and reused for many solves. For large 2D meshes with wide
// stencils, whose LU fill makes KLU's left-looking, column-by-column factorisation slow: the
// 40,000-cell cubic plate of bench/bench_modal.cpp (120,000 unknowns, 6.3e6 nonzeros)
// factorises in 78 s with KLU (METIS nested dissection) and in about 25 s with UMFPACK (METIS)
// on a loaded machine with the reference BLAS, 5.3 s with OpenBLAS (docs/modal.md); the
// plane-stress cantilever at 640 x 64 (82,000 unknowns) in 1.6 s against KLU's 12 s
// (docs/scale.md).
#pragma once
#include <span>

#include "core/system_operator.hpp"

namespace rfmems {

// The size from which the sparse direct solves factorise with UMFPACK rather than KLU (the
// modal solver's shift-invert, KINSOL's static solves): below it KLU's lower overhead wins
// (480 unknowns: 8 ms for a whole modal analysis), above it the multifrontal method does
// (30,000 unknowns: 2-3x; 82,000: 8x).
constexpr Index kUmfpackFrom = 20000;

// How UMFPACK orders the matrix:
//   Metis: its default (unsymmetric) strategy with METIS nested dissection;
//   SymmetricNestedDissection: its symmetric strategy (diagonal pivots preferred, a symmetric
//     pre-ordering kept) on nested_dissection_order (klu_factorization.hpp), which orders a dense
//     row and column last. For systems with one (the voltage of the bordered quasi-static
//     pull-in system), where METIS with a hub fills ~8x more: the 160 x 16 plate switch's
//     bordered Jacobian (7681 unknowns) has 3.1e6 entries in L + U against Metis's 2.4e7 and
//     KLU's 4.3e6 (nested dissection), and factorises in 0.07 s against KLU's 0.3 s, solves in
//     2.5 ms against 8.5 ms (dense fronts through BLAS; bench/bench_quasi_static_trace.cpp).
enum class UmfpackOrdering { Metis, SymmetricNestedDissection };

class UmfpackFactorization {
 public:
  // Factorises the CSR matrix (pattern, values) in that ordering; each solve then takes up to
  // `refinement_steps` steps of iterative refinement (UMFPACK's, against the matrix itself: a
  // residual and a solve each). Throws SolverError if singular or if UMFPACK fails.
  UmfpackFactorization(const CsrPattern& pattern, std::span<const Real> values,
                       int refinement_steps = 0, UmfpackOrdering ordering = UmfpackOrdering::Metis);
  ~UmfpackFactorization();
  UmfpackFactorization(const UmfpackFactorization&) = delete;
  UmfpackFactorization& operator=(const UmfpackFactorization&) = delete;
  // A new matrix of the same pattern: the numeric factorisation again (fresh partial pivoting)
  // on the symbolic analysis (ordering, frontal structure) of the first. SolverError as above.
  void refactor(std::span<const Real> values);
  // Solves A x = b in place.
  void solve(std::span<Real> b);
  // Numeric factorisations so far (the first included), and the entries of L + U.
  long factorizations() const;
  long factor_entries() const;

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace rfmems

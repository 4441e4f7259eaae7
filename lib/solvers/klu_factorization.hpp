// A sparse LU factorisation with SuiteSparse KLU, factorised once and reused for many solves
// (the segregated baseline and the "one factorisation" cost floor of the benchmarks).
#pragma once
#include <span>

#include "core/system_operator.hpp"

namespace rfmems {

// Fill-reducing ordering of the symbolic analysis: AMD (KLU's default) on A + A^T, or COLAMD
// on the columns (less fill for matrices whose rows reach far, e.g. the plate creep Schur
// complement: 1.32e6 vs 1.37e6 entries in L and a 1.6x faster refactor on 81 x 21 cells), or
// METIS nested dissection of A + A^T (large 2D grids: the 240k-unknown Stokes saddle point of
// bench_stokes_damping factorises in 32 CPU s against AMD's 142 s, L + U 5.2e7 entries).
enum class KluOrdering { Amd, Colamd, NestedDissection };

class KluFactorization {
 public:
  // Factorises the CSR matrix (pattern, values). Throws SolverError if singular.
  KluFactorization(const CsrPattern& pattern, std::span<const Real> values,
                   KluOrdering ordering = KluOrdering::Amd);
  ~KluFactorization();
  KluFactorization(const KluFactorization&) = delete;
  KluFactorization& operator=(const KluFactorization&) = delete;
  // Solves A x = b in place.
  void solve(std::span<Real> b);
  // New values on the same pattern (e.g. the geometry moved): keeps the symbolic analysis
  // (ordering) and the pivot sequence (klu_refactor); if the reused pivots give a poor
  // reciprocal condition estimate it factorises again with fresh pivoting, still reusing the
  // symbolic analysis. Throws SolverError if singular.
  void refactor(std::span<const Real> values);

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace rfmems

// A sparse LU factorisation with SuiteSparse KLU, factorised once and reused for many solves
// (the segregated baseline and the "one factorisation" cost floor of the benchmarks).
#pragma once
#include <span>

#include "core/system_operator.hpp"

namespace rfmems {

class KluFactorization {
 public:
  // Factorises the CSR matrix (pattern, values). Throws SolverError if singular.
  KluFactorization(const CsrPattern& pattern, std::span<const Real> values);
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

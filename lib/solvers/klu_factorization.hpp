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

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace rfmems

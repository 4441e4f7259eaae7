// A sparse LU factorisation with SuiteSparse UMFPACK (multifrontal: dense frontal matrices
// through BLAS), factorised once and reused for many solves. For large 2D meshes with wide
// stencils, whose LU fill makes KLU's left-looking, column-by-column factorisation slow: the
// 40,000-cell cubic plate of bench/bench_modal.cpp (120,000 unknowns, 6.3e6 nonzeros)
// factorises in 78 s with KLU (METIS nested dissection) and in about 25 s with UMFPACK (METIS),
// CPU on a loaded machine (docs/modal.md).
#pragma once
#include <span>

#include "core/system_operator.hpp"

namespace rfmems {

class UmfpackFactorization {
 public:
  // Factorises the CSR matrix (pattern, values), METIS ordering, no iterative refinement. Throws
  // SolverError if singular or if UMFPACK fails.
  UmfpackFactorization(const CsrPattern& pattern, std::span<const Real> values);
  ~UmfpackFactorization();
  UmfpackFactorization(const UmfpackFactorization&) = delete;
  UmfpackFactorization& operator=(const UmfpackFactorization&) = delete;
  // Solves A x = b in place.
  void solve(std::span<Real> b);

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace rfmems

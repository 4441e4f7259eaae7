// The sparse LU factorisation of a CSR matrix for code that factorises and solves by itself
// (not through a SUNDIALS linear solver), chosen by size as sparse_direct_solver.hpp chooses
// for KINSOL and IDA: KLU (AMD ordering, column by column) below `umfpack_from` unknowns,
// UMFPACK (METIS ordering, multifrontal with dense fronts through BLAS) from there on, where the
// fill of a 3D mesh's wide stencil makes KLU slow and large. Measured on the 3D creep strip's
// stiffness (480 x 24 x 3 cells, 103,680 unknowns): docs/creep.md.
#pragma once
#include <memory>
#include <span>
#include <vector>

#include "solvers/klu_factorization.hpp"
#include "solvers/umfpack_factorization.hpp"

namespace rfmems {

class SparseLu {
 public:
  // `pattern` must outlive this. Throws SolverError if the matrix is singular.
  SparseLu(const CsrPattern& pattern, std::span<const Real> values,
           Index umfpack_from = kUmfpackFrom);
  // A new matrix of the same pattern, on the first's ordering.
  void refactor(std::span<const Real> values);
  // Solves A x = b in place, at the factorisation's accuracy: enough for a preconditioner, or
  // for Newton, which corrects the error itself.
  void solve(std::span<Real> b);
  // The same with two steps of iterative refinement against the matrix, where the answer is
  // used as it is (an equilibrium taken in one step). On the 3D creep strip's stiffness (480 x
  // 24 x 3 cells, half span, 103,680 unknowns) the plain solves left the deflection 3.0e-8
  // (KLU) and 0.2e-8 (UMFPACK) from where the refined ones agree to 4e-9; the creep
  // deflection, 1e-3 of the elastic one and measured from it, inherited 3.5e-5 from KLU's.
  void solve_refined(std::span<Real> b);
  bool umfpack() const { return umfpack_ != nullptr; }
  long factor_entries() const;

 private:
  const CsrPattern& pattern_;
  std::vector<Real> values_;
  std::unique_ptr<KluFactorization> klu_;
  std::unique_ptr<UmfpackFactorization> umfpack_;
};

}  // namespace rfmems

// A SUNDIALS direct linear solver (SUNLinearSolver) for KINSOL and IDA on sparse LU
// factorisations kept across setups, chosen by size: KLU (solvers/klu_factorization.hpp) below
// `umfpack_from` unknowns, UMFPACK (multifrontal, METIS ordering, dense fronts through BLAS:
// solvers/umfpack_factorization.hpp) from there on, where the LU fill of a large 2D or 3D mesh
// with wide stencils makes KLU's column-by-column factorisation slow.
//
// The symbolic analysis (the fill-reducing ordering) is done once for the pattern. Each later
// setup refactorises: KLU keeping the pivot sequence (klu_refactor) while its condition
// estimate stays within 1e3 of its value at the last fresh pivoting (KluSystem::MixedUnits);
// UMFPACK numerically again on its symbolic analysis, with fresh partial pivoting. SUNDIALS' own
// SUNLinSol_KLU pivots afresh whenever that estimate is below the (2/3)-power of the unit
// round-off, which a bordered plate system with deflections, rotations and a voltage as
// unknowns always is: there it refactorised from scratch at every Newton step.
#pragma once
#include <memory>

#include "solvers/klu_factorization.hpp"
#include "solvers/sundials_handles.hpp"
#include "solvers/umfpack_factorization.hpp"

namespace rfmems::sundials {

struct DirectCounts {
  long fresh_factorizations = 0, refactorizations = 0, factor_entries = 0;
  bool umfpack = false;  // which factorisation the last setup used
};

// UMFPACK's iterative refinement in each of KINSOL's solves: a Newton step's solve at the LU's
// backward error, so that a linear problem converges in one step (solvers/kinsol_solver.hpp's
// round-off floor) rather than paying a second factorisation. IDA's Newton iteration, with its
// lagged Jacobian, corrects the solve's error itself and asks for none (each step costs a
// solve and a product: 2 steps took the 481 x 12 plane creep run from 21 to 36 s).
constexpr int kRefinementSteps = 2;

// The solver for CSR matrices of `pattern`'s shape. `counts` (optional) is kept up to date.
LinearSolver make_sparse_direct_solver(SUNContext ctx, KluOrdering ordering,
                                       std::shared_ptr<DirectCounts> counts = nullptr,
                                       Index umfpack_from = kUmfpackFrom,
                                       int refinement_steps = kRefinementSteps,
                                       UmfpackOrdering umfpack_ordering = UmfpackOrdering::Metis);

}  // namespace rfmems::sundials

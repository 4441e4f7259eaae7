// A SUNDIALS direct linear solver (SUNLinearSolver) on KluFactorization, for KINSOL and IDA
// when successive Jacobians share a pattern: the symbolic analysis (the fill-reducing ordering)
// is done once, and each later setup refactorises keeping the pivot sequence (klu_refactor)
// while KLU's condition estimate stays within 1e3 of its value at the last fresh pivoting
// (KluSystem::MixedUnits). SUNDIALS' own SUNLinSol_KLU pivots afresh whenever that
// estimate is below (2/3)-power of the unit round-off, which a bordered plate system with
// deflections, rotations and a voltage as unknowns always is: there it refactorised from
// scratch at every Newton step.
#pragma once
#include <memory>

#include "solvers/klu_factorization.hpp"
#include "solvers/sundials_handles.hpp"

namespace rfmems::sundials {

struct KluCounts {
  long fresh_factorizations = 0, refactorizations = 0, factor_entries = 0;
};

// The solver for CSR matrices of `pattern`'s shape. `counts` (optional) is kept up to date.
LinearSolver make_reusing_klu_solver(SUNContext ctx, KluOrdering ordering,
                                     std::shared_ptr<KluCounts> counts = nullptr);

}  // namespace rfmems::sundials

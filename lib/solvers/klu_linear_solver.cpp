#include "solvers/klu_linear_solver.hpp"

#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <exception>

#include "core/error.hpp"

namespace rfmems::sundials {

namespace {

struct Content {
  KluOrdering ordering;
  std::shared_ptr<KluCounts> counts;
  CsrPattern pattern;
  std::unique_ptr<KluFactorization> lu;
  int last_flag = SUNLS_SUCCESS;
};

Content& content(SUNLinearSolver s) { return *static_cast<Content*>(s->content); }

SUNLinearSolver_Type get_type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID get_id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }
sunindextype last_flag(SUNLinearSolver s) { return content(s).last_flag; }

// A failed factorisation is recoverable: the integrator or Newton may retry with a new matrix.
int setup(SUNLinearSolver s, SUNMatrix a) {
  Content& c = content(s);
  const sunindextype n = SUNSparseMatrix_NP(a);
  const sunindextype* ptr = SUNSparseMatrix_IndexPointers(a);
  const std::span<const Real> values(SUNSparseMatrix_Data(a), static_cast<std::size_t>(ptr[n]));
  try {
    if (!c.lu || c.pattern.nnz() != ptr[n]) {
      const sunindextype* idx = SUNSparseMatrix_IndexValues(a);
      c.pattern.row_ptr.assign(ptr, ptr + n + 1);
      c.pattern.col_idx.assign(idx, idx + ptr[n]);
      c.lu =
          std::make_unique<KluFactorization>(c.pattern, values, c.ordering, KluSystem::MixedUnits);
    } else {
      c.lu->refactor(values);
    }
  } catch (const std::exception&) {
    c.lu.reset();
    return c.last_flag = SUNLS_PACKAGE_FAIL_REC;
  }
  if (c.counts)
    *c.counts = {c.lu->fresh_factorizations(), c.lu->refactorizations(), c.lu->factor_entries()};
  return c.last_flag = SUNLS_SUCCESS;
}

int solve(SUNLinearSolver s, SUNMatrix, N_Vector x, N_Vector b, realtype) {
  Content& c = content(s);
  if (!c.lu) return c.last_flag = SUNLS_PACKAGE_FAIL_UNREC;
  N_VScale(1.0, b, x);
  c.lu->solve(as_span(x));
  return c.last_flag = SUNLS_SUCCESS;
}

int free_solver(SUNLinearSolver s) {
  delete static_cast<Content*>(s->content);
  s->content = nullptr;
  SUNLinSolFreeEmpty(s);
  return SUNLS_SUCCESS;
}

}  // namespace

LinearSolver make_reusing_klu_solver(SUNContext ctx, KluOrdering ordering,
                                     std::shared_ptr<KluCounts> counts) {
  SUNLinearSolver s = SUNLinSolNewEmpty(ctx);
  if (!s) throw SolverError("SUNLinSolNewEmpty failed");
  s->content = new Content{ordering, std::move(counts), {}, nullptr};
  s->ops->gettype = get_type;
  s->ops->getid = get_id;
  s->ops->initialize = initialize;
  s->ops->setup = setup;
  s->ops->solve = solve;
  s->ops->lastflag = last_flag;
  s->ops->free = free_solver;
  return LinearSolver(s);
}

}  // namespace rfmems::sundials

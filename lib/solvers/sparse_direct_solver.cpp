#include "solvers/sparse_direct_solver.hpp"

#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <exception>

#include "core/error.hpp"

namespace rfmems::sundials {

namespace {

struct Content {
  KluOrdering ordering;
  std::shared_ptr<DirectCounts> counts;
  Index umfpack_from;
  int refinement_steps;
  UmfpackOrdering umfpack_ordering;
  CsrPattern pattern;
  std::unique_ptr<KluFactorization> klu;
  std::unique_ptr<UmfpackFactorization> umfpack;
  int last_flag = SUNLS_SUCCESS;

  bool factorized() const { return klu || umfpack; }
  void reset() {
    klu.reset();
    umfpack.reset();
  }
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
    if (!c.factorized() || c.pattern.nnz() != ptr[n]) {
      const sunindextype* idx = SUNSparseMatrix_IndexValues(a);
      c.pattern.row_ptr.assign(ptr, ptr + n + 1);
      c.pattern.col_idx.assign(idx, idx + ptr[n]);
      c.reset();
      if (n >= c.umfpack_from)
        c.umfpack = std::make_unique<UmfpackFactorization>(c.pattern, values, c.refinement_steps,
                                                           c.umfpack_ordering);
      else
        c.klu = std::make_unique<KluFactorization>(c.pattern, values, c.ordering,
                                                   KluSystem::MixedUnits);
    } else if (c.umfpack) {
      c.umfpack->refactor(values);
    } else {
      c.klu->refactor(values);
    }
  } catch (const std::exception&) {
    c.reset();
    return c.last_flag = SUNLS_PACKAGE_FAIL_REC;
  }
  if (c.counts) {
    if (c.umfpack)
      *c.counts = {1, c.umfpack->factorizations() - 1, c.umfpack->factor_entries(), true};
    else
      *c.counts = {c.klu->fresh_factorizations(), c.klu->refactorizations(),
                   c.klu->factor_entries(), false};
  }
  return c.last_flag = SUNLS_SUCCESS;
}

int solve(SUNLinearSolver s, SUNMatrix, N_Vector x, N_Vector b, realtype) {
  Content& c = content(s);
  if (!c.factorized()) return c.last_flag = SUNLS_PACKAGE_FAIL_UNREC;
  N_VScale(1.0, b, x);
  try {
    if (c.umfpack)
      c.umfpack->solve(as_span(x));
    else
      c.klu->solve(as_span(x));
  } catch (const std::exception&) {
    return c.last_flag = SUNLS_PACKAGE_FAIL_UNREC;
  }
  return c.last_flag = SUNLS_SUCCESS;
}

int free_solver(SUNLinearSolver s) {
  delete static_cast<Content*>(s->content);
  s->content = nullptr;
  SUNLinSolFreeEmpty(s);
  return SUNLS_SUCCESS;
}

}  // namespace

LinearSolver make_sparse_direct_solver(SUNContext ctx, KluOrdering ordering,
                                       std::shared_ptr<DirectCounts> counts, Index umfpack_from,
                                       int refinement_steps, UmfpackOrdering umfpack_ordering) {
  SUNLinearSolver s = SUNLinSolNewEmpty(ctx);
  if (!s) throw SolverError("SUNLinSolNewEmpty failed");
  s->content =
      new Content{ordering, std::move(counts), umfpack_from, refinement_steps, umfpack_ordering,
                  {},       nullptr,           nullptr};
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

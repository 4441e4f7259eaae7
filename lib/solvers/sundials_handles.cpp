#include "solvers/sundials_handles.hpp"

#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>

#include "core/error.hpp"

namespace rfmems::sundials {

Context make_context() {
  SUNContext ctx = nullptr;
  if (SUNContext_Create(nullptr, &ctx) != 0) throw SolverError("SUNContext_Create failed");
  return Context(ctx);
}

Vector make_serial_vector(Index n, SUNContext ctx) {
  N_Vector v = N_VNew_Serial(n, ctx);
  if (!v) throw SolverError("N_VNew_Serial failed");
  N_VConst(0.0, v);
  return Vector(v);
}

Matrix make_csr_matrix(const CsrPattern& pattern, SUNContext ctx) {
  SUNMatrix m = SUNSparseMatrix(pattern.n_rows(), pattern.n_rows(),
                                std::max<Index>(pattern.nnz(), 1), CSR_MAT, ctx);
  if (!m) throw SolverError("SUNSparseMatrix failed");
  load_pattern(pattern, m);
  return Matrix(m);
}

void load_pattern(const CsrPattern& pattern, SUNMatrix m) {
  if (SUNSparseMatrix_NNZ(m) < pattern.nnz()) SUNSparseMatrix_Reallocate(m, pattern.nnz());
  std::copy(pattern.row_ptr.begin(), pattern.row_ptr.end(), SUNSparseMatrix_IndexPointers(m));
  std::copy(pattern.col_idx.begin(), pattern.col_idx.end(), SUNSparseMatrix_IndexValues(m));
}

LinearSolver make_klu_solver(N_Vector y, SUNMatrix a, SUNContext ctx) {
  LinearSolver solver(SUNLinSol_KLU(y, a, ctx));
  if (!solver) throw SolverError("SUNLinSol_KLU failed");
  SUNLinSol_KLUSetOrdering(solver.get(), 0);
  return solver;
}

}  // namespace rfmems::sundials

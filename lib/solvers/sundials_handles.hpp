// RAII owners for SUNDIALS objects. This directory is the only place that includes SUNDIALS.
#pragma once
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include <memory>
#include <span>

#include "core/system_operator.hpp"

namespace rfmems::sundials {

struct ContextDeleter {
  void operator()(SUNContext ctx) const { SUNContext_Free(&ctx); }
};
struct VectorDeleter {
  void operator()(N_Vector v) const { N_VDestroy(v); }
};
struct MatrixDeleter {
  void operator()(SUNMatrix m) const { SUNMatDestroy(m); }
};
struct LinearSolverDeleter {
  void operator()(SUNLinearSolver s) const { SUNLinSolFree(s); }
};

using Context = std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter>;
using Vector = std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter>;
using Matrix = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter>;
using LinearSolver = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, LinearSolverDeleter>;

Context make_context();
Vector make_serial_vector(Index n, SUNContext ctx);
// A CSR SUNSparseMatrix holding `pattern` (values zero).
Matrix make_csr_matrix(const CsrPattern& pattern, SUNContext ctx);

// SUNLinSol_KLU on (y, A) with the AMD ordering (KLU's own default) rather than SUNDIALS'
// COLAMD: on the bordered pull-in systems and the plate's wide stencils COLAMD fills in 4x
// more (measured: 116 s against 27 s for a 160 x 16 plate's displacement-controlled pull-in
// curve). SolverError if SUNDIALS cannot create it.
LinearSolver make_klu_solver(N_Vector y, SUNMatrix a, SUNContext ctx);
// Copies the pattern into a CSR SUNSparseMatrix (KLU may have been handed a fresh one).
void load_pattern(const CsrPattern& pattern, SUNMatrix m);

inline std::span<Real> as_span(N_Vector v) {
  return {N_VGetArrayPointer(v), static_cast<std::size_t>(N_VGetLength(v))};
}

}  // namespace rfmems::sundials

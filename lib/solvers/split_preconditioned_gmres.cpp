#include "solvers/split_preconditioned_gmres.hpp"

#include <sunlinsol/sunlinsol_spgmr.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "solvers/sundials_handles.hpp"

namespace rfmems {

namespace {

struct Operators {
  const CsrPattern& pattern;
  std::span<const Real> values;
  const PreconditionerSolve& preconditioner;
};

// z = A v
int product(void* data, N_Vector v, N_Vector z) {
  const auto* op = static_cast<const Operators*>(data);
  multiply(op->pattern, op->values, sundials::as_span(v), sundials::as_span(z));
  return 0;
}

// z = P^-1 r
int precondition(void* data, N_Vector r, N_Vector z, realtype, int) {
  const auto* op = static_cast<const Operators*>(data);
  N_VScale(1.0, r, z);
  op->preconditioner(sundials::as_span(z));
  return 0;
}

}  // namespace

SplitGmresResult split_preconditioned_gmres(const CsrPattern& pattern, std::span<const Real> values,
                                            const PreconditionerSolve& preconditioner,
                                            std::span<const Real> b, std::span<Real> x,
                                            const SplitGmresOptions& options) {
  const Index n = pattern.n_rows();
  sundials::Context ctx = sundials::make_context();
  sundials::Vector bv = sundials::make_serial_vector(n, ctx.get());
  sundials::Vector xv = sundials::make_serial_vector(n, ctx.get());
  sundials::Vector unit = sundials::make_serial_vector(n, ctx.get());
  sundials::Vector weight = sundials::make_serial_vector(n, ctx.get());
  N_VConst(1.0, unit.get());
  std::span<Real> w = sundials::as_span(weight.get());
  Real b_norm = 0;
  for (Index i = 0; i < n; ++i) {
    Real largest = 0;
    for (Index k = pattern.row_ptr[i]; k < pattern.row_ptr[i + 1]; ++k)
      largest = std::max(largest, std::abs(values[k]));
    w[i] = largest > 0 ? 1 / largest : 1;
    b_norm += (w[i] * b[i]) * (w[i] * b[i]);
  }
  b_norm = std::sqrt(b_norm);
  std::copy(b.begin(), b.end(), sundials::as_span(bv.get()).begin());
  std::copy(x.begin(), x.end(), sundials::as_span(xv.get()).begin());

  Operators op{pattern, values, preconditioner};
  sundials::LinearSolver gmres(
      SUNLinSol_SPGMR(xv.get(), SUN_PREC_RIGHT, options.krylov_dimension, ctx.get()));
  if (!gmres) throw SolverError("SUNLinSol_SPGMR failed");
  SUNLinSol_SPGMRSetMaxRestarts(gmres.get(), options.max_restarts);
  SUNLinSolSetATimes(gmres.get(), &op, product);
  SUNLinSolSetPreconditioner(gmres.get(), &op, nullptr, precondition);
  // s1 weights the (right-preconditioned) residual, s2 the solution.
  SUNLinSolSetScalingVectors(gmres.get(), weight.get(), unit.get());
  if (SUNLinSolInitialize(gmres.get()) != SUNLS_SUCCESS || SUNLinSolSetup(gmres.get(), nullptr))
    throw SolverError("SPGMR set-up failed");
  const int flag =
      SUNLinSolSolve(gmres.get(), nullptr, xv.get(), bv.get(), options.relative_tolerance * b_norm);
  const std::span<const Real> xs = sundials::as_span(xv.get());
  std::copy(xs.begin(), xs.end(), x.begin());
  SplitGmresResult result;
  result.iterations = SUNLinSolNumIters(gmres.get());
  result.relative_residual = b_norm > 0 ? SUNLinSolResNorm(gmres.get()) / b_norm : 0;
  result.converged = flag == SUNLS_SUCCESS;
  return result;
}

}  // namespace rfmems

#include "solvers/kinsol_solver.hpp"

#include <fmt/format.h>
#include <kinsol/kinsol.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"

namespace rfmems {

namespace {
void check(int flag, const char* call) {
  if (flag < 0) throw SolverError(fmt::format("KINSOL: {} failed with flag {}", call, flag));
}
}  // namespace

KinsolSolver::KinsolSolver(SystemOperator& op, const KinsolOptions& options)
    : op_(op), options_(options), ctx_(sundials::make_context()) {
  const Index n = op_.size();
  y_ = sundials::make_serial_vector(n, ctx_.get());
  scale_u_ = sundials::make_serial_vector(n, ctx_.get());
  scale_f_ = sundials::make_serial_vector(n, ctx_.get());
  zero_ = sundials::make_serial_vector(n, ctx_.get());
  jac_ = sundials::make_csr_matrix(op_.jacobian_pattern(), ctx_.get());
  solver_ = sundials::make_klu_solver(y_.get(), jac_.get(), ctx_.get());
  mem_ = KINCreate(ctx_.get());
  if (!mem_) throw SolverError("KINCreate failed");
  check(KINInit(mem_, residual_trampoline, y_.get()), "KINInit");
  check(KINSetUserData(mem_, this), "KINSetUserData");
  check(KINSetLinearSolver(mem_, solver_.get(), jac_.get()), "KINSetLinearSolver");
  check(KINSetJacFn(mem_, jacobian_trampoline), "KINSetJacFn");
  check(KINSetMaxSetupCalls(mem_, 1), "KINSetMaxSetupCalls");  // exact Newton
  check(KINSetNumMaxIters(mem_, options_.max_iterations), "KINSetNumMaxIters");
  check(KINSetPrintLevel(mem_, 0), "KINSetPrintLevel");
}

KinsolSolver::~KinsolSolver() { KINFree(&mem_); }

NonlinearStats KinsolSolver::solve(Real t, std::span<Real> y) {
  t_ = t;
  auto yv = sundials::as_span(y_.get());
  std::copy(y.begin(), y.end(), yv.begin());

  // Scale F by its initial size so the tolerance is a relative reduction.
  auto f0 = sundials::as_span(scale_f_.get());
  op_.residual(t_, yv, sundials::as_span(zero_.get()), f0);
  NonlinearStats stats;
  Real f0_norm = 0;
  for (Real v : f0) f0_norm = std::max(f0_norm, std::abs(v));
  stats.initial_residual = f0_norm;
  stats.residual_evals = 1;
  const Real scale = options_.residual_scale > 0 ? options_.residual_scale : f0_norm;
  if (f0_norm == 0) return stats;
  N_VConst(1.0 / scale, scale_f_.get());
  N_VConst(1.0, scale_u_.get());
  check(KINSetFuncNormTol(mem_, options_.relative_tolerance), "KINSetFuncNormTol");
  check(KINSetScaledStepTol(mem_, 1e-300), "KINSetScaledStepTol");
  // From a zero initial guess KINSOL's default step bound (1000 |u0|_D) is tiny; lift it.
  Real max_step = options_.max_newton_step > 0 ? options_.max_newton_step : 1e300;
  check(KINSetMaxNewtonStep(mem_, max_step), "KINSetMaxNewtonStep");

  residual_calls_ = 0;
  int flag = KINSol(mem_, y_.get(), options_.line_search ? KIN_LINESEARCH : KIN_NONE,
                    scale_u_.get(), scale_f_.get());
  guard_.rethrow();
  if (flag < 0)
    throw SolverError(
        fmt::format("KINSOL failed with flag {} ({})", flag, KINGetReturnFlagName(flag)));
  long nni = 0, nje = 0, nli = 0;
  KINGetNumNonlinSolvIters(mem_, &nni);
  KINGetNumJacEvals(mem_, &nje);
  KINGetNumLinIters(mem_, &nli);
  stats.newton_iters = nni;
  stats.jacobian_evals = nje;
  stats.linear_iters = nli;
  stats.residual_evals += residual_calls_;
  // The unscaled infinity norm (KINGetFuncNorm reports a scaled 2-norm).
  op_.residual(t_, yv, sundials::as_span(zero_.get()), f0);
  stats.final_residual = 0;
  for (Real v : f0) stats.final_residual = std::max(stats.final_residual, std::abs(v));
  std::copy(yv.begin(), yv.end(), y.begin());
  return stats;
}

int KinsolSolver::residual_trampoline(N_Vector y, N_Vector f, void* self) {
  auto* me = static_cast<KinsolSolver*>(self);
  return me->guard_.run([&] {
    ++me->residual_calls_;
    me->op_.residual(me->t_, sundials::as_span(y), sundials::as_span(me->zero_.get()),
                     sundials::as_span(f));
  });
}

int KinsolSolver::jacobian_trampoline(N_Vector y, N_Vector, SUNMatrix J, void* self, N_Vector,
                                      N_Vector) {
  auto* me = static_cast<KinsolSolver*>(self);
  return me->guard_.run_or_stop([&] {
    const CsrPattern& pattern = me->op_.jacobian_pattern();
    sundials::load_pattern(pattern, J);
    std::span<Real> values(SUNSparseMatrix_Data(J), static_cast<std::size_t>(pattern.nnz()));
    std::fill(values.begin(), values.end(), 0.0);
    me->op_.jacobian(me->t_, 0.0, sundials::as_span(y), sundials::as_span(me->zero_.get()), values);
  });
}

}  // namespace rfmems

#include "solvers/kinsol_solver.hpp"

#include <fmt/format.h>
#include <kinsol/kinsol.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <cmath>
#include <limits>
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
  // Continuation reuses its factorisation's analysis and pivots, and a large system factorises
  // with UMFPACK; a small single solve keeps SUNDIALS' own KLU interface.
  solver_ = options_.keep_jacobian || n >= options_.umfpack_from
                ? sundials::make_sparse_direct_solver(
                      ctx_.get(), options_.ordering, counts_, options_.umfpack_from,
                      options_.umfpack_refinement_steps, options_.umfpack_ordering)
                : sundials::make_klu_solver(y_.get(), jac_.get(), ctx_.get());
  mem_ = KINCreate(ctx_.get());
  if (!mem_) throw SolverError("KINCreate failed");
  check(KINInit(mem_, residual_trampoline, y_.get()), "KINInit");
  check(KINSetUserData(mem_, this), "KINSetUserData");
  check(KINSetLinearSolver(mem_, solver_.get(), jac_.get()), "KINSetLinearSolver");
  check(KINSetJacFn(mem_, jacobian_trampoline), "KINSetJacFn");
  // Exact Newton, or the Jacobian kept for up to 10 iterations.
  check(KINSetMaxSetupCalls(mem_, options_.keep_jacobian ? 10 : 1), "KINSetMaxSetupCalls");
  check(KINSetPrintLevel(mem_, 0), "KINSetPrintLevel");
  // Failures reach the caller as flags and SolverError; KINSOL's own messages would also stop
  // the one-step first call of every solve (see solve()).
  check(KINSetErrHandlerFn(
            mem_, [](int, const char*, const char*, char*, void*) {}, nullptr),
        "KINSetErrHandlerFn");
}

KinsolSolver::~KinsolSolver() { KINFree(&mem_); }

NonlinearStats KinsolSolver::solve(Real t, std::span<Real> y) {
  t_ = t;
  auto yv = sundials::as_span(y_.get());
  std::copy(y.begin(), y.end(), yv.begin());

  // F scaled to a relative size: by its initial norm, or by the given scale(s).
  const auto zero = sundials::as_span(zero_.get());
  auto fscale = sundials::as_span(scale_f_.get());
  std::vector<Real> f0(y.size()), f(y.size());
  op_.residual(t_, yv, zero, f0);
  NonlinearStats stats;
  Real f0_norm = 0;
  for (Real v : f0) f0_norm = std::max(f0_norm, std::abs(v));
  stats.initial_residual = f0_norm;
  stats.residual_evals = 1;
  if (f0_norm == 0) return stats;
  if (!options_.residual_scales.empty()) {
    for (std::size_t i = 0; i < fscale.size(); ++i) fscale[i] = 1.0 / options_.residual_scales[i];
  } else {
    const Real scale = options_.residual_scale > 0 ? options_.residual_scale : f0_norm;
    std::fill(fscale.begin(), fscale.end(), 1.0 / scale);
  }
  N_VConst(1.0, scale_u_.get());
  check(KINSetScaledStepTol(mem_, 1e-300), "KINSetScaledStepTol");
  // From a zero initial guess KINSOL's default step bound (1000 |u0|_D) is tiny; lift it.
  Real max_step = options_.max_newton_step > 0 ? options_.max_newton_step : 1e300;
  check(KINSetMaxNewtonStep(mem_, max_step), "KINSetMaxNewtonStep");

  // With round_off_floor: one Newton step, then the tolerance raised to the round-off floor
  // where it lies below it.
  residual_calls_ = 0;
  const bool setup_first = !(options_.keep_jacobian && solved_once_);
  long iterations = 0, jacobians = 0, linear = 0;
  auto counted = [&](int flag) {  // KINSOL's counters restart with every KINSol call
    long v = 0;
    KINGetNumNonlinSolvIters(mem_, &v);
    iterations += v;
    KINGetNumJacEvals(mem_, &v);
    jacobians += v;
    KINGetNumLinIters(mem_, &v);
    linear += v;
    return flag;
  };
  Real tolerance = options_.relative_tolerance;
  const bool floor = options_.round_off_floor && options_.max_iterations > 1;
  int flag = counted(run_kinsol(floor ? 1 : options_.max_iterations, tolerance, setup_first));
  if (floor && flag == KIN_MAXITER_REACHED) {
    op_.residual(t_, yv, zero, f);
    ++stats.residual_evals;
    tolerance = std::max(tolerance, round_off_floor(yv));
    Real scaled = 0;
    for (std::size_t i = 0; i < f.size(); ++i)
      scaled = std::max(scaled, std::abs(f[i]) * fscale[i]);
    flag =
        scaled <= tolerance
            ? KIN_SUCCESS
            : counted(run_kinsol(options_.max_iterations - 1, tolerance, !options_.keep_jacobian));
  }
  guard_.rethrow();
  if (flag < 0)
    throw SolverError(
        fmt::format("KINSOL failed with flag {} ({})", flag, KINGetReturnFlagName(flag)));
  solved_once_ = true;
  stats.newton_iters = iterations;
  stats.jacobian_evals = jacobians;
  stats.linear_iters = linear;
  stats.residual_evals += residual_calls_;
  stats.fresh_factorizations = counts_->fresh_factorizations;
  stats.refactorizations = counts_->refactorizations;
  stats.factor_entries = counts_->factor_entries;
  stats.umfpack = counts_->umfpack;
  // The unscaled infinity norm (KINGetFuncNorm reports a scaled 2-norm).
  op_.residual(t_, yv, zero, f0);
  stats.final_residual = 0;
  for (Real v : f0) {
    // A diverged iteration (an overflow to inf or NaN) can end with KINSOL's test met, as NaN
    // compares false with every bound: it is a failure, not a solution.
    if (!std::isfinite(v))
      throw SolverError("KINSOL diverged: the residual at its last iterate is not finite");
    stats.final_residual = std::max(stats.final_residual, std::abs(v));
  }
  std::copy(yv.begin(), yv.end(), y.begin());
  return stats;
}

int KinsolSolver::run_kinsol(long max_iterations, Real tolerance, bool setup_first) {
  check(KINSetNumMaxIters(mem_, max_iterations), "KINSetNumMaxIters");
  check(KINSetFuncNormTol(mem_, tolerance), "KINSetFuncNormTol");
  check(KINSetNoInitSetup(mem_, setup_first ? SUNFALSE : SUNTRUE), "KINSetNoInitSetup");
  return KINSol(mem_, y_.get(), options_.line_search ? KIN_LINESEARCH : KIN_NONE, scale_u_.get(),
                scale_f_.get());
}

Real KinsolSolver::round_off_floor(std::span<const Real> y) const {
  const CsrPattern& pattern = op_.jacobian_pattern();
  const Real* values = SUNSparseMatrix_Data(jac_.get());
  const auto fscale = sundials::as_span(scale_f_.get());
  Real largest = 0;
  for (Index i = 0; i < pattern.n_rows(); ++i) {
    Real terms = 0;
    for (Index p = pattern.row_ptr[i]; p < pattern.row_ptr[i + 1]; ++p)
      terms += std::abs(values[p] * y[pattern.col_idx[p]]);
    largest = std::max(largest, terms * fscale[i]);
  }
  return round_off_floor_of(largest);
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

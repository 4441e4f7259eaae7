#include "solvers/distributed_static_solve.hpp"

#include <fmt/format.h>
#include <kinsol/kinsol.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <utility>

#include "core/error.hpp"
#include "parallel/distributed_structural_systems.hpp"
#include "solvers/callback_guard.hpp"
#include "solvers/distributed_linearization.hpp"
#include "solvers/parallel_vector.hpp"

namespace rfmems {

namespace {

void check(int flag, const char* call) {
  if (flag < 0) throw SolverError(fmt::format("KINSOL: {} failed with flag {}", call, flag));
}

struct Problem {
  DistributedStaticSystem system;
  DistributedLinearization linearization;
  Real t = 0;
  long residual_calls = 0;
  CallbackGuard guard;
  std::vector<Real> no_derivative;

  Problem(DistributedSecondOrderOperator& op, Real time, DistributedLinearization::Family family)
      : system(op),
        linearization(system, false, DistributedLinearization::best_for(system, false, family)),
        t(time),
        no_derivative(op.owned_size(), 0.0) {}
};

Problem& problem_of(void* data) { return *static_cast<Problem*>(data); }

int residual(N_Vector y, N_Vector f, void* data) {
  Problem& p = problem_of(data);
  return p.guard.run([&] {
    ++p.residual_calls;
    p.system.residual(p.t, sundials::local_span(y), p.no_derivative, sundials::local_span(f));
  });
}

int preconditioner_setup(N_Vector u, N_Vector, N_Vector, N_Vector, void* data) {
  Problem& p = problem_of(data);
  return p.guard.run(
      [&] { p.linearization.setup(p.t, 0.0, sundials::local_span(u), p.no_derivative); });
}

int preconditioner_solve(N_Vector, N_Vector, N_Vector, N_Vector, N_Vector v, void* data) {
  Problem& p = problem_of(data);
  return p.guard.run([&] {
    auto z = sundials::local_span(v);
    p.linearization.precondition(z, z);
  });
}

int jacobian_times(N_Vector v, N_Vector jv, N_Vector, booleantype* new_u, void* data) {
  Problem& p = problem_of(data);
  *new_u = SUNFALSE;  // the product uses the Jacobian of the last setup, at this u
  return p.guard.run(
      [&] { p.linearization.apply(0.0, sundials::local_span(v), sundials::local_span(jv)); });
}

Real global_max_abs(const Communicator& comm, std::span<const Real> x) {
  Real m = 0;
  for (Real v : x) m = std::max(m, std::abs(v));
  return comm.max(m);
}

}  // namespace

DistributedStaticSolution solve_static_distributed(DistributedSecondOrderOperator& op, Real t,
                                                   const DistributedNewtonOptions& options,
                                                   std::vector<Real> y0) {
  const Communicator& comm = op.communicator();
  const Index n = op.owned_size();
  Problem problem(op, t, options.preconditioner);
  DistributedStaticSolution solution;
  solution.y = y0.empty() ? std::vector<Real>(n, 0.0) : std::move(y0);

  sundials::Context ctx = sundials::make_context();
  sundials::Vector y = sundials::make_parallel_vector(comm, n, ctx.get());
  sundials::Vector scale_u = sundials::make_parallel_vector(comm, n, ctx.get());
  sundials::Vector scale_f = sundials::make_parallel_vector(comm, n, ctx.get());
  auto yv = sundials::local_span(y.get());
  std::copy(solution.y.begin(), solution.y.end(), yv.begin());

  // Scale F by its initial size so the tolerance is a relative reduction (as the serial solve).
  auto f0 = sundials::local_span(scale_f.get());
  problem.system.residual(t, yv, problem.no_derivative, f0);
  NonlinearStats& stats = solution.stats;
  stats.initial_residual = global_max_abs(comm, f0);
  stats.residual_evals = 1;
  if (stats.initial_residual == 0) return solution;
  N_VConst(1.0 / stats.initial_residual, scale_f.get());
  N_VConst(1.0, scale_u.get());

  // Classical Gram-Schmidt's dot products fused (one pass, one reduction) on the vectors SPGMR
  // clones from y; without them N_VDotProdMulti loops.
  if (options.classical_gram_schmidt) sundials::enable_fused_operations(y.get());
  sundials::LinearSolver gmres(
      SUNLinSol_SPGMR(y.get(), SUN_PREC_RIGHT, options.krylov_dimension, ctx.get()));
  if (!gmres) throw SolverError("SUNLinSol_SPGMR failed");
  SUNLinSol_SPGMRSetGSType(gmres.get(),
                           options.classical_gram_schmidt ? SUN_CLASSICAL_GS : SUN_MODIFIED_GS);

  void* mem = KINCreate(ctx.get());
  if (!mem) throw SolverError("KINCreate failed");
  struct Free {
    void* mem;
    ~Free() { KINFree(&mem); }
  } free_mem{mem};
  check(KINInit(mem, residual, y.get()), "KINInit");
  check(KINSetUserData(mem, &problem), "KINSetUserData");
  check(KINSetLinearSolver(mem, gmres.get(), nullptr), "KINSetLinearSolver");
  check(KINSetPreconditioner(mem, preconditioner_setup, preconditioner_solve),
        "KINSetPreconditioner");
  check(KINSetJacTimesVecFn(mem, jacobian_times), "KINSetJacTimesVecFn");
  check(KINSetMaxSetupCalls(mem, 1), "KINSetMaxSetupCalls");  // exact Newton
  check(KINSetEtaForm(mem, KIN_ETACONSTANT), "KINSetEtaForm");
  check(KINSetPrintLevel(mem, 0), "KINSetPrintLevel");
  // Failures reach the caller as flags and SolverError; KINSOL's own messages would also stop
  // the one-step first call of a solve with round_off_floor.
  check(KINSetErrHandlerFn(
            mem, [](int, const char*, const char*, char*, void*) {}, nullptr),
        "KINSetErrHandlerFn");
  check(KINSetScaledStepTol(mem, 1e-300), "KINSetScaledStepTol");
  check(KINSetMaxNewtonStep(mem, 1e300), "KINSetMaxNewtonStep");  // see KinsolSolver::solve

  long iterations = 0, linear = 0;
  auto run = [&](long max_iterations, Real tolerance, Real forcing, int max_restarts) {
    check(SUNLinSol_SPGMRSetMaxRestarts(gmres.get(), max_restarts), "SPGMRSetMaxRestarts");
    check(KINSetNumMaxIters(mem, max_iterations), "KINSetNumMaxIters");
    check(KINSetFuncNormTol(mem, tolerance), "KINSetFuncNormTol");
    check(KINSetEtaConstValue(mem, forcing), "KINSetEtaConstValue");
    const int flag = KINSol(mem, y.get(), KIN_NONE, scale_u.get(), scale_f.get());
    long v = 0;  // KINSOL's counters restart with every KINSol call
    KINGetNumNonlinSolvIters(mem, &v);
    iterations += v;
    KINGetNumLinIters(mem, &v);
    linear += v;
    return flag;
  };
  // With round_off_floor, as KinsolSolver::solve: one Newton step, then the tolerance raised to
  // the residual's round-off floor there; the later Krylov solves reduce the residual to a
  // tenth of that tolerance, not by linear_tolerance again, which the floor may forbid. The
  // first step's GMRES, whose target may lie beneath the floor it cannot yet know, gets two
  // cycles at most (KINSOL takes a reduced residual as a first step): GMRES stagnates at the
  // floor, and its restarts would gain nothing there.
  Real tolerance = options.relative_tolerance;
  const bool floor = options.round_off_floor && options.max_iterations > 1;
  int flag = run(floor ? 1 : options.max_iterations, tolerance, options.linear_tolerance,
                 floor ? std::min(options.max_restarts, 1) : options.max_restarts);
  problem.guard.rethrow();
  if (floor && flag == KIN_MAXITER_REACHED) {
    std::vector<Real> f(n), terms(n);
    problem.system.residual(t, yv, problem.no_derivative, f);
    ++stats.residual_evals;
    problem.linearization.absolute_product(yv, terms);
    const Real scale = 1.0 / stats.initial_residual;
    tolerance = std::max(tolerance, round_off_floor_of(global_max_abs(comm, terms) * scale));
    const Real scaled = global_max_abs(comm, f) * scale;
    flag = scaled <= tolerance
               ? KIN_SUCCESS
               : run(options.max_iterations - 1, tolerance,
                     std::clamp(0.1 * tolerance / scaled, options.linear_tolerance, 0.1),
                     options.max_restarts);
  }
  problem.guard.rethrow();
  if (flag < 0)
    throw SolverError(fmt::format("KINSOL (distributed) failed with flag {} ({})", flag,
                                  KINGetReturnFlagName(flag)));
  stats.newton_iters = iterations;
  stats.jacobian_evals = problem.linearization.setups();
  stats.linear_iters = linear;
  stats.residual_evals += problem.residual_calls;
  solution.multigrid = problem.linearization.multigrid_stats();
  problem.system.residual(t, yv, problem.no_derivative, f0);
  stats.final_residual = global_max_abs(comm, f0);
  std::copy(yv.begin(), yv.end(), solution.y.begin());
  return solution;
}

}  // namespace rfmems

// Static (steady) solves of a SystemOperator, F(t, y, 0) = 0, with SUNDIALS KINSOL: Newton's
// method with an exact Jacobian (rebuilt every iteration, or kept while Newton converges) and
// optional line search. The linear solves: SUNDIALS' KLU for a small system solved once; the
// sparse direct solver that refactorises on the pattern's one symbolic analysis (KLU, or
// UMFPACK from kUmfpackFrom unknowns: solvers/sparse_direct_solver.hpp) for continuation and
// for large systems.
//
// The stopping test is scaled to the problem: ||F||_inf <= relative_tolerance x the residual
// scale (||F(y0)||_inf, or residual_scale), and with round_off_floor never below the residual's
// round-off floor
// c eps max_i (|J| |y|)_i: the size of the terms that cancel in F, times the unit round-off
// (the componentwise backward error of an LU solve: Higham, Accuracy and Stability of
// Numerical Algorithms). Without the floor a linear problem whose terms cancel by a
// factor (a/h)^2 (a thin plate's shear against its load) cannot meet a relative reduction of
// 1e-6 and Newton iterates on round-off; with it, it stops after its one exact step.
#pragma once
#include <exception>
#include <limits>
#include <memory>

#include "core/system_operator.hpp"
#include "solvers/callback_guard.hpp"
#include "solvers/sparse_direct_solver.hpp"
#include "solvers/sundials_handles.hpp"

namespace rfmems {

// The residual's round-off floor from the largest row of |J| |y| (scaled like F): c eps times
// it, c = 10 a margin over the LU solve's backward error (a small multiple of eps per row
// entry) and the residual's own summation; the plates of a/h = 5 to 1e5 stop after one step
// with it.
inline Real round_off_floor_of(Real largest_terms) {
  return 10 * std::numeric_limits<Real>::epsilon() * largest_terms;
}

struct KinsolOptions {
  // Converged when ||F||_inf <= relative_tolerance * ||F(y0)||_inf (scaled by KINSOL's fscale).
  // The default sits above the round-off floor of one direct solve on slender structures
  // (~5e-7 measured on a 160 x 16 beam at L/h = 50).
  Real relative_tolerance = 1e-6;
  int max_iterations = 50;
  bool line_search = false;
  Real max_newton_step = 0;  // 0: KINSOL's default scaled by the problem (see solve())
  // > 0: the tolerance is relative to this residual scale instead of ||F(y0)||_inf (for
  // continuation, where a good predictor makes F(y0) tiny and a reduction of it meaningless).
  Real residual_scale = 0;
  // > 0: per-component residual scales instead (the rows of F differ in units or size).
  std::vector<Real> residual_scales;
  // Keep the Jacobian (and its factors) across iterations and across solve() calls while
  // Newton converges: KINSOL re-evaluates it after 10 iterations, when the line search or the
  // step test fails with a stale one (modified Newton; for continuation, where successive
  // states are close).
  bool keep_jacobian = false;
  // Stop at the residual's round-off floor where the tolerance lies below it (see above): one
  // Newton step first, then the tolerance raised to the floor measured there. Off, KINSOL's
  // own test alone (as penalty-contact solves need, whose floor is set by the penalty).
  bool round_off_floor = false;
  KluOrdering ordering = KluOrdering::BySize;  // of the sparse direct solver's KLU
  // The size from which the factorisation is UMFPACK's (solvers/umfpack_factorization.hpp),
  // in this ordering, with this many steps of iterative refinement per solve (see
  // solvers/sparse_direct_solver.hpp's kRefinementSteps).
  Index umfpack_from = kUmfpackFrom;
  UmfpackOrdering umfpack_ordering = UmfpackOrdering::Metis;
  int umfpack_refinement_steps = sundials::kRefinementSteps;
};

struct NonlinearStats {
  long newton_iters = 0, residual_evals = 0, jacobian_evals = 0, linear_iters = 0;
  // The sparse direct solver (keep_jacobian, or umfpack_from unknowns and more): factorisations
  // with fresh pivoting (UMFPACK: with a fresh symbolic analysis) and refactorisations, over the
  // solver's life (cumulative); entries of L + U; whether UMFPACK factorised.
  long fresh_factorizations = 0, refactorizations = 0, factor_entries = 0;
  bool umfpack = false;
  Real initial_residual = 0, final_residual = 0;
};

class KinsolSolver {
 public:
  KinsolSolver(SystemOperator& op, const KinsolOptions& options);
  ~KinsolSolver();
  KinsolSolver(const KinsolSolver&) = delete;
  KinsolSolver& operator=(const KinsolSolver&) = delete;

  // The options, which a caller may change between solves (tolerance, residual scales).
  KinsolOptions& options() { return options_; }

  // Solves F(t, y, 0) = 0 starting from y (overwritten with the solution).
  NonlinearStats solve(Real t, std::span<Real> y);

 private:
  // KINSol with this iteration cap and function-norm tolerance; returns its flag.
  int run_kinsol(long max_iterations, Real tolerance, bool setup_first);
  // c eps max_i (|J| |y|)_i with the Jacobian of the last setup, scaled like F.
  Real round_off_floor(std::span<const Real> y) const;
  static int residual_trampoline(N_Vector y, N_Vector f, void* self);
  static int jacobian_trampoline(N_Vector y, N_Vector f, SUNMatrix J, void* self, N_Vector,
                                 N_Vector);

  SystemOperator& op_;
  KinsolOptions options_;
  sundials::Context ctx_;
  sundials::Vector y_, scale_u_, scale_f_, zero_;
  sundials::Matrix jac_;
  sundials::LinearSolver solver_;
  std::shared_ptr<sundials::DirectCounts> counts_ = std::make_shared<sundials::DirectCounts>();
  bool solved_once_ = false;
  void* mem_ = nullptr;
  Real t_ = 0;
  long residual_calls_ = 0;
  CallbackGuard guard_;
};

}  // namespace rfmems

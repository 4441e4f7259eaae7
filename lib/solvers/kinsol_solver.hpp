// Static (steady) solves of a SystemOperator, F(t, y, 0) = 0, with SUNDIALS KINSOL: Newton's
// method with an exact Jacobian (rebuilt every iteration), KLU, and optional line search.
#pragma once
#include <exception>

#include "core/system_operator.hpp"
#include "solvers/callback_guard.hpp"
#include "solvers/sundials_handles.hpp"

namespace rfmems {

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
};

struct NonlinearStats {
  long newton_iters = 0, residual_evals = 0, jacobian_evals = 0, linear_iters = 0;
  Real initial_residual = 0, final_residual = 0;
};

class KinsolSolver {
 public:
  KinsolSolver(SystemOperator& op, const KinsolOptions& options);
  ~KinsolSolver();
  KinsolSolver(const KinsolSolver&) = delete;
  KinsolSolver& operator=(const KinsolSolver&) = delete;

  // Solves F(t, y, 0) = 0 starting from y (overwritten with the solution).
  NonlinearStats solve(Real t, std::span<Real> y);

 private:
  static int residual_trampoline(N_Vector y, N_Vector f, void* self);
  static int jacobian_trampoline(N_Vector y, N_Vector f, SUNMatrix J, void* self, N_Vector,
                                 N_Vector);

  SystemOperator& op_;
  KinsolOptions options_;
  sundials::Context ctx_;
  sundials::Vector y_, scale_u_, scale_f_, zero_;
  sundials::Matrix jac_;
  sundials::LinearSolver solver_;
  void* mem_ = nullptr;
  Real t_ = 0;
  long residual_calls_ = 0;
  CallbackGuard guard_;
};

}  // namespace rfmems

// Transient integration of a SystemOperator with SUNDIALS IDA (variable-order, variable-step
// BDF) and a sparse direct linear solver (KLU, or UMFPACK on large systems) or preconditioned
// GMRES, with optional root functions for events.
#pragma once
#include <exception>
#include <functional>
#include <memory>
#include <vector>

#include "core/system_operator.hpp"
#include "solvers/callback_guard.hpp"
#include "solvers/jacobian_lu_preconditioner.hpp"
#include "solvers/sparse_direct_solver.hpp"
#include "solvers/sundials_handles.hpp"

namespace rfmems {

struct IdaOptions {
  // Direct: sparse LU Newton solves, SUNDIALS' KLU below umfpack_from unknowns and UMFPACK
  // (solvers/sparse_direct_solver.hpp: METIS ordering, dense fronts through BLAS, refactorised
  // on one symbolic analysis) from there on, where KLU's fill on a 3D mesh makes each
  // factorisation slow. Spgmr: GMRES preconditioned by the operator's own preconditioner, or
  // by an LU factorisation of its Jacobian lagged between setups.
  enum class LinearSolver { Direct, Spgmr };
  LinearSolver linear_solver = LinearSolver::Direct;
  // Higher than KINSOL's kUmfpackFrom: IDA solves many times per factorisation, and KLU's
  // solves on AMD's ordering are the cheaper ones below this size. Measured on creep runs
  // (bench_creep_plate_vs_continuum): plane stress 481 x 12 (34,632 unknowns) KLU 16.5 s against
  // UMFPACK 21.4 s; 3D 121 x 8 x 3 (29,040) equal, 30 s; 3D 241 x 8 x 4 (77,120) UMFPACK
  // 171 s for 1 h of creep, where KLU had not finished 500 h after 10 minutes at 1.4 GB.
  Index umfpack_from = 50000;
  int krylov_dimension = 30;
  // IDA's eps_lin (IDASetEpsLin): a Krylov solve stops at ||P^-1 r||_WRMS <= factor x the
  // Newton tolerance (0.33). The error of the correction, (P^-1 J)^-1 P^-1 r, is that times up
  // to ||(P^-1 J)^-1||, which a preconditioner dropping strong couplings makes large; the
  // error lands in the step's solution and its error estimate (docs/mpi.md, "Krylov tolerance").
  // 0: the integrator's default: SUNDIALS' 0.05 in IdaIntegrator (its Spgmr preconditioner
  // an LU of the Jacobian or the operator's own), DistributedLinearization::
  // krylov_tolerance_factor() in DistributedIdaIntegrator.
  Real krylov_tolerance_factor = 0;
  Real rtol = 1e-6;
  Real atol = 1e-12;
  // Per-component absolute tolerances (IDASVtolerances); empty: the scalar atol on every
  // component. Unknowns of different units (a displacement in m, a velocity in m/s, a
  // pressure in Pa) need their own scales for the local error test to weigh them alike.
  std::vector<Real> atols;
  // Leave the algebraic components (IDASetId 0) out of the local error test
  // (IDASetSuppressAlg): for unknowns fixed by the differential ones (quasi-static rotations).
  bool suppress_algebraic = false;
  int max_order = 5;
  Real initial_step = 0;  // 0: IDA chooses
  Real max_step = 0;      // 0: no limit
  // Newton and step control of the adaptive mode (SUNDIALS IDA optional inputs; 0: IDA's
  // default, shown in brackets). Newton stops when its estimated error, rate/(1-rate) x the
  // last correction, is below nonlinear_convergence x the local error test's 1
  // (IDASetNonlinConvCoef [0.33]); it gives up after max_newton_iterations
  // (IDASetMaxNonlinIters [4]) and the step after max_convergence_failures
  // (IDASetMaxConvFails [10]). The Jacobian is refreshed when c_j = alpha/h changes by more
  // than jacobian_cj_change (IDASetDeltaCjLSetup [0.25]). After a step, IDA keeps h unless the
  // error estimate allows growth by step_growth_threshold (IDASetEtaFixedStepBounds [2]); it
  // then grows by at most max_step_growth (IDASetEtaMax [2]). A failed Newton solve cuts h by
  // convergence_failure_cut (IDASetEtaConvFail [0.25]).
  Real nonlinear_convergence = 0;
  int max_newton_iterations = 0;
  int max_convergence_failures = 0;
  Real jacobian_cj_change = 0;
  Real step_growth_threshold = 0;
  Real max_step_growth = 0;
  Real convergence_failure_cut = 0;
  // Fixed-step mode (baselines and studies): every step has this size and the error test
  // never rejects it; with max_order 1 or 2 this is backward Euler or BDF2.
  Real fixed_step = 0;
  // With fixed_step: let IDA cut the step down to this after a failed Newton solve (0: no
  // cuts, the step is exactly fixed_step), growing back to fixed_step afterwards; the error
  // test still never rejects. A fixed-step competitor that survives the 1/g^2 touch-down.
  Real fixed_step_min = 0;
  long max_steps = 100000;
};

// `ida` with rtol and the absolute tolerances (scalar and per component) times `factor`: the
// same run at tighter (factor < 1) tolerances, whose answer beside the first estimates the
// first's integration error (IDA's global error is roughly proportional to its tolerances).
IdaOptions with_tolerances_scaled(IdaOptions ida, Real factor);

struct IntegratorStats {
  long steps = 0, residual_evals = 0, jacobian_evals = 0, newton_iters = 0, linear_setups = 0;
  long linear_iters = 0, preconditioner_setups = 0;
  long error_test_fails = 0, newton_fails = 0;
  // Krylov solves that stopped short of IDA's linear tolerance (IDAGetNumLinConvFails); 0 with
  // KLU.
  long linear_conv_fails = 0;
  bool umfpack = false;  // the direct solver factorised with UMFPACK (IdaOptions::umfpack_from)
  int last_order = 0;
  Real last_step = 0;
};

// The counters of one IDA memory block (IDAGetNum*; residual evaluations include the linear
// solver's): what IdaIntegrator and DistributedIdaIntegrator report.
IntegratorStats ida_memory_stats(void* ida_mem);

// g_i(t, y, y') whose sign changes mark events.
using RootFunction = std::function<void(Real t, std::span<const Real> y, std::span<const Real> yp,
                                        std::span<Real> g)>;

class IdaIntegrator {
 public:
  IdaIntegrator(SystemOperator& op, const IdaOptions& options);
  ~IdaIntegrator();
  IdaIntegrator(const IdaIntegrator&) = delete;
  IdaIntegrator& operator=(const IdaIntegrator&) = delete;

  // Sets the initial state (y' consistent with F(t0, y0, y0') = 0 is the caller's job).
  void initialize(Real t0, std::span<const Real> y0, std::span<const Real> yp0);
  // Restarts from a new state (IDAReInit: order 1, history dropped; the linear solver, the
  // options and the roots are kept). For partitioned schemes that redo or restart a step.
  void reinitialize(Real t0, std::span<const Real> y0, std::span<const Real> yp0);
  // Makes the algebraic components of y and all of y' consistent (F(t0, y, y') = 0) with
  // the differential components of y held, by IDACalcIC (IDA_YA_YDP_INIT), aiming at the
  // first output time t_first (> t0). For DAEs whose algebraic part (quasi-static rotations,
  // a film pressure at steady state) does not balance the initial load.
  void correct_initial_conditions(Real t_first);
  void set_roots(int n_roots, RootFunction g);

  enum class Status { Reached, Root, Stepped };  // Stepped: step() only
  // Advances to t_out (or to an event before it); returns where it stopped.
  Status advance(Real t_out);
  // One internal step (IDA_ONE_STEP), never beyond t_stop (IDASetStopTime): for partitioned
  // schemes that refresh a lagged load after every step IDA accepts. Reached means t_stop.
  Status step(Real t_stop);
  Real time() const { return t_; }
  // The state at t within the last step taken (IDAGetSolution: IDA's interpolating polynomial,
  // what its normal mode returns at an output time).
  void state_at(Real t, std::vector<Real>& y, std::vector<Real>& yp) const;
  std::span<const Real> y() const;
  std::span<const Real> yp() const;
  // Which roots fired at the last Root return (+1 rising, -1 falling, 0 none).
  std::vector<int> roots_found() const;
  IntegratorStats stats() const;
  // Saves IDA's whole step state (BDF history, step size and order, stop time, root-finding
  // state, our y / y') and restores it, so that a partitioned scheme can redo the step(s)
  // taken since the save with a corrected load as if they had not been taken (strong coupling
  // per step), keeping the variable-order history that IDAReInit would drop. One checkpoint;
  // the step count is restored too (work counters are not). Uses IDA's private memory layout
  // (ida_impl.h, SUNDIALS 6.4).
  void save_checkpoint();
  void restore_checkpoint();
  // IDA's internal time t_n and y(t_n) (its phi[0]): past time() after a root return, where
  // y() is interpolated back to the root.
  Real internal_time() const;
  std::span<const Real> internal_y() const;

 private:
  struct Checkpoint;
  std::unique_ptr<Checkpoint> checkpoint_;
  static int residual_trampoline(Real t, N_Vector y, N_Vector yp, N_Vector r, void* self);
  static int jacobian_trampoline(Real t, Real c_j, N_Vector y, N_Vector yp, N_Vector r, SUNMatrix J,
                                 void* self, N_Vector, N_Vector, N_Vector);
  static int root_trampoline(Real t, N_Vector y, N_Vector yp, Real* g, void* self);
  static int preconditioner_setup_trampoline(Real t, N_Vector y, N_Vector yp, N_Vector r, Real c_j,
                                             void* self);
  static int preconditioner_solve_trampoline(Real t, N_Vector y, N_Vector yp, N_Vector r,
                                             N_Vector rv, N_Vector zv, Real c_j, Real delta,
                                             void* self);

  SystemOperator& op_;
  IdaOptions options_;
  sundials::Context ctx_;
  sundials::Vector y_, yp_;
  sundials::Matrix jac_;
  sundials::LinearSolver solver_;
  void* mem_ = nullptr;
  Real t_ = 0;
  bool initialized_ = false;
  int n_roots_ = 0;
  RootFunction roots_;
  CallbackGuard guard_;
  std::unique_ptr<JacobianLuPreconditioner> fallback_preconditioner_;
  std::shared_ptr<sundials::DirectCounts> direct_counts_;  // with UMFPACK only
};

}  // namespace rfmems

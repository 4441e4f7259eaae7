#include "solvers/ida_integrator.hpp"

#include <algorithm>
#include <utility>
#include <fmt/format.h>
#include <ida/ida.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include "core/error.hpp"

namespace rfmems {

namespace {
void check(int flag, const char* call) {
  if (flag < 0) throw SolverError(fmt::format("IDA: {} failed with flag {}", call, flag));
}
}  // namespace

// Runs a callback body, mapping RecoverableError to SUNDIALS' "retry" (> 0) and storing any
// other exception to rethrow once IDA has returned.
template <class F>
int IdaIntegrator::guarded(F&& body) {
  try {
    body();
    return 0;
  } catch (const RecoverableError&) {
    return 1;
  } catch (...) {
    pending_ = std::current_exception();
    return -1;
  }
}

IdaIntegrator::IdaIntegrator(SystemOperator& op, const IdaOptions& options)
    : op_(op), options_(options), ctx_(sundials::make_context()) {
  const Index n = op_.size();
  y_ = sundials::make_serial_vector(n, ctx_.get());
  yp_ = sundials::make_serial_vector(n, ctx_.get());
  if (options_.linear_solver == IdaOptions::LinearSolver::Klu) {
    jac_ = sundials::make_csr_matrix(op_.jacobian_pattern(), ctx_.get());
    solver_ = sundials::make_klu_solver(y_.get(), jac_.get(), ctx_.get());
  } else {
    solver_ = sundials::LinearSolver(
        SUNLinSol_SPGMR(y_.get(), SUN_PREC_LEFT, options_.krylov_dimension, ctx_.get()));
    if (!op_.has_preconditioner())
      fallback_preconditioner_ = std::make_unique<JacobianLuPreconditioner>(op_);
  }
  if (!solver_) throw SolverError("creating the IDA linear solver failed");
  mem_ = IDACreate(ctx_.get());
  if (!mem_) throw SolverError("IDACreate failed");
}

IdaIntegrator::~IdaIntegrator() { IDAFree(&mem_); }

void IdaIntegrator::initialize(Real t0, std::span<const Real> y0, std::span<const Real> yp0) {
  std::copy(y0.begin(), y0.end(), sundials::as_span(y_.get()).begin());
  std::copy(yp0.begin(), yp0.end(), sundials::as_span(yp_.get()).begin());
  t_ = t0;
  check(IDAInit(mem_, residual_trampoline, t0, y_.get(), yp_.get()), "IDAInit");
  check(IDASetUserData(mem_, this), "IDASetUserData");
  const bool fixed = options_.fixed_step > 0;
  // In fixed-step mode the local error test is made vacuous by huge tolerances.
  if (!fixed && !options_.atol_vector.empty()) {
    if (static_cast<Index>(options_.atol_vector.size()) != op_.size())
      throw std::invalid_argument("IdaOptions::atol_vector: one entry per unknown");
    sundials::Vector atol = sundials::make_serial_vector(op_.size(), ctx_.get());
    std::copy(options_.atol_vector.begin(), options_.atol_vector.end(),
              sundials::as_span(atol.get()).begin());
    check(IDASVtolerances(mem_, options_.rtol, atol.get()), "IDASVtolerances");
  } else {
    check(IDASStolerances(mem_, fixed ? 1e10 : options_.rtol, fixed ? 1e10 : options_.atol),
          "IDASStolerances");
  }
  check(IDASetLinearSolver(mem_, solver_.get(), jac_.get()), "IDASetLinearSolver");
  if (jac_) {
    check(IDASetJacFn(mem_, jacobian_trampoline), "IDASetJacFn");
  } else {
    check(IDASetPreconditioner(mem_, preconditioner_setup_trampoline,
                               preconditioner_solve_trampoline),
          "IDASetPreconditioner");
  }
  check(IDASetMaxOrd(mem_, options_.max_order), "IDASetMaxOrd");
  check(IDASetMaxNumSteps(mem_, options_.max_steps), "IDASetMaxNumSteps");
  auto id = sundials::make_serial_vector(op_.size(), ctx_.get());
  auto components = op_.differential_components();
  std::copy(components.begin(), components.end(), sundials::as_span(id.get()).begin());
  check(IDASetId(mem_, id.get()), "IDASetId");
  if (fixed) {
    check(IDASetInitStep(mem_, options_.fixed_step), "IDASetInitStep");
    check(IDASetMaxStep(mem_, options_.fixed_step), "IDASetMaxStep");
    check(IDASetMinStep(mem_, options_.fixed_step), "IDASetMinStep");
    // Newton on a linear system converges in one iteration; make it exact.
    check(IDASetNonlinConvCoef(mem_, 1e-10), "IDASetNonlinConvCoef");
  } else {
    if (options_.initial_step > 0) check(IDASetInitStep(mem_, options_.initial_step), "IDASetInitStep");
    if (options_.max_step > 0) check(IDASetMaxStep(mem_, options_.max_step), "IDASetMaxStep");
  }
  if (n_roots_ > 0) check(IDARootInit(mem_, n_roots_, root_trampoline), "IDARootInit");
  initialized_ = true;
}

void IdaIntegrator::reinitialize(Real t0, std::span<const Real> y0, std::span<const Real> yp0) {
  if (!initialized_) {
    initialize(t0, y0, yp0);
    return;
  }
  std::copy(y0.begin(), y0.end(), sundials::as_span(y_.get()).begin());
  std::copy(yp0.begin(), yp0.end(), sundials::as_span(yp_.get()).begin());
  t_ = t0;
  check(IDAReInit(mem_, t0, y_.get(), yp_.get()), "IDAReInit");
}

void IdaIntegrator::correct_initial_conditions(Real t_first) {
  check(IDACalcIC(mem_, IDA_YA_YDP_INIT, t_first), "IDACalcIC");
  if (pending_) std::rethrow_exception(std::exchange(pending_, nullptr));
  check(IDAGetConsistentIC(mem_, y_.get(), yp_.get()), "IDAGetConsistentIC");
}

void IdaIntegrator::set_roots(int n_roots, RootFunction g) {
  n_roots_ = n_roots;
  roots_ = std::move(g);
  if (initialized_) check(IDARootInit(mem_, n_roots_, root_trampoline), "IDARootInit");
}

IdaIntegrator::Status IdaIntegrator::advance(Real t_out) {
  Real t_ret = t_;
  int flag = IDASolve(mem_, t_out, &t_ret, y_.get(), yp_.get(), IDA_NORMAL);
  t_ = t_ret;
  if (pending_) std::rethrow_exception(std::exchange(pending_, nullptr));
  if (flag < 0)
    throw SolverError(fmt::format("IDA failed at t = {:.6g} with flag {} ({})", t_ret, flag,
                                  IDAGetReturnFlagName(flag)));
  return flag == IDA_ROOT_RETURN ? Status::Root : Status::Reached;
}

IdaIntegrator::Status IdaIntegrator::step(Real t_stop) {
  check(IDASetStopTime(mem_, t_stop), "IDASetStopTime");
  Real t_ret = t_;
  const int flag = IDASolve(mem_, t_stop, &t_ret, y_.get(), yp_.get(), IDA_ONE_STEP);
  t_ = t_ret;
  if (pending_) std::rethrow_exception(std::exchange(pending_, nullptr));
  if (flag < 0)
    throw SolverError(fmt::format("IDA failed at t = {:.6g} with flag {} ({})", t_ret, flag,
                                  IDAGetReturnFlagName(flag)));
  if (flag == IDA_ROOT_RETURN) return Status::Root;
  return flag == IDA_TSTOP_RETURN ? Status::Reached : Status::Stepped;
}

std::span<const Real> IdaIntegrator::y() const { return sundials::as_span(y_.get()); }
std::span<const Real> IdaIntegrator::yp() const { return sundials::as_span(yp_.get()); }

std::vector<int> IdaIntegrator::roots_found() const {
  std::vector<int> found(n_roots_, 0);
  if (n_roots_ > 0) IDAGetRootInfo(mem_, found.data());
  return found;
}

IntegratorStats IdaIntegrator::stats() const {
  IntegratorStats s;
  long nrevals_ls = 0;
  IDAGetNumSteps(mem_, &s.steps);
  IDAGetNumResEvals(mem_, &s.residual_evals);
  IDAGetNumLinResEvals(mem_, &nrevals_ls);
  s.residual_evals += nrevals_ls;
  IDAGetNumJacEvals(mem_, &s.jacobian_evals);
  IDAGetNumNonlinSolvIters(mem_, &s.newton_iters);
  IDAGetNumLinSolvSetups(mem_, &s.linear_setups);
  IDAGetNumErrTestFails(mem_, &s.error_test_fails);
  IDAGetNumNonlinSolvConvFails(mem_, &s.newton_fails);
  IDAGetLastOrder(mem_, &s.last_order);
  IDAGetLastStep(mem_, &s.last_step);
  IDAGetNumLinIters(mem_, &s.linear_iters);
  IDAGetNumPrecEvals(mem_, &s.preconditioner_setups);
  return s;
}

int IdaIntegrator::residual_trampoline(Real t, N_Vector y, N_Vector yp, N_Vector r, void* self) {
  auto* me = static_cast<IdaIntegrator*>(self);
  return me->guarded([&] {
    me->op_.residual(t, sundials::as_span(y), sundials::as_span(yp), sundials::as_span(r));
  });
}

int IdaIntegrator::jacobian_trampoline(Real t, Real c_j, N_Vector y, N_Vector yp, N_Vector,
                                       SUNMatrix J, void* self, N_Vector, N_Vector, N_Vector) {
  auto* me = static_cast<IdaIntegrator*>(self);
  return me->guarded([&] {
    const CsrPattern& pattern = me->op_.jacobian_pattern();
    sundials::load_pattern(pattern, J);
    std::span<Real> values(SUNSparseMatrix_Data(J), static_cast<std::size_t>(pattern.nnz()));
    std::fill(values.begin(), values.end(), 0.0);
    me->op_.jacobian(t, c_j, sundials::as_span(y), sundials::as_span(yp), values);
  });
}

int IdaIntegrator::root_trampoline(Real t, N_Vector y, N_Vector yp, Real* g, void* self) {
  auto* me = static_cast<IdaIntegrator*>(self);
  return me->guarded([&] {
    me->roots_(t, sundials::as_span(y), sundials::as_span(yp),
               std::span<Real>(g, static_cast<std::size_t>(me->n_roots_)));
  });
}

int IdaIntegrator::preconditioner_setup_trampoline(Real t, N_Vector y, N_Vector yp, N_Vector,
                                                   Real c_j, void* self) {
  auto* me = static_cast<IdaIntegrator*>(self);
  return me->guarded([&] {
    if (me->fallback_preconditioner_)
      me->fallback_preconditioner_->setup(t, c_j, sundials::as_span(y), sundials::as_span(yp));
    else
      me->op_.preconditioner_setup(t, c_j, sundials::as_span(y), sundials::as_span(yp));
  });
}

int IdaIntegrator::preconditioner_solve_trampoline(Real, N_Vector, N_Vector, N_Vector,
                                                   N_Vector rv, N_Vector zv, Real, Real,
                                                   void* self) {
  auto* me = static_cast<IdaIntegrator*>(self);
  return me->guarded([&] {
    if (me->fallback_preconditioner_)
      me->fallback_preconditioner_->solve(sundials::as_span(rv), sundials::as_span(zv));
    else
      me->op_.preconditioner_solve(sundials::as_span(rv), sundials::as_span(zv));
  });
}

}  // namespace rfmems

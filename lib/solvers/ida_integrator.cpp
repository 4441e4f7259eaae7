#include "solvers/ida_integrator.hpp"

#include <fmt/format.h>
#include <ida/ida.h>
#include <ida/ida_impl.h>
#include <sundials/sundials_config.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <string>
#include <utility>

#include "core/error.hpp"

// save_checkpoint/restore_checkpoint copy IDA's private step history (ida_impl.h), whose
// layout is SUNDIALS 6.4's; another version must be checked field by field before it builds.
static_assert(SUNDIALS_VERSION_MAJOR == 6 && SUNDIALS_VERSION_MINOR == 4,
              "IdaIntegrator's checkpoint reads ida_impl.h of SUNDIALS 6.4: check its IDAMem");

// IDA's normal mode interpolates y and y' at an output time with this function (ida.c); the
// library exports it without declaring it in a header.
extern "C" int IDAGetSolution(void* ida_mem, realtype t, N_Vector yret, N_Vector ypret);

namespace rfmems {

IdaOptions with_tolerances_scaled(IdaOptions ida, Real factor) {
  ida.rtol *= factor;
  ida.atol *= factor;
  for (Real& a : ida.atols) a *= factor;
  return ida;
}

namespace {

// IDA's own messages: kept (the last one, per thread) for the SolverError that a failure
// becomes, instead of IDA printing "[IDA ERROR] ..." on stderr. A failure the caller expects and
// handles (a step the model refuses at the end of a creep life, a root) then prints nothing.
thread_local std::string t_last_message;

extern "C" void keep_ida_message(int, const char* module, const char* function, char* message,
                                 void*) {
  t_last_message = fmt::format("{} {}: {}", module ? module : "IDA", function ? function : "",
                               message ? message : "");
}

// ": <IDA's last message>" if there is one.
std::string last_message() { return t_last_message.empty() ? "" : ": " + t_last_message; }

void check(int flag, const char* call) {
  if (flag < 0)
    throw SolverError(fmt::format("IDA: {} failed with flag {}{}", call, flag, last_message()));
}
}  // namespace

IdaIntegrator::IdaIntegrator(SystemOperator& op, const IdaOptions& options)
    : op_(op), options_(options), ctx_(sundials::make_context()) {
  const Index n = op_.size();
  y_ = sundials::make_serial_vector(n, ctx_.get());
  yp_ = sundials::make_serial_vector(n, ctx_.get());
  if (options_.linear_solver == IdaOptions::LinearSolver::Direct) {
    jac_ = sundials::make_csr_matrix(op_.jacobian_pattern(), ctx_.get());
    if (n >= options_.umfpack_from) {
      direct_counts_ = std::make_shared<sundials::DirectCounts>();
      solver_ = sundials::make_sparse_direct_solver(ctx_.get(), KluOrdering::Amd, direct_counts_,
                                                    options_.umfpack_from, /*refinement_steps=*/0);
    } else {
      solver_ = sundials::make_klu_solver(y_.get(), jac_.get(), ctx_.get());
    }
  } else {
    solver_ = sundials::LinearSolver(
        SUNLinSol_SPGMR(y_.get(), SUN_PREC_LEFT, options_.krylov_dimension, ctx_.get()));
    if (!op_.has_preconditioner())
      fallback_preconditioner_ = std::make_unique<JacobianLuPreconditioner>(op_);
  }
  if (!solver_) throw SolverError("creating the IDA linear solver failed");
  mem_ = IDACreate(ctx_.get());
  if (!mem_) throw SolverError("IDACreate failed");
  check(IDASetErrHandlerFn(mem_, keep_ida_message, nullptr), "IDASetErrHandlerFn");
}

// The fields of IDAMemRec that IDASolve (one-step mode) and IDAStep read or change over a step:
// the divided differences phi, the step-size coefficients, order and step control, the stop
// time and the root finder's bracket.
struct IdaIntegrator::Checkpoint {
  std::vector<std::vector<Real>> phi;
  std::vector<Real> ee;
  Real psi[MXORDP1], alpha[MXORDP1], beta[MXORDP1], sigma[MXORDP1], gamma[MXORDP1];
  int kk, kused, knew, phase, ns;
  Real hh, hused, tn, tretlast, cj, cjlast, cjold, cjratio, ss, oldnrm, eta;
  long nst;
  booleantype tstopset;
  Real tstop;
  std::vector<int> iroots;
  std::vector<Real> glo, ghi, grout;
  std::vector<booleantype> gactive;
  Real tlo, thi, trout, toutc;
  int taskc, irfnd, mxgnull;
  Real t;
  std::vector<Real> y, yp;
};

IdaIntegrator::~IdaIntegrator() { IDAFree(&mem_); }

void IdaIntegrator::save_checkpoint() {
  if (!checkpoint_) checkpoint_ = std::make_unique<Checkpoint>();
  Checkpoint& c = *checkpoint_;
  const IDAMem m = static_cast<IDAMem>(mem_);
  c.phi.resize(m->ida_maxord_alloc + 1);  // phi[j] is allocated for j <= maxord_alloc
  for (int j = 0; j <= m->ida_maxord_alloc; ++j) {
    const std::span<const Real> v = sundials::as_span(m->ida_phi[j]);
    c.phi[j].assign(v.begin(), v.end());
  }
  const std::span<const Real> ee = sundials::as_span(m->ida_ee);
  c.ee.assign(ee.begin(), ee.end());
  std::copy(m->ida_psi, m->ida_psi + MXORDP1, c.psi);
  std::copy(m->ida_alpha, m->ida_alpha + MXORDP1, c.alpha);
  std::copy(m->ida_beta, m->ida_beta + MXORDP1, c.beta);
  std::copy(m->ida_sigma, m->ida_sigma + MXORDP1, c.sigma);
  std::copy(m->ida_gamma, m->ida_gamma + MXORDP1, c.gamma);
  c.kk = m->ida_kk, c.kused = m->ida_kused, c.knew = m->ida_knew, c.phase = m->ida_phase;
  c.ns = m->ida_ns;
  c.hh = m->ida_hh, c.hused = m->ida_hused, c.tn = m->ida_tn;
  c.tretlast = m->ida_tretlast, c.cj = m->ida_cj, c.cjlast = m->ida_cjlast;
  c.cjold = m->ida_cjold, c.cjratio = m->ida_cjratio, c.ss = m->ida_ss;
  c.oldnrm = m->ida_oldnrm, c.eta = m->ida_eta, c.nst = m->ida_nst;
  c.tstopset = m->ida_tstopset, c.tstop = m->ida_tstop;
  const int nr = m->ida_nrtfn;
  c.iroots.assign(m->ida_iroots, m->ida_iroots + nr);
  c.glo.assign(m->ida_glo, m->ida_glo + nr);
  c.ghi.assign(m->ida_ghi, m->ida_ghi + nr);
  c.grout.assign(m->ida_grout, m->ida_grout + nr);
  c.gactive.assign(m->ida_gactive, m->ida_gactive + nr);
  c.tlo = m->ida_tlo, c.thi = m->ida_thi, c.trout = m->ida_trout, c.toutc = m->ida_toutc;
  c.taskc = m->ida_taskc, c.irfnd = m->ida_irfnd, c.mxgnull = m->ida_mxgnull;
  c.t = t_;
  c.y.assign(y().begin(), y().end());
  c.yp.assign(yp().begin(), yp().end());
}

Real IdaIntegrator::internal_time() const { return static_cast<IDAMem>(mem_)->ida_tn; }

std::span<const Real> IdaIntegrator::internal_y() const {
  return sundials::as_span(static_cast<IDAMem>(mem_)->ida_phi[0]);
}

void IdaIntegrator::restore_checkpoint() {
  if (!checkpoint_) throw SolverError("IDA: restore_checkpoint without a saved checkpoint");
  const Checkpoint& c = *checkpoint_;
  const IDAMem m = static_cast<IDAMem>(mem_);
  if (m->ida_nrtfn != static_cast<int>(c.iroots.size()))
    throw SolverError("IDA: the roots changed since the checkpoint");
  for (std::size_t j = 0; j < c.phi.size(); ++j)
    std::copy(c.phi[j].begin(), c.phi[j].end(), sundials::as_span(m->ida_phi[j]).begin());
  std::copy(c.ee.begin(), c.ee.end(), sundials::as_span(m->ida_ee).begin());
  std::copy(c.psi, c.psi + MXORDP1, m->ida_psi);
  std::copy(c.alpha, c.alpha + MXORDP1, m->ida_alpha);
  std::copy(c.beta, c.beta + MXORDP1, m->ida_beta);
  std::copy(c.sigma, c.sigma + MXORDP1, m->ida_sigma);
  std::copy(c.gamma, c.gamma + MXORDP1, m->ida_gamma);
  m->ida_kk = c.kk, m->ida_kused = c.kused, m->ida_knew = c.knew, m->ida_phase = c.phase;
  m->ida_ns = c.ns;
  m->ida_hh = c.hh, m->ida_hused = c.hused, m->ida_tn = c.tn;
  m->ida_tretlast = c.tretlast, m->ida_cj = c.cj, m->ida_cjlast = c.cjlast;
  m->ida_cjold = c.cjold, m->ida_cjratio = c.cjratio, m->ida_ss = c.ss;
  m->ida_oldnrm = c.oldnrm, m->ida_eta = c.eta, m->ida_nst = c.nst;
  m->ida_tstopset = c.tstopset, m->ida_tstop = c.tstop;
  std::copy(c.iroots.begin(), c.iroots.end(), m->ida_iroots);
  std::copy(c.glo.begin(), c.glo.end(), m->ida_glo);
  std::copy(c.ghi.begin(), c.ghi.end(), m->ida_ghi);
  std::copy(c.grout.begin(), c.grout.end(), m->ida_grout);
  std::copy(c.gactive.begin(), c.gactive.end(), m->ida_gactive);
  m->ida_tlo = c.tlo, m->ida_thi = c.thi, m->ida_trout = c.trout, m->ida_toutc = c.toutc;
  m->ida_taskc = c.taskc, m->ida_irfnd = c.irfnd, m->ida_mxgnull = c.mxgnull;
  t_ = c.t;
  std::copy(c.y.begin(), c.y.end(), sundials::as_span(y_.get()).begin());
  std::copy(c.yp.begin(), c.yp.end(), sundials::as_span(yp_.get()).begin());
}

void IdaIntegrator::initialize(Real t0, std::span<const Real> y0, std::span<const Real> yp0) {
  std::copy(y0.begin(), y0.end(), sundials::as_span(y_.get()).begin());
  std::copy(yp0.begin(), yp0.end(), sundials::as_span(yp_.get()).begin());
  t_ = t0;
  check(IDAInit(mem_, residual_trampoline, t0, y_.get(), yp_.get()), "IDAInit");
  check(IDASetUserData(mem_, this), "IDASetUserData");
  const bool fixed = options_.fixed_step > 0;
  // In fixed-step mode the local error test is made vacuous by huge tolerances.
  if (!fixed && !options_.atols.empty()) {
    if (static_cast<Index>(options_.atols.size()) != op_.size())
      throw SolverError(fmt::format("IDA: {} absolute tolerances for {} unknowns",
                                    options_.atols.size(), op_.size()));
    auto atol = sundials::make_serial_vector(op_.size(), ctx_.get());
    std::copy(options_.atols.begin(), options_.atols.end(), sundials::as_span(atol.get()).begin());
    check(IDASVtolerances(mem_, options_.rtol, atol.get()), "IDASVtolerances");  // IDA copies it
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
  if (!jac_ && options_.krylov_tolerance_factor > 0)
    check(IDASetEpsLin(mem_, options_.krylov_tolerance_factor), "IDASetEpsLin");
  check(IDASetMaxOrd(mem_, options_.max_order), "IDASetMaxOrd");
  check(IDASetMaxNumSteps(mem_, options_.max_steps), "IDASetMaxNumSteps");
  auto id = sundials::make_serial_vector(op_.size(), ctx_.get());
  auto components = op_.differential_components();
  std::copy(components.begin(), components.end(), sundials::as_span(id.get()).begin());
  check(IDASetId(mem_, id.get()), "IDASetId");
  if (options_.suppress_algebraic && !fixed)
    check(IDASetSuppressAlg(mem_, SUNTRUE), "IDASetSuppressAlg");
  if (fixed) {
    check(IDASetInitStep(mem_, options_.fixed_step), "IDASetInitStep");
    check(IDASetMaxStep(mem_, options_.fixed_step), "IDASetMaxStep");
    check(IDASetMinStep(
              mem_, options_.fixed_step_min > 0 ? options_.fixed_step_min : options_.fixed_step),
          "IDASetMinStep");
    // Newton on a linear system converges in one iteration; make it exact.
    check(IDASetNonlinConvCoef(mem_, 1e-10), "IDASetNonlinConvCoef");
  } else {
    if (options_.initial_step > 0)
      check(IDASetInitStep(mem_, options_.initial_step), "IDASetInitStep");
    if (options_.max_step > 0) check(IDASetMaxStep(mem_, options_.max_step), "IDASetMaxStep");
    if (options_.nonlinear_convergence > 0)
      check(IDASetNonlinConvCoef(mem_, options_.nonlinear_convergence), "IDASetNonlinConvCoef");
    if (options_.max_newton_iterations > 0)
      check(IDASetMaxNonlinIters(mem_, options_.max_newton_iterations), "IDASetMaxNonlinIters");
    if (options_.max_convergence_failures > 0)
      check(IDASetMaxConvFails(mem_, options_.max_convergence_failures), "IDASetMaxConvFails");
    if (options_.jacobian_cj_change > 0)
      check(IDASetDeltaCjLSetup(mem_, options_.jacobian_cj_change), "IDASetDeltaCjLSetup");
    if (options_.step_growth_threshold > 0)
      check(IDASetEtaFixedStepBounds(mem_, 1.0, options_.step_growth_threshold),
            "IDASetEtaFixedStepBounds");
    if (options_.max_step_growth > 0)
      check(IDASetEtaMax(mem_, options_.max_step_growth), "IDASetEtaMax");
    if (options_.convergence_failure_cut > 0)
      check(IDASetEtaConvFail(mem_, options_.convergence_failure_cut), "IDASetEtaConvFail");
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
  guard_.rethrow();
  check(IDAGetConsistentIC(mem_, y_.get(), yp_.get()), "IDAGetConsistentIC");
}

void IdaIntegrator::set_roots(int n_roots, RootFunction g) {
  n_roots_ = n_roots;
  roots_ = std::move(g);
  if (initialized_) check(IDARootInit(mem_, n_roots_, root_trampoline), "IDARootInit");
}

IdaIntegrator::Status IdaIntegrator::advance(Real t_out) {
  Real t_ret = t_;
  t_last_message.clear();
  int flag = IDASolve(mem_, t_out, &t_ret, y_.get(), yp_.get(), IDA_NORMAL);
  t_ = t_ret;
  guard_.rethrow();
  if (flag < 0)
    throw SolverError(fmt::format("IDA failed at t = {:.6g} with flag {} ({}){}", t_ret, flag,
                                  IDAGetReturnFlagName(flag), last_message()));
  return flag == IDA_ROOT_RETURN ? Status::Root : Status::Reached;
}

IdaIntegrator::Status IdaIntegrator::step(Real t_stop) {
  check(IDASetStopTime(mem_, t_stop), "IDASetStopTime");
  Real t_ret = t_;
  t_last_message.clear();
  const int flag = IDASolve(mem_, t_stop, &t_ret, y_.get(), yp_.get(), IDA_ONE_STEP);
  t_ = t_ret;
  guard_.rethrow();
  if (flag < 0)
    throw SolverError(fmt::format("IDA failed at t = {:.6g} with flag {} ({}){}", t_ret, flag,
                                  IDAGetReturnFlagName(flag), last_message()));
  if (flag == IDA_ROOT_RETURN) return Status::Root;
  return flag == IDA_TSTOP_RETURN ? Status::Reached : Status::Stepped;
}

void IdaIntegrator::state_at(Real t, std::vector<Real>& y, std::vector<Real>& yp) const {
  auto yv = sundials::make_serial_vector(op_.size(), ctx_.get());
  auto ypv = sundials::make_serial_vector(op_.size(), ctx_.get());
  check(IDAGetSolution(mem_, t, yv.get(), ypv.get()), "IDAGetSolution");
  const std::span<const Real> a = sundials::as_span(yv.get()), b = sundials::as_span(ypv.get());
  y.assign(a.begin(), a.end());
  yp.assign(b.begin(), b.end());
}

std::span<const Real> IdaIntegrator::y() const { return sundials::as_span(y_.get()); }
std::span<const Real> IdaIntegrator::yp() const { return sundials::as_span(yp_.get()); }

std::vector<int> IdaIntegrator::roots_found() const {
  std::vector<int> found(n_roots_, 0);
  if (n_roots_ > 0) IDAGetRootInfo(mem_, found.data());
  return found;
}

IntegratorStats ida_memory_stats(void* mem) {
  IntegratorStats s;
  long nrevals_ls = 0;
  IDAGetNumSteps(mem, &s.steps);
  IDAGetNumResEvals(mem, &s.residual_evals);
  IDAGetNumLinResEvals(mem, &nrevals_ls);
  s.residual_evals += nrevals_ls;
  IDAGetNumJacEvals(mem, &s.jacobian_evals);
  IDAGetNumNonlinSolvIters(mem, &s.newton_iters);
  IDAGetNumLinSolvSetups(mem, &s.linear_setups);
  IDAGetNumErrTestFails(mem, &s.error_test_fails);
  IDAGetNumNonlinSolvConvFails(mem, &s.newton_fails);
  IDAGetLastOrder(mem, &s.last_order);
  IDAGetLastStep(mem, &s.last_step);
  IDAGetNumLinIters(mem, &s.linear_iters);
  IDAGetNumPrecEvals(mem, &s.preconditioner_setups);
  IDAGetNumLinConvFails(mem, &s.linear_conv_fails);
  return s;
}

IntegratorStats IdaIntegrator::stats() const {
  IntegratorStats s = ida_memory_stats(mem_);
  s.umfpack = direct_counts_ && direct_counts_->umfpack;
  return s;
}

int IdaIntegrator::residual_trampoline(Real t, N_Vector y, N_Vector yp, N_Vector r, void* self) {
  auto* me = static_cast<IdaIntegrator*>(self);
  return me->guard_.run([&] {
    me->op_.residual(t, sundials::as_span(y), sundials::as_span(yp), sundials::as_span(r));
  });
}

int IdaIntegrator::jacobian_trampoline(Real t, Real c_j, N_Vector y, N_Vector yp, N_Vector,
                                       SUNMatrix J, void* self, N_Vector, N_Vector, N_Vector) {
  auto* me = static_cast<IdaIntegrator*>(self);
  return me->guard_.run([&] {
    const CsrPattern& pattern = me->op_.jacobian_pattern();
    sundials::load_pattern(pattern, J);
    std::span<Real> values(SUNSparseMatrix_Data(J), static_cast<std::size_t>(pattern.nnz()));
    std::fill(values.begin(), values.end(), 0.0);
    me->op_.jacobian(t, c_j, sundials::as_span(y), sundials::as_span(yp), values);
  });
}

int IdaIntegrator::root_trampoline(Real t, N_Vector y, N_Vector yp, Real* g, void* self) {
  auto* me = static_cast<IdaIntegrator*>(self);
  return me->guard_.run([&] {
    me->roots_(t, sundials::as_span(y), sundials::as_span(yp),
               std::span<Real>(g, static_cast<std::size_t>(me->n_roots_)));
  });
}

int IdaIntegrator::preconditioner_setup_trampoline(Real t, N_Vector y, N_Vector yp, N_Vector,
                                                   Real c_j, void* self) {
  auto* me = static_cast<IdaIntegrator*>(self);
  return me->guard_.run([&] {
    if (me->fallback_preconditioner_)
      me->fallback_preconditioner_->setup(t, c_j, sundials::as_span(y), sundials::as_span(yp));
    else
      me->op_.preconditioner_setup(t, c_j, sundials::as_span(y), sundials::as_span(yp));
  });
}

int IdaIntegrator::preconditioner_solve_trampoline(Real, N_Vector, N_Vector, N_Vector, N_Vector rv,
                                                   N_Vector zv, Real, Real, void* self) {
  auto* me = static_cast<IdaIntegrator*>(self);
  return me->guard_.run([&] {
    if (me->fallback_preconditioner_)
      me->fallback_preconditioner_->solve(sundials::as_span(rv), sundials::as_span(zv));
    else
      me->op_.preconditioner_solve(sundials::as_span(rv), sundials::as_span(zv));
  });
}

}  // namespace rfmems

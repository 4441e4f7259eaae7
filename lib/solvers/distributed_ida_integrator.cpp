#include "solvers/distributed_ida_integrator.hpp"

#include <fmt/format.h>
#include <ida/ida.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include <algorithm>
#include <exception>
#include <utility>

#include "core/error.hpp"
#include "solvers/callback_guard.hpp"
#include "solvers/distributed_linearization.hpp"
#include "solvers/parallel_vector.hpp"

namespace rfmems {

namespace {
void check(int flag, const char* call) {
  if (flag < 0)
    throw SolverError(fmt::format("IDA (distributed): {} failed with flag {}", call, flag));
}
}  // namespace

struct DistributedIdaIntegrator::Impl {
  DistributedSystem& system;
  IdaOptions options;
  DistributedLinearization linearization;
  sundials::Context ctx;
  sundials::Vector y, yp;
  sundials::LinearSolver gmres;
  void* mem = nullptr;
  Real t = 0;
  CallbackGuard guard;

  Impl(DistributedSystem& s, const IdaOptions& o, DistributedLinearization::Family family)
      : system(s),
        options(o),
        linearization(s, true, DistributedLinearization::best_for(s, true, family)),
        ctx(sundials::make_context()) {}
  ~Impl() { IDAFree(&mem); }

  void rethrow() { guard.rethrow(); }

  static Impl& of(void* data) { return *static_cast<Impl*>(data); }

  static int residual(Real t, N_Vector y, N_Vector yp, N_Vector r, void* data) {
    Impl& me = of(data);
    return me.guard.run([&] {
      me.system.residual(t, sundials::local_span(y), sundials::local_span(yp),
                         sundials::local_span(r));
    });
  }
  static int preconditioner_setup(Real t, N_Vector y, N_Vector yp, N_Vector, Real c_j, void* data) {
    Impl& me = of(data);
    return me.guard.run(
        [&] { me.linearization.setup(t, c_j, sundials::local_span(y), sundials::local_span(yp)); });
  }
  static int preconditioner_solve(Real, N_Vector, N_Vector, N_Vector, N_Vector r, N_Vector z, Real,
                                  Real, void* data) {
    Impl& me = of(data);
    return me.guard.run(
        [&] { me.linearization.precondition(sundials::local_span(r), sundials::local_span(z)); });
  }
  static int jacobian_times(Real, N_Vector, N_Vector, N_Vector, N_Vector v, N_Vector jv, Real c_j,
                            void* data, N_Vector, N_Vector) {
    Impl& me = of(data);
    return me.guard.run(
        [&] { me.linearization.apply(c_j, sundials::local_span(v), sundials::local_span(jv)); });
  }
};

DistributedIdaIntegrator::DistributedIdaIntegrator(DistributedSystem& system,
                                                   const IdaOptions& options,
                                                   DistributedLinearization::Family preconditioner)
    : impl_(std::make_unique<Impl>(system, options, preconditioner)) {
  Impl& k = *impl_;
  const Communicator& comm = system.communicator();
  const Index n = system.owned_size();
  k.y = sundials::make_parallel_vector(comm, n, k.ctx.get());
  k.yp = sundials::make_parallel_vector(comm, n, k.ctx.get());
  k.gmres = sundials::LinearSolver(
      SUNLinSol_SPGMR(k.y.get(), SUN_PREC_LEFT, options.krylov_dimension, k.ctx.get()));
  if (!k.gmres) throw SolverError("SUNLinSol_SPGMR failed");
  SUNLinSol_SPGMRSetGSType(k.gmres.get(), SUN_MODIFIED_GS);
  // A multigrid cycle is a weaker preconditioner than the subdomain LU on small parts: allow
  // restarts rather than fail a solve at the Krylov dimension (the damped beam: 39 of 376
  // solves unconverged without them).
  if (preconditioner == DistributedLinearization::Family::Multigrid)
    SUNLinSol_SPGMRSetMaxRestarts(k.gmres.get(), 5);
  k.mem = IDACreate(k.ctx.get());
  if (!k.mem) throw SolverError("IDACreate failed");
}

DistributedIdaIntegrator::~DistributedIdaIntegrator() = default;

void DistributedIdaIntegrator::initialize(Real t0, std::span<const Real> y0,
                                          std::span<const Real> yp0) {
  Impl& k = *impl_;
  std::copy(y0.begin(), y0.end(), sundials::local_span(k.y.get()).begin());
  std::copy(yp0.begin(), yp0.end(), sundials::local_span(k.yp.get()).begin());
  k.t = t0;
  check(IDAInit(k.mem, Impl::residual, t0, k.y.get(), k.yp.get()), "IDAInit");
  check(IDASetUserData(k.mem, &k), "IDASetUserData");
  check(IDASStolerances(k.mem, k.options.rtol, k.options.atol), "IDASStolerances");
  check(IDASetLinearSolver(k.mem, k.gmres.get(), nullptr), "IDASetLinearSolver");
  check(IDASetPreconditioner(k.mem, Impl::preconditioner_setup, Impl::preconditioner_solve),
        "IDASetPreconditioner");
  check(IDASetJacTimes(k.mem, nullptr, Impl::jacobian_times), "IDASetJacTimes");
  check(IDASetEpsLin(k.mem, k.options.krylov_tolerance_factor > 0
                                ? k.options.krylov_tolerance_factor
                                : k.linearization.krylov_tolerance_factor()),
        "IDASetEpsLin");
  check(IDASetMaxOrd(k.mem, k.options.max_order), "IDASetMaxOrd");
  check(IDASetMaxNumSteps(k.mem, k.options.max_steps), "IDASetMaxNumSteps");
  if (k.options.initial_step > 0)
    check(IDASetInitStep(k.mem, k.options.initial_step), "IDASetInitStep");
  if (k.options.max_step > 0) check(IDASetMaxStep(k.mem, k.options.max_step), "IDASetMaxStep");
  auto id =
      sundials::make_parallel_vector(k.system.communicator(), k.system.owned_size(), k.ctx.get());
  const std::vector<Real> components = k.system.differential_components();
  std::copy(components.begin(), components.end(), sundials::local_span(id.get()).begin());
  check(IDASetId(k.mem, id.get()), "IDASetId");
}

void DistributedIdaIntegrator::advance(Real t_out) {
  Impl& k = *impl_;
  Real t_ret = k.t;
  const int flag = IDASolve(k.mem, t_out, &t_ret, k.y.get(), k.yp.get(), IDA_NORMAL);
  k.t = t_ret;
  k.rethrow();
  if (flag < 0)
    throw SolverError(fmt::format("IDA (distributed) failed at t = {:.6g} with flag {} ({})", t_ret,
                                  flag, IDAGetReturnFlagName(flag)));
}

Real DistributedIdaIntegrator::time() const { return impl_->t; }
std::span<const Real> DistributedIdaIntegrator::y() const {
  return sundials::local_span(impl_->y.get());
}
std::span<const Real> DistributedIdaIntegrator::yp() const {
  return sundials::local_span(impl_->yp.get());
}

IntegratorStats DistributedIdaIntegrator::stats() const {
  IntegratorStats s = ida_memory_stats(impl_->mem);
  // The Jacobian is the distributed linearization's, which IDA's Krylov interface does not
  // count: its setups are the Jacobian evaluations.
  s.jacobian_evals = impl_->linearization.setups();
  return s;
}

}  // namespace rfmems

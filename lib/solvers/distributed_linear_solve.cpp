#include "solvers/distributed_linear_solve.hpp"

#include <fmt/format.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "parallel/distributed_system.hpp"
#include "solvers/callback_guard.hpp"
#include "solvers/distributed_linearization.hpp"
#include "solvers/parallel_vector.hpp"

namespace rfmems {

namespace {

// F(y) = A y: its Jacobian is the matrix, its overlap the subdomain matrix.
class MatrixSystem : public DistributedSystem {
 public:
  MatrixSystem(const Communicator& comm, const DistributedMatrix& a)
      : comm_(comm), a_(a), work_(a.n_local, 0.0) {}
  const Communicator& communicator() const override { return comm_; }
  Index owned_size() const override { return a_.n_owned; }
  Index local_columns() const override { return a_.n_local; }
  std::vector<Real> differential_components() const override {
    return std::vector<Real>(a_.n_owned, 0.0);
  }
  void residual(Real, std::span<const Real> y, std::span<const Real>, std::span<Real> r) override {
    std::copy(y.begin(), y.begin() + a_.n_owned, work_.begin());
    exchange_ghosts(work_);
    for (Index i = 0; i < a_.n_owned; ++i) {
      Real sum = 0;
      for (Index e = a_.pattern.row_ptr[i]; e < a_.pattern.row_ptr[i + 1]; ++e)
        sum += a_.values[e] * work_[a_.pattern.col_idx[e]];
      r[i] = sum;
    }
  }
  const CsrPattern& jacobian_pattern() const override { return a_.pattern; }
  void jacobian(Real, Real, std::span<const Real>, std::span<const Real>,
                std::span<Real> values) override {
    std::copy(a_.values.begin(), a_.values.end(), values.begin());
  }
  void exchange_ghosts(std::span<Real> x) const override {
    if (a_.exchange) a_.exchange->exchange(x, 1);
  }
  const CsrPattern* overlap_pattern() const override {
    return a_.overlap_pattern.n_rows() > 0 ? &a_.overlap_pattern : nullptr;
  }
  void overlap_jacobian(Real, Real, std::span<const Real>, std::span<const Real>,
                        std::span<Real> values) override {
    std::copy(a_.overlap_values.begin(), a_.overlap_values.end(), values.begin());
  }

 private:
  const Communicator& comm_;
  const DistributedMatrix& a_;
  std::vector<Real> work_;
};

DistributedLinearization::Preconditioner preconditioner_of(MatrixSystem& system, bool overlap) {
  return overlap && system.overlap_pattern()
             ? DistributedLinearization::Preconditioner::RestrictedAdditiveSchwarz
             : DistributedLinearization::Preconditioner::BlockJacobi;
}

}  // namespace

struct DistributedLinearSolver::Impl {
  Communicator comm;
  MatrixSystem system;
  DistributedLinearization linearization;
  DistributedLinearOptions options;
  bool schwarz;
  CallbackGuard guard;
  sundials::Context ctx = sundials::make_context();
  sundials::Vector x, b;
  sundials::LinearSolver gmres;

  Impl(const Communicator& c, const DistributedMatrix& a, const DistributedLinearOptions& o)
      : comm(c),
        system(comm, a),
        linearization(system, false, preconditioner_of(system, o.overlap)),
        options(o),
        schwarz(preconditioner_of(system, o.overlap) ==
                DistributedLinearization::Preconditioner::RestrictedAdditiveSchwarz),
        x(sundials::make_parallel_vector(comm, a.n_owned, ctx.get())),
        b(sundials::make_parallel_vector(comm, a.n_owned, ctx.get())) {
    // The fused reductions (one MPI_Allreduce for all of classical Gram-Schmidt's dot
    // products) on the vectors SPGMR clones from x; without them N_VDotProdMulti loops.
    for (N_Vector v : {x.get(), b.get()}) sundials::enable_fused_operations(v);
    gmres.reset(SUNLinSol_SPGMR(x.get(), SUN_PREC_RIGHT, o.krylov_dimension, ctx.get()));
    if (!gmres) throw SolverError("SUNLinSol_SPGMR failed");
    SUNLinSol_SPGMRSetGSType(gmres.get(),
                             o.classical_gram_schmidt ? SUN_CLASSICAL_GS : SUN_MODIFIED_GS);
    SUNLinSol_SPGMRSetMaxRestarts(gmres.get(), o.max_restarts);
    if (SUNLinSolSetATimes(gmres.get(), this, times) != 0 ||
        SUNLinSolSetPreconditioner(gmres.get(), this, nullptr, precondition) != 0 ||
        SUNLinSolInitialize(gmres.get()) != 0)
      throw SolverError("SPGMR: setting up the distributed linear solve failed");
  }

  static int times(void* data, N_Vector v, N_Vector z) {
    Impl& p = *static_cast<Impl*>(data);
    return p.guard.run_or_stop(
        [&] { p.linearization.apply(0.0, sundials::local_span(v), sundials::local_span(z)); });
  }
  static int precondition(void* data, N_Vector r, N_Vector z, realtype, int) {
    Impl& p = *static_cast<Impl*>(data);
    return p.guard.run_or_stop([&] {
      const auto rs = sundials::local_span(r);
      const auto zs = sundials::local_span(z);
      std::copy(rs.begin(), rs.end(), zs.begin());
      p.linearization.precondition(zs, zs);
    });
  }
};

DistributedLinearSolver::DistributedLinearSolver(const Communicator& comm,
                                                 const DistributedMatrix& matrix,
                                                 const DistributedLinearOptions& options)
    : impl_(std::make_unique<Impl>(comm, matrix, options)) {}

DistributedLinearSolver::~DistributedLinearSolver() = default;

bool DistributedLinearSolver::schwarz() const { return impl_->schwarz; }

void DistributedLinearSolver::factor() { impl_->linearization.setup(0.0, 0.0, {}, {}); }

DistributedLinearStats DistributedLinearSolver::solve(std::span<const Real> b, std::span<Real> x) {
  Impl& p = *impl_;
  auto bv = sundials::local_span(p.b.get());
  auto xv = sundials::local_span(p.x.get());
  std::copy(b.begin(), b.end(), bv.begin());
  std::copy(x.begin(), x.end(), xv.begin());
  const Real b_norm = std::sqrt(N_VDotProd(p.b.get(), p.b.get()));  // collective
  DistributedLinearStats stats;
  if (b_norm == 0) {  // x = 0 exactly
    std::fill(x.begin(), x.end(), 0.0);
    return stats;
  }
  const int flag = SUNLinSolSolve(p.gmres.get(), nullptr, p.x.get(), p.b.get(),
                                  p.options.relative_tolerance * b_norm);
  p.guard.rethrow();
  stats.iterations = SUNLinSolNumIters(p.gmres.get());
  stats.relative_residual = SUNLinSolResNorm(p.gmres.get()) / b_norm;
  if (flag != SUNLS_SUCCESS)
    throw SolverError(fmt::format(
        "distributed GMRES: flag {} after {} iterations, relative residual {:.3e} (tolerance "
        "{:.1e})",
        flag, stats.iterations, stats.relative_residual, p.options.relative_tolerance));
  std::copy(xv.begin(), xv.end(), x.begin());
  return stats;
}

}  // namespace rfmems

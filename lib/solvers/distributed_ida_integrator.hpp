// Transient integration of a DistributedSystem with SUNDIALS IDA on the MPI parallel
// N_Vector: variable-order variable-step BDF as IdaIntegrator, with SPGMR (left
// preconditioned) for the Newton systems, the exact distributed Jacobian-vector product of
// dF/dy + c_j dF/dy' and a rank-local KLU preconditioner (solvers/distributed_linearization.hpp:
// the Schur complement K + c_j^2 M by additive Schwarz on the overlap for a structural
// first-order system, else block Jacobi), refreshed when IDA asks for a linear-solver setup.
//
// The options and statistics are IdaIntegrator's (linear_solver is ignored: always SPGMR;
// atols, fixed steps and root functions are not supported here). The local error test is
// IDA's weighted RMS norm over all ranks, so the steps are the serial run's up to the
// differences of the inexact Newton solves. Those are kept beneath the Newton tolerance by a
// Krylov tolerance (IDA's eps_lin) set by the preconditioner's quality,
// DistributedLinearization::krylov_tolerance_factor(): SUNDIALS' 0.05 let block Jacobi on a
// damped beam end 3.6e-2 (2 ranks) and 6.1e-2 (3 ranks) off the serial answer with GMRES
// converged every time (docs/mpi.md, "Krylov tolerance").
#pragma once
#include <memory>
#include <span>

#include "parallel/distributed_system.hpp"
#include "solvers/distributed_linearization.hpp"
#include "solvers/ida_integrator.hpp"

namespace rfmems {

class DistributedIdaIntegrator {
 public:
  // Collective. The preconditioner family's best variant for the system
  // (DistributedLinearization::best_for).
  DistributedIdaIntegrator(
      DistributedSystem& system, const IdaOptions& options,
      DistributedLinearization::Family preconditioner = DistributedLinearization::Family::Schwarz);
  ~DistributedIdaIntegrator();
  DistributedIdaIntegrator(const DistributedIdaIntegrator&) = delete;
  DistributedIdaIntegrator& operator=(const DistributedIdaIntegrator&) = delete;

  // Owned parts of the initial state (consistent y' is the caller's job).
  void initialize(Real t0, std::span<const Real> y0, std::span<const Real> yp0);
  // Advances to t_out (collective).
  void advance(Real t_out);
  Real time() const;
  std::span<const Real> y() const;   // owned
  std::span<const Real> yp() const;  // owned
  IntegratorStats stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rfmems

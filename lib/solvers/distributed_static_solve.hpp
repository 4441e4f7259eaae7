// Static equilibrium R(t, y) = 0 of a distributed structural operator: KINSOL on
// SUNDIALS' MPI parallel N_Vector, Newton with SPGMR (right-preconditioned GMRES, modified
// Gram-Schmidt) for the linear systems, the exact distributed Jacobian-vector product and a
// preconditioner: KLU on the rank-local blocks (restricted additive Schwarz on the ghost
// overlap, or block Jacobi) or algebraic multigrid on the whole matrix
// (solvers/distributed_linearization.hpp).
//
// The convergence test is the serial one (solvers/static_solve.hpp): ||R||_inf <=
// relative_tolerance ||R(y0)||_inf, and with round_off_floor never below the residual's
// round-off floor (solvers/kinsol_solver.hpp). Each Newton step's Krylov solve is tight
// (constant forcing term linear_tolerance, not Eisenstat-Walker), so a linear problem still
// takes one Newton step, as with KLU, at any tolerance: without the floor a tolerance beneath
// it left Newton and GMRES iterating on round-off (a plane beam at L/h = 50 stopped after 50
// Newton steps).
#pragma once
#include <vector>

#include "parallel/distributed_system.hpp"
#include "solvers/distributed_linearization.hpp"
#include "solvers/kinsol_solver.hpp"

namespace rfmems {

struct DistributedNewtonOptions {
  Real relative_tolerance = 1e-6;  // as KinsolOptions
  int max_iterations = 50;
  bool round_off_floor = true;  // as the serial solve_static (KinsolOptions::round_off_floor)
  // KINSOL's constant forcing term: each GMRES solve reduces the scaled residual of the
  // Newton system by this (2-norm).
  Real linear_tolerance = 1e-12;
  int krylov_dimension = 200;
  int max_restarts = 10;
  // Classical Gram-Schmidt with reorthogonalisation (fused dot products: one pass over the
  // basis per iteration) instead of modified (one pass per basis vector).
  bool classical_gram_schmidt = false;
  // Schwarz: restricted additive Schwarz on the ghost overlap where the operator offers it,
  // else block Jacobi on the owned blocks; Multigrid: BoomerAMG on the whole Jacobian.
  DistributedLinearization::Family preconditioner = DistributedLinearization::Family::Schwarz;
};

struct DistributedStaticSolution {
  std::vector<Real> y;   // this rank's owned unknowns
  NonlinearStats stats;  // linear_iters: the GMRES iterations (the same on every rank)
  AmgStats multigrid;    // the hierarchy of the last setup (multigrid only)
};

// Collective. Starts from y0 (owned; zero if empty).
DistributedStaticSolution solve_static_distributed(DistributedSecondOrderOperator& op, Real t,
                                                   const DistributedNewtonOptions& options = {},
                                                   std::vector<Real> y0 = {});

}  // namespace rfmems

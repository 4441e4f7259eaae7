// GMRES on one sparse matrix preconditioned by another operator: PETSc's split of the operator
// (Amat) from the one the preconditioner is built from (Pmat). SUNDIALS SPGMR,
// right-preconditioned (its residual is the unpreconditioned b - A x), modified Gram-Schmidt,
// restarted; P^-1 any fixed linear map (a KLU factorisation of P, a multigrid V-cycle).
//
// The residual is weighted per row by 1 / (the row's largest |A| entry), so that rows of
// different units (a plate's forces and moments, a bordered voltage row) count alike: GMRES
// stops when ||D (b - A x)||_2 <= relative_tolerance ||D b||_2.
//
// For measurements of a preconditioner's quality (its iterations against the mesh): a
// compact-stencil Jacobian's LU for a wide-stencil one (bench/bench_compact_preconditioner.cpp),
// multigrid variants on a thin strip (bench/bench_amg_rigid_body_modes.cpp).
#pragma once
#include <functional>
#include <span>

#include "core/system_operator.hpp"

namespace rfmems {

struct SplitGmresOptions {
  Real relative_tolerance = 1e-8;
  int krylov_dimension = 200;
  int max_restarts = 5;
};

struct SplitGmresResult {
  long iterations = 0;
  Real relative_residual = 0;  // ||D (b - A x)||_2 / ||D b||_2 at exit
  bool converged = false;
};

// z = P^-1 z in place.
using PreconditionerSolve = std::function<void(std::span<Real>)>;

// Solves A x = b (A: pattern, values) with the preconditioner; x holds the initial guess on
// entry.
SplitGmresResult split_preconditioned_gmres(const CsrPattern& pattern, std::span<const Real> values,
                                            const PreconditionerSolve& preconditioner,
                                            std::span<const Real> b, std::span<Real> x,
                                            const SplitGmresOptions& options = {});

}  // namespace rfmems

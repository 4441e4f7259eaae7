// GMRES on one sparse matrix preconditioned by the LU factorisation of another: PETSc's split
// of the operator (Amat) from the matrix the preconditioner is built from (Pmat). SUNDIALS SPGMR,
// right-preconditioned (its residual is the unpreconditioned b - A x), modified Gram-Schmidt,
// restarted; P^-1 by a KLU factorisation of P.
//
// The residual is weighted per row by 1 / (the row's largest |A| entry), so that rows of
// different units (a plate's forces and moments, a bordered voltage row) count alike: GMRES
// stops when ||D (b - A x)||_2 <= relative_tolerance ||D b||_2.
//
// For measurements of a preconditioner's quality (its iterations against the mesh), e.g. a
// compact-stencil Jacobian's LU for a wide-stencil one (bench/bench_compact_preconditioner.cpp).
#pragma once
#include <span>

#include "core/system_operator.hpp"
#include "solvers/klu_factorization.hpp"

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

// Solves A x = b (A: pattern, values) with P's factorisation as the preconditioner; x holds the
// initial guess on entry.
SplitGmresResult split_preconditioned_gmres(const CsrPattern& pattern, std::span<const Real> values,
                                            KluFactorization& preconditioner,
                                            std::span<const Real> b, std::span<Real> x,
                                            const SplitGmresOptions& options = {});

}  // namespace rfmems

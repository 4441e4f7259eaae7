// Eigenpairs of a sparse generalised problem with a diagonal mass,
//
//   K x = lambda M x,   K: n x n sparse (CSR), not necessarily symmetric; M = diag(m), m >= 0,
//
// the n_modes eigenvalues nearest a real shift sigma, by shift-invert Arnoldi (Spectra's
// GenEigsSolver, implicitly restarted, on the shift-invert operator): the eigenvalues nu of
//
//   T = (K - sigma M)^-1 M,   nu = 1 / (lambda - sigma),
//
// of largest |nu| are the lambda nearest sigma. T is scaled by c ~ |lambda - sigma| of the
// nearest eigenvalues so that the wanted c nu are O(1): Spectra's convergence test floors at an
// absolute eps^(2/3), which an unscaled nu ~ 1e-12 (lambda = omega^2 of a MEMS structure) would
// pass at once. T is applied with one factorisation of K - sigma M, made once: KLU
// (solvers/klu_factorization.hpp) for small systems, UMFPACK (solvers/umfpack_factorization.hpp)
// for large ones, whose LU fill KLU's left-looking factorisation handles slowly (docs/modal.md,
// "Cost"). A singular M (components without inertia) is allowed: its null space gives nu = 0
// (lambda infinite), never among the largest; the Arnoldi start vector is T applied to a
// pseudo-random vector of fixed seed (every mode present, the run reproducible), so that every
// Krylov vector, and so every eigenvector, satisfies the massless rows of K x = lambda M x.
//
// Why the general (non-symmetric) solver: a cell-centred FV stiffness is not symmetric, and its
// eigenvalues may come in complex pairs; each is returned as it is, with its complex eigenvector.
// Spectra: header-only, on Eigen, the ARPACK algorithm (Debian libspectra-dev).
#pragma once
#include <complex>
#include <span>
#include <string>
#include <vector>

#include "core/system_operator.hpp"
#include "solvers/umfpack_factorization.hpp"

namespace rfmems {

struct ShiftInvertOptions {
  Index n_modes = 6;       // 1 <= n_modes <= (number of nonzero masses) - 2
  Real shift = 0;          // sigma, in the units of lambda
  Index subspace = 0;      // Arnoldi basis size; 0: max(2 n_modes + 1, 20), at most n
  Real tolerance = 1e-10;  // Spectra's relative tolerance on the Ritz values of c T
  Index max_restarts = 1000;
  // The factorisation of K - sigma M: KLU (AMD ordering) below `umfpack_from` unknowns, UMFPACK
  // (multifrontal, METIS ordering) from there on (solvers/umfpack_factorization.hpp).
  Index umfpack_from = kUmfpackFrom;
};

struct ShiftInvertStats {
  Index requested = 0;
  Index converged = 0;
  Index restarts = 0;               // Spectra's num_iterations()
  Index operator_applications = 0;  // solves with K - sigma M (Spectra's and the start vector's)
  Index subspace = 0;
  std::string factorization;  // "klu" or "umfpack"
  Real factor_seconds = 0;    // KLU factorisation of K - sigma M (wall)
  Real solve_seconds = 0;     // the Arnoldi iteration and the eigenvectors (wall)
};

struct EigenPair {
  std::complex<Real> value;                // lambda
  std::vector<std::complex<Real>> vector;  // x, ||x||_2 = 1
  // ||K x - lambda M x|| / (||K x|| + |lambda| ||M x||): the relative residual of the pair.
  Real residual = 0;
};

struct ShiftInvertSolution {
  std::vector<EigenPair> pairs;  // the converged pairs, nearest the shift first
  ShiftInvertStats stats;
};

// The pairs of K x = lambda M x nearest options.shift. InputError-free: the caller checks
// n_modes; throws SolverError if K - sigma M is singular (sigma an eigenvalue, or a structure
// free to move rigidly with sigma = 0) or the iteration fails.
ShiftInvertSolution solve_shift_invert(const CsrPattern& pattern, std::span<const Real> stiffness,
                                       std::span<const Real> mass_diagonal,
                                       const ShiftInvertOptions& options);

// The number of nonzero masses less 2: the most eigenpairs solve_shift_invert can return
// (finite eigenvalues of the pencil; the Arnoldi method needs two more basis vectors).
Index max_shift_invert_modes(std::span<const Real> mass_diagonal);

}  // namespace rfmems

// Shift-invert Arnoldi for K x = lambda M x (see the header).
#include "solvers/modal_solver.hpp"

#include <fmt/format.h>

// GCC 12 reports a false -Wuse-after-free inside Eigen's storage as Spectra's Hessenberg
// eigenvector code inlines it; the headers are not ours to change.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuse-after-free"
#include <Spectra/GenEigsSolver.h>
#pragma GCC diagnostic pop
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "core/error.hpp"
#include "solvers/sparse_lu.hpp"

namespace rfmems {

namespace {

using Clock = std::chrono::steady_clock;

Real seconds_since(Clock::time_point start) {
  return std::chrono::duration<Real>(Clock::now() - start).count();
}

// The shift-invert operation for the pencil (K, M), scaled: y = c (K - sigma M)^-1 M x, with the
// factorisation made once (factorize). c = 1 until set_scale.
class PencilShiftSolve {
 public:
  using Scalar = Real;

  PencilShiftSolve(const CsrPattern& pattern, std::span<const Real> stiffness,
                   std::span<const Real> mass, bool umfpack)
      : pattern_(pattern), stiffness_(stiffness), mass_(mass), umfpack_(umfpack) {}

  Eigen::Index rows() const { return pattern_.n_rows(); }
  Eigen::Index cols() const { return pattern_.n_rows(); }

  void factorize(Real sigma) {
    const Clock::time_point start = Clock::now();
    std::vector<Real> shifted(stiffness_.begin(), stiffness_.end());
    for (Index i = 0; i < pattern_.n_rows(); ++i) {
      if (mass_[i] == 0) continue;
      const Index k = pattern_.find(i, i);
      if (k < 0) throw SolverError("modal solve: the stiffness pattern lacks a diagonal entry");
      shifted[k] -= sigma * mass_[i];
    }
    try {
      // No iterative refinement: each step costs a residual and another solve, and the
      // shift-invert iteration needs no more than the factorisation's accuracy.
      lu_ = std::make_unique<SparseLu>(pattern_, shifted,
                                       umfpack_ ? 0 : std::numeric_limits<Index>::max());
    } catch (const SolverError&) {
      throw SolverError(fmt::format(
          "modal solve: K - sigma M is singular at sigma = {:g} (a shift on an eigenvalue, or a "
          "structure that can move rigidly: give a nonzero shift)",
          sigma));
    }
    factor_seconds_ = seconds_since(start);
  }

  void perform_op(const Real* x, Real* y) const {
    const Index n = pattern_.n_rows();
    for (Index i = 0; i < n; ++i) y[i] = scale_ * mass_[i] * x[i];
    const std::span<Real> b(y, static_cast<std::size_t>(n));
    lu_->solve(b);
    ++applications_;
  }

  void set_scale(Real c) { scale_ = c; }
  Real scale() const { return scale_; }
  Real factor_seconds() const { return factor_seconds_; }
  Index applications() const { return applications_; }

 private:
  const CsrPattern& pattern_;
  std::span<const Real> stiffness_;
  std::span<const Real> mass_;
  bool umfpack_;
  // solve() is not const; perform_op must be.
  std::unique_ptr<SparseLu> lu_;
  Real scale_ = 1;
  Real factor_seconds_ = 0;
  mutable Index applications_ = 0;
};

// ||K x - lambda M x|| / (||K x|| + |lambda| ||M x||).
Real pair_residual(const CsrPattern& pattern, std::span<const Real> K, std::span<const Real> mass,
                   std::complex<Real> lambda, const std::vector<std::complex<Real>>& x) {
  Real r2 = 0, kx2 = 0, mx2 = 0;
  for (Index i = 0; i < pattern.n_rows(); ++i) {
    std::complex<Real> kx = 0;
    for (Index k = pattern.row_ptr[i]; k < pattern.row_ptr[i + 1]; ++k)
      kx += K[k] * x[pattern.col_idx[k]];
    const std::complex<Real> mx = mass[i] * x[i];
    r2 += std::norm(kx - lambda * mx);
    kx2 += std::norm(kx);
    mx2 += std::norm(mx);
  }
  const Real scale = std::sqrt(kx2) + std::abs(lambda) * std::sqrt(mx2);
  return scale > 0 ? std::sqrt(r2) / scale : 0;
}

}  // namespace

Index max_shift_invert_modes(std::span<const Real> mass_diagonal) {
  const auto massive =
      std::count_if(mass_diagonal.begin(), mass_diagonal.end(), [](Real m) { return m != 0; });
  return static_cast<Index>(massive) - 2;
}

ShiftInvertSolution solve_shift_invert(const CsrPattern& pattern, std::span<const Real> stiffness,
                                       std::span<const Real> mass_diagonal,
                                       const ShiftInvertOptions& options) {
  const Index n = pattern.n_rows();
  const Index nev = options.n_modes;
  if (nev < 1 || nev > max_shift_invert_modes(mass_diagonal))
    throw SolverError(fmt::format("modal solve: {} modes asked of a pencil with {} finite ones",
                                  nev, std::max<Index>(0, max_shift_invert_modes(mass_diagonal))));
  const Index ncv = std::min(n, options.subspace > 0 ? std::max(options.subspace, nev + 2)
                                                     : std::max(2 * nev + 1, Index{20}));

  const bool umfpack = options.umfpack_from > 0 && n >= options.umfpack_from;
  PencilShiftSolve op(pattern, stiffness, mass_diagonal, umfpack);
  op.factorize(options.shift);

  const Clock::time_point start = Clock::now();
  // The start vector T b, b pseudo-random with a fixed seed (every mode present in it, the
  // run reproducible): in the range of T, so free of the directions of M's null space (see
  // the header).
  Eigen::VectorXd b(n), start_vector(n), next(n);
  std::mt19937_64 random(20261204);
  std::uniform_real_distribution<Real> uniform(-0.5, 0.5);
  for (Index i = 0; i < n; ++i) b[i] = uniform(random);
  op.perform_op(b.data(), start_vector.data());
  if (start_vector.norm() == 0) throw SolverError("modal solve: the mass matrix is zero");
  // Spectra's convergence test is relative to max(|nu|, eps^(2/3)): with nu = 1/(lambda -
  // sigma) ~ 1e-12 (a MEMS structure's lambda = omega^2 ~ 1e12) it would accept any Ritz value.
  // So T is scaled by c ~ |lambda - sigma| of the nearest eigenvalues (one power step's
  // estimate), which puts the wanted c nu near 1; lambda = sigma + c / (c nu) below.
  op.perform_op(start_vector.data(), next.data());
  if (next.norm() > 0) op.set_scale(start_vector.norm() / next.norm());
  start_vector /= start_vector.norm();

  Spectra::GenEigsSolver<PencilShiftSolve> eigs(op, nev, ncv);
  eigs.init(start_vector.data());
  eigs.compute(Spectra::SortRule::LargestMagn, options.max_restarts, options.tolerance,
               Spectra::SortRule::LargestMagn);
  if (eigs.info() == Spectra::CompInfo::NumericalIssue)
    throw SolverError("modal solve: Spectra reported a numerical issue");

  ShiftInvertSolution solution;
  // The eigenvalues of c T are c / (lambda - sigma).
  const Eigen::VectorXcd values =
      (op.scale() / eigs.eigenvalues().array() + options.shift).matrix();
  const Eigen::MatrixXcd vectors = eigs.eigenvectors();
  solution.stats.solve_seconds = seconds_since(start);
  for (Index k = 0; k < values.size(); ++k) {
    EigenPair pair;
    pair.value = values[k];
    pair.vector.assign(vectors.col(k).data(), vectors.col(k).data() + n);
    pair.residual = pair_residual(pattern, stiffness, mass_diagonal, pair.value, pair.vector);
    solution.pairs.push_back(std::move(pair));
  }
  // Nearest the shift first (Spectra sorts by |lambda|).
  std::stable_sort(solution.pairs.begin(), solution.pairs.end(),
                   [&](const EigenPair& a, const EigenPair& b) {
                     return std::abs(a.value - options.shift) < std::abs(b.value - options.shift);
                   });
  ShiftInvertStats& s = solution.stats;
  s.requested = nev;
  s.converged = static_cast<Index>(values.size());
  s.restarts = eigs.num_iterations();
  s.operator_applications = op.applications();
  s.subspace = ncv;
  s.factorization = umfpack ? "umfpack" : "klu";
  s.factor_seconds = op.factor_seconds();
  return solution;
}

}  // namespace rfmems

// The shift-invert eigensolver (solvers/modal_solver.hpp) against dense eigenvalues computed
// another way (Eigen's EigenSolver on the pencil reduced to its massive unknowns by the Schur
// complement), with a non-symmetric K, a singular M, a shift inside the spectrum, a complex
// pair, and a singular K - sigma M; and the modal exponent of the structural analysis
// (physics/structure/modal_analysis.hpp) against the roots of s^2 + beta lambda s + lambda.
// Both factorisations (KLU, UMFPACK) of K - sigma M are exercised.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>

#include "core/error.hpp"
#include "physics/structure/modal_analysis.hpp"
#include "solvers/modal_solver.hpp"

using namespace rfmems;

namespace {

struct Pencil {
  CsrPattern pattern;
  std::vector<Real> values, mass;
  Eigen::MatrixXd dense;
};

Pencil from_dense(const Eigen::MatrixXd& K, std::vector<Real> mass) {
  Pencil p;
  p.dense = K;
  p.mass = std::move(mass);
  for (Index i = 0; i < K.rows(); ++i) {
    for (Index j = 0; j < K.cols(); ++j)
      if (K(i, j) != 0 || i == j) {
        p.pattern.col_idx.push_back(j);
        p.values.push_back(K(i, j));
      }
    p.pattern.row_ptr.push_back(static_cast<Index>(p.pattern.col_idx.size()));
  }
  return p;
}

// A chain of n massive unknowns, each coupled to a massless one (as a plate's w to its
// rotations), with a non-symmetric coupling (1 +- skew along the chain: non-normal, its
// eigenvalues' condition growing as ((1 + skew) / (1 - skew))^(n/2)); masses varying along it.
Pencil chain(Index n, Real skew = 0.1) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  std::vector<Real> mass(2 * n, 0.0);
  for (Index i = 0; i < n; ++i) {
    const Index a = 2 * i, b = 2 * i + 1;  // a massive, b massless
    K(a, a) = 2.5;
    if (i > 0) K(a, a - 2) = -(1 + skew);
    if (i + 1 < n) K(a, a + 2) = -(1 - skew);
    K(a, b) = 0.3;
    K(b, a) = -0.2;
    K(b, b) = 1.0 + 0.01 * static_cast<Real>(i);
    mass[a] = 1.0 + 0.5 * std::sin(static_cast<Real>(i));
  }
  return from_dense(K, mass);
}

// Eigenvalues of K x = lambda M x with M singular: eliminate the massless unknowns (Schur
// complement) and solve M_m^-1 S densely.
std::vector<std::complex<Real>> reference_eigenvalues(const Pencil& p) {
  std::vector<Index> massive, massless;
  for (Index i = 0; i < static_cast<Index>(p.mass.size()); ++i)
    (p.mass[i] != 0 ? massive : massless).push_back(i);
  const Index m = massive.size(), z = massless.size();
  Eigen::MatrixXd Kmm(m, m), Kmz(m, z), Kzm(z, m), Kzz(z, z);
  for (Index i = 0; i < m; ++i) {
    for (Index j = 0; j < m; ++j) Kmm(i, j) = p.dense(massive[i], massive[j]);
    for (Index j = 0; j < z; ++j) Kmz(i, j) = p.dense(massive[i], massless[j]);
  }
  for (Index i = 0; i < z; ++i) {
    for (Index j = 0; j < m; ++j) Kzm(i, j) = p.dense(massless[i], massive[j]);
    for (Index j = 0; j < z; ++j) Kzz(i, j) = p.dense(massless[i], massless[j]);
  }
  Eigen::MatrixXd S = Kmm;
  if (z > 0) S -= Kmz * Kzz.partialPivLu().solve(Kzm);
  for (Index i = 0; i < m; ++i) S.row(i) /= p.mass[massive[i]];
  const Eigen::EigenSolver<Eigen::MatrixXd> es(S);
  std::vector<std::complex<Real>> values(es.eigenvalues().data(),
                                         es.eigenvalues().data() + es.eigenvalues().size());
  return values;
}

// The k reference eigenvalues nearest sigma, nearest first.
std::vector<std::complex<Real>> nearest(std::vector<std::complex<Real>> values, Real sigma,
                                        std::size_t k) {
  std::sort(values.begin(), values.end(),
            [&](auto a, auto b) { return std::abs(a - sigma) < std::abs(b - sigma); });
  values.resize(k);
  return values;
}

}  // namespace

TEST(ModalSolver, NonSymmetricPencilWithSingularMassMatchesDenseReference) {
  const Pencil p = chain(40);
  for (const Real sigma : {0.0, 1.3})
    for (const Index umfpack_from : {Index{0}, Index{1}}) {  // KLU, then UMFPACK
      ShiftInvertOptions options;
      options.n_modes = 5;
      options.shift = sigma;
      options.umfpack_from = umfpack_from;
      const ShiftInvertSolution s = solve_shift_invert(p.pattern, p.values, p.mass, options);
      ASSERT_EQ(s.stats.converged, 5);
      EXPECT_EQ(s.stats.factorization, umfpack_from > 0 ? "umfpack" : "klu");
      EXPECT_GT(s.stats.operator_applications, 5);
      const auto expected = nearest(reference_eigenvalues(p), sigma, 5);
      for (std::size_t k = 0; k < 5; ++k) {
        EXPECT_NEAR(std::abs(s.pairs[k].value - expected[k]), 0.0, 1e-9 * std::abs(expected[k]))
            << "sigma " << sigma << ", pair " << k;
        EXPECT_LT(s.pairs[k].residual, 1e-9);
        // The residual recomputed here, in full, including the massless rows.
        const auto& x = s.pairs[k].vector;
        Eigen::VectorXcd xv(x.size());
        for (std::size_t i = 0; i < x.size(); ++i) xv[i] = x[i];
        Eigen::VectorXcd mx(x.size());
        for (std::size_t i = 0; i < x.size(); ++i) mx[i] = p.mass[i] * x[i];
        const Eigen::VectorXcd r = p.dense.cast<std::complex<Real>>() * xv - s.pairs[k].value * mx;
        EXPECT_LT(r.norm(), 1e-9 * (p.dense.norm() * xv.norm())) << "pair " << k;
        EXPECT_NEAR(xv.norm(), 1.0, 1e-12);
      }
    }
  EXPECT_EQ(max_shift_invert_modes(p.mass), 38);
}

TEST(ModalSolver, StiffPencilOfAMemsStructureConverges) {
  // lambda ~ omega^2 ~ 1e12 (a MEMS plate): the Ritz values of the unscaled (K - sigma M)^-1 M
  // are ~1e-12, below Spectra's absolute floor eps^(2/3), and every Ritz pair would pass its
  // convergence test at once; the scaled operator must still give accurate pairs.
  Pencil p = chain(150, 0.01);
  for (Real& v : p.values) v *= 1e12;
  p.dense *= 1e12;
  ShiftInvertOptions options;
  options.n_modes = 10;
  const ShiftInvertSolution s = solve_shift_invert(p.pattern, p.values, p.mass, options);
  ASSERT_EQ(s.stats.converged, 10);
  const auto expected = nearest(reference_eigenvalues(p), 0.0, 10);
  for (std::size_t k = 0; k < 10; ++k) {
    EXPECT_NEAR(std::abs(s.pairs[k].value - expected[k]), 0.0, 1e-9 * std::abs(expected[k]))
        << "pair " << k;
    EXPECT_LT(s.pairs[k].residual, 1e-9) << "pair " << k;
  }
}

TEST(ModalSolver, ComplexPairIsReturnedWithItsConjugate) {
  // Three 2 x 2 blocks [[a, b], [-b, a]] (eigenvalues a +- i b) and a real tail.
  const Index n = 30;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (Index i = 0; i < n; ++i) K(i, i) = 10.0 + static_cast<Real>(i);
  const Real a[3] = {1.0, 2.0, 3.0}, b[3] = {0.5, 0.02, 1e-3};
  for (int k = 0; k < 3; ++k) {
    const Index i = 2 * k;
    K(i, i) = K(i + 1, i + 1) = a[k];
    K(i, i + 1) = b[k];
    K(i + 1, i) = -b[k];
  }
  const Pencil p = from_dense(K, std::vector<Real>(n, 1.0));
  ShiftInvertOptions options;
  options.n_modes = 6;
  const ShiftInvertSolution s = solve_shift_invert(p.pattern, p.values, p.mass, options);
  ASSERT_EQ(s.stats.converged, 6);
  for (int k = 0; k < 3; ++k) {
    int found = 0;
    for (const EigenPair& pair : s.pairs)
      if (std::abs(pair.value - std::complex<Real>(a[k], b[k])) < 1e-10 ||
          std::abs(pair.value - std::complex<Real>(a[k], -b[k])) < 1e-10)
        ++found;
    EXPECT_EQ(found, 2) << "pair " << k;
  }
}

TEST(ModalSolver, SingularShiftedMatrixIsASolverError) {
  // A free chain (K annihilates constants): sigma = 0 is an eigenvalue.
  const Index n = 12;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (Index i = 0; i + 1 < n; ++i) {
    K(i, i) += 1;
    K(i + 1, i + 1) += 1;
    K(i, i + 1) -= 1;
    K(i + 1, i) -= 1;
  }
  const Pencil p = from_dense(K, std::vector<Real>(n, 1.0));
  ShiftInvertOptions options;
  options.n_modes = 3;
  EXPECT_THROW(solve_shift_invert(p.pattern, p.values, p.mass, options), SolverError);
  options.shift = -0.5;  // off the spectrum: the rigid mode lambda = 0 is found
  const ShiftInvertSolution s = solve_shift_invert(p.pattern, p.values, p.mass, options);
  EXPECT_NEAR(std::abs(s.pairs[0].value), 0.0, 1e-10);
}

TEST(ModalExponent, RootsOfTheDampedCharacteristicEquation) {
  const Real omega = 3.0;
  // Undamped: s = i omega.
  const std::complex<Real> s0 = modal_exponent(omega * omega, 0.0);
  EXPECT_NEAR(s0.real(), 0.0, 1e-14);
  EXPECT_NEAR(s0.imag(), omega, 1e-14);
  // Kelvin-Voigt C = beta K: zeta = beta omega / 2 and |s| = omega.
  const Real beta = 0.02;
  const std::complex<Real> s1 = modal_exponent(omega * omega, beta);
  EXPECT_NEAR(-s1.real() / std::abs(s1), beta * omega / 2, 1e-14);
  EXPECT_NEAR(std::abs(s1), omega, 1e-13);
  EXPECT_GT(s1.imag(), 0.0);
  // Overdamped (beta omega > 2): both roots real, the slower one reported.
  const std::complex<Real> s2 = modal_exponent(omega * omega, 1.0);
  const Real disc = std::sqrt(std::pow(1.0 * omega * omega, 2) - 4 * omega * omega);
  EXPECT_NEAR(s2.real(), (-omega * omega + disc) / 2, 1e-12);
  // An unstable state, lambda < 0: s = +sqrt(-lambda), real.
  const std::complex<Real> s3 = modal_exponent(-4.0, 0.0);
  EXPECT_NEAR(s3.real(), 2.0, 1e-14);
  EXPECT_NEAR(s3.imag(), 0.0, 1e-14);
  // Every reported root solves s^2 + beta lambda s + lambda = 0, a complex lambda included.
  for (const std::complex<Real> lambda :
       {std::complex<Real>(9.0, 0.3), std::complex<Real>(9.0, -0.3)})
    for (const Real b : {0.0, 0.05}) {
      const std::complex<Real> s = modal_exponent(lambda, b);
      EXPECT_LT(std::abs(s * s + b * lambda * s + lambda), 1e-12 * std::abs(lambda));
      EXPECT_GE(s.imag(), 0.0);
    }
}

// Tests of ArrowheadSystem, COMET's per-cell (N+3) x (N+3) Newton matrix (thesis eq. 5.38).
//
// Asserted, for M = 3 (thesis: f coupled to u, v, w) and M = 5 (f coupled to the conserved
// moments): on random well-conditioned blocks (diagonal dominant D, N = 1000, 512, 1) the
// O(N) Schur-complement solve agrees with a dense Eigen LU of the assembled matrix to 1e-12
// (relative, max norm); multiply() inverts solve() to 1e-12; in-place solving (x_f aliasing
// the right-hand side) gives the same answer; a zero diagonal entry and a singular Schur
// complement raise SolverError.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "core/error.hpp"
#include "physics/gas/comet/arrowhead_system.hpp"

namespace rfmems {
namespace {

template <int M>
ArrowheadSystem<M> random_system(Index n, std::mt19937& rng) {
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  ArrowheadSystem<M> m(n);
  for (Index k = 0; k < n; ++k) {
    m.d(k) = 2.0 + std::abs(u(rng)) * 3.0;
    for (int j = 0; j < M; ++j) {
      m.b(k, j) = u(rng);
      m.c(j, k) = u(rng) / Real(n);  // like the quadrature weights of the moment rows
    }
  }
  using MatM = typename ArrowheadSystem<M>::MatM;
  m.e() = MatM::Identity() * 2.0 + 0.3 * MatM::NullaryExpr([&] { return u(rng); });
  return m;
}

template <int M>
Eigen::MatrixXd dense(const ArrowheadSystem<M>& m) {
  const Index n = m.n_ordinates();
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n + M, n + M);
  for (Index k = 0; k < n; ++k) {
    a(k, k) = m.d(k);
    for (int j = 0; j < M; ++j) {
      a(k, n + j) = m.b(k, j);
      a(n + j, k) = m.c(j, k);
    }
  }
  a.bottomRightCorner(M, M) = m.e();
  return a;
}

template <int M>
void check_against_dense(Index n, unsigned seed) {
  using VecM = typename ArrowheadSystem<M>::VecM;
  std::mt19937 rng(seed);
  const ArrowheadSystem<M> m = random_system<M>(n, rng);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  Eigen::VectorXd rhs(n + M);
  for (Index i = 0; i < n + M; ++i) rhs[i] = u(rng);
  const Eigen::VectorXd ref = dense(m).partialPivLu().solve(rhs);

  std::vector<Real> xf(n);
  VecM xu;
  m.solve(std::span<const Real>(rhs.data(), n), VecM(rhs.tail(M)), xf, xu);
  Real err = 0;
  for (Index k = 0; k < n; ++k) err = std::max(err, std::abs(xf[k] - ref[k]));
  for (int j = 0; j < M; ++j) err = std::max(err, std::abs(xu[j] - ref[n + j]));
  EXPECT_LT(err, 1e-12 * ref.cwiseAbs().maxCoeff()) << "N = " << n << ", M = " << M;

  std::vector<Real> yf(n);
  VecM yu;
  m.multiply(xf, xu, yf, yu);
  Real res = 0;
  for (Index k = 0; k < n; ++k) res = std::max(res, std::abs(yf[k] - rhs[k]));
  for (int j = 0; j < M; ++j) res = std::max(res, std::abs(yu[j] - rhs[n + j]));
  EXPECT_LT(res, 1e-12 * rhs.cwiseAbs().maxCoeff());

  std::vector<Real> inplace(rhs.data(), rhs.data() + n);
  VecM xu2;
  m.solve(inplace, VecM(rhs.tail(M)), inplace, xu2);
  for (Index k = 0; k < n; ++k) EXPECT_EQ(inplace[k], xf[k]);
  EXPECT_EQ((xu2 - xu).norm(), 0.0);
}

TEST(ArrowheadSystem, MatchesDenseLu) {
  check_against_dense<3>(1000, 1);
  check_against_dense<3>(512, 7);
  check_against_dense<3>(1, 3);
  check_against_dense<5>(1000, 2);
  check_against_dense<5>(512, 8);
  check_against_dense<5>(1, 4);
}

TEST(ArrowheadSystem, SingularInputsThrow) {
  std::mt19937 rng(5);
  ArrowheadSystem<3> m = random_system<3>(10, rng);
  std::vector<Real> x(10, 1.0);
  Vec3 xu = Vec3::Ones();
  m.d(3) = 0.0;
  EXPECT_THROW(m.solve(x, xu, x, xu), SolverError);
  ArrowheadSystem<3> z(4);
  for (Index k = 0; k < 4; ++k) z.d(k) = 1.0;  // B = C = E = 0: Schur complement 0
  std::vector<Real> y(4, 1.0);
  EXPECT_THROW(z.solve(y, xu, y, xu), SolverError);
}

}  // namespace
}  // namespace rfmems

// Finite-difference check of d f_eq / dU, the derivative of the discrete-conservative
// equilibrium with respect to the conserved moments U = sum w (1, xi, |xi|^2) f
// (comet/equilibrium_moment_derivative.hpp), the B block of COMET's conserved coupling.
//
// For BGK (m = U) and ESBGK (second moments m m^T/rho + p I + A, A traceless held fixed), on a
// 10 x 10 x 8 grid and a drifting, anisotropic state: each column j by central differences of
// the equilibrium re-solved (kinetic/equilibrium.hpp, Newton to round-off) at U +- h e_j,
// h = 1e-5 |U_j| scale; asserted max |fd - analytic| <= 1e-6 max |analytic| per column. Also
// asserted: the psi-moments of each column are the unit vector e_j to 1e-10 (the derivative
// is that of a discrete-conservative family: sum_k w psi_k df_k/dU = I).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "physics/gas/comet/equilibrium_moment_derivative.hpp"
#include "physics/gas/kinetic/equilibrium.hpp"

namespace rfmems {
namespace {

using Vec5 = Eigen::Matrix<Real, 5, 1>;

// The equilibrium with conserved moments U; for ESBGK with the traceless xi-space part A.
std::vector<Real> equilibrium_of(const Vec5& U, const Mat3& A, const KineticGas& gas,
                                 const VelocityGrid& grid) {
  const Real s = grid.reference_speed;
  const Real rho = U[0];
  const Vec3 m = U.segment<3>(1);
  const Real p = (U[4] - m.squaredNorm() / rho) / 3;  // xi units
  EquilibriumTarget t;
  t.rho = rho;
  t.u = m / rho * s;
  t.covariance = s * s * (p * Mat3::Identity() + A) / rho;
  EquilibriumCoefficients a = equilibrium(t, gas.model, grid);
  std::vector<Real> f(grid.size());
  evaluate_equilibrium(a, grid, f);
  return f;
}

void check(CollisionModel model) {
  const KineticGas gas = KineticGas::argon(model);
  const Real T0 = 273.15, rho0 = 9.28e-6;
  const VelocityGrid grid = VelocityGrid::uniform(10, 10, 8, 3.5 * gas.thermal_speed(T0));
  const Real s = grid.reference_speed;
  // Base state: drifting, anisotropic (ESBGK) Gaussian.
  const Vec3 u(60.0, -25.0, 10.0);
  Mat3 cov = gas.R * T0 * Mat3::Identity();
  Mat3 A = Mat3::Zero();
  if (model == CollisionModel::Esbgk) {
    A << 0.08, 0.03, 0.0, 0.03, -0.05, 0.01, 0.0, 0.01, -0.03;
    A *= rho0 * gas.R * T0 / (s * s);
  }
  const Real p_xi = rho0 * gas.R * T0 / (s * s);
  Vec5 U;
  U[0] = rho0;
  U.segment<3>(1) = rho0 * u / s;
  U[4] = rho0 * (u / s).squaredNorm() + 3 * p_xi;
  const std::vector<Real> f_eq = equilibrium_of(U, A, gas, grid);
  // Its moments are U (discrete conservation).
  const Vec5 Ueq = conserved_moments(grid, f_eq);
  EXPECT_LT((Ueq - U).cwiseAbs().maxCoeff(), 1e-12 * U.cwiseAbs().maxCoeff());
  (void)cov;

  const Index N = grid.size();
  std::vector<Real> d(5 * N);
  equilibrium_conserved_derivative(model, grid, f_eq, d);
  for (int j = 0; j < 5; ++j) {
    const Real h = 1e-5 * (j == 0 || j == 4 ? std::abs(U[j]) : rho0);
    Vec5 Up = U, Um = U;
    Up[j] += h;
    Um[j] -= h;
    const std::vector<Real> fp = equilibrium_of(Up, A, gas, grid),
                            fm = equilibrium_of(Um, A, gas, grid);
    Real diff = 0, scale = 0;
    std::vector<Real> column(N);
    for (Index k = 0; k < N; ++k) {
      const Real fd = (fp[k] - fm[k]) / (2 * h);
      diff = std::max(diff, std::abs(fd - d[5 * k + j]));
      scale = std::max(scale, std::abs(d[5 * k + j]));
      column[k] = d[5 * k + j];
    }
    EXPECT_LT(diff, 1e-6 * scale) << collision_model_name(model) << " column " << j;
    const Vec5 mom = conserved_moments(grid, column);
    for (int i = 0; i < 5; ++i)
      EXPECT_NEAR(mom[i], i == j ? 1.0 : 0.0, 1e-10)
          << collision_model_name(model) << " " << i << j;
  }
}

TEST(EquilibriumMomentDerivative, Bgk) { check(CollisionModel::Bgk); }
TEST(EquilibriumMomentDerivative, Esbgk) { check(CollisionModel::Esbgk); }

}  // namespace
}  // namespace rfmems

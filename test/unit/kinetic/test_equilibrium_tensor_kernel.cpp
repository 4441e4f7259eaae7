// The tensor-product kernel of the discrete equilibrium (kinetic/equilibrium_tensor_kernel.hpp)
// against the direct sums it replaces, on an anisotropic 10 x 8 x 6 grid (unequal extents, so
// an axis mix-up cannot cancel):
//  1. f_k = exp(a . phi(xi_k)) from the three exponential tables equals exp of the dot product
//     to 1e-13 relative (ESBGK and BGK coefficients of a drifting, sheared Gaussian);
//  2. G = w sum g phi, J = w sum g phi phi^T, H = w sum g psi phi^T and the combination
//     g_k phi_k^T Y equal the direct sums to 1e-13 of their largest entry;
//  3. cell_moments (nested central sums) equals macroscopic_state's moments() for a random
//     non-equilibrium f: rho, u, T, pressure tensor and heat flux to 1e-12 relative;
//  4. a grid that is not a tensor product (two ordinates swapped) is detected (valid() false)
//     and its dense path gives the same discrete equilibrium, to 1e-12, with the target's
//     density (1e-13) and velocity on both paths; a repeated solve from the stored state
//     takes no Newton step.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "physics/gas/kinetic/equilibrium.hpp"
#include "physics/gas/kinetic/equilibrium_tensor_kernel.hpp"
#include "physics/gas/kinetic/macroscopic_state.hpp"

using namespace rfmems;

namespace {

const KineticGas kArgon = KineticGas::argon(CollisionModel::Esbgk);
constexpr Real kT0 = 273.15, kRho0 = 9.28e-6;

VelocityGrid anisotropic_grid() {
  const Real c0 = kArgon.thermal_speed(kT0);
  return VelocityGrid::uniform(10, 8, 6, Vec3(3.5 * c0, 3.0 * c0, 2.5 * c0));
}

Eigen::Matrix<Real, 10, 1> esbgk_basis(const Vec3& xi) {
  Eigen::Matrix<Real, 10, 1> phi;
  phi << 1, xi[0], xi[1], xi[2], xi[0] * xi[0], xi[1] * xi[1], xi[2] * xi[2], xi[0] * xi[1],
      xi[0] * xi[2], xi[1] * xi[2];
  return phi;
}

Eigen::Matrix<Real, 5, 1> bgk_basis(const Vec3& xi) {
  Eigen::Matrix<Real, 5, 1> phi;
  phi << 1, xi[0], xi[1], xi[2], xi.squaredNorm();
  return phi;
}

// A drifting, sheared Gaussian target.
EquilibriumTarget sheared_target() {
  EquilibriumTarget t;
  t.rho = kRho0;
  t.u = Vec3(60.0, -25.0, 10.0);
  t.covariance = kArgon.R * kT0 * Mat3::Identity();
  t.covariance(0, 1) = t.covariance(1, 0) = 0.2 * kArgon.R * kT0;
  t.covariance(0, 0) *= 1.3;
  t.covariance(2, 2) *= 0.8;
  return t;
}

std::vector<Real> random_distribution(const VelocityGrid& grid, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> noise(-0.4, 0.4);
  std::vector<Real> f(grid.size());
  const Real RT = kArgon.R * kT0;
  for (Index k = 0; k < grid.size(); ++k) {
    const Vec3 C = grid.c[k] - Vec3(60, -25, 10);
    f[k] = 1e-13 * std::exp(-C.squaredNorm() / (2 * RT) + 0.3 * C.x() * C.y() / (2 * RT)) *
           (1 + noise(rng));
  }
  return f;
}

Real max_abs(const Eigen::MatrixXd& m) { return m.cwiseAbs().maxCoeff(); }

TEST(EquilibriumTensorKernel, ExponentialMatchesDirectEvaluation) {
  const VelocityGrid grid = anisotropic_grid();
  const EquilibriumTensorKernel kernel(grid);
  ASSERT_TRUE(kernel.valid());
  const Real inv_s = 1.0 / grid.reference_speed;
  for (CollisionModel model : {CollisionModel::Esbgk, CollisionModel::Bgk}) {
    const EquilibriumCoefficients a = continuous_coefficients(sheared_target(), model, grid);
    std::vector<Real> f(grid.size());
    kernel.exponential(a.a.data(), a.size, f.data());
    Real err = 0;
    for (Index k = 0; k < grid.size(); ++k) {
      const Vec3 xi = grid.c[k] * inv_s;
      Real e = 0;
      if (a.size == 10)
        e = esbgk_basis(xi).dot(Eigen::Map<const Eigen::Matrix<Real, 10, 1>>(a.a.data()));
      else
        e = bgk_basis(xi).dot(Eigen::Map<const Eigen::Matrix<Real, 5, 1>>(a.a.data()));
      err = std::max(err, std::abs(f[k] - std::exp(e)) / std::exp(e));
    }
    EXPECT_LT(err, 1e-13) << collision_model_name(model);
  }
}

TEST(EquilibriumTensorKernel, MomentSumsMatchDirectSums) {
  const VelocityGrid grid = anisotropic_grid();
  const EquilibriumTensorKernel kernel(grid);
  ASSERT_TRUE(kernel.valid());
  const std::vector<Real> g = random_distribution(grid, 7);
  const Real inv_s = 1.0 / grid.reference_speed;
  Eigen::Matrix<Real, 10, 1> G10 = Eigen::Matrix<Real, 10, 1>::Zero();
  Eigen::Matrix<Real, 10, 10> J10 = Eigen::Matrix<Real, 10, 10>::Zero();
  Eigen::Matrix<Real, 5, 5> J5 = Eigen::Matrix<Real, 5, 5>::Zero();
  Eigen::Matrix<Real, 5, 10> H10 = Eigen::Matrix<Real, 5, 10>::Zero();
  for (Index k = 0; k < grid.size(); ++k) {
    const Vec3 xi = grid.c[k] * inv_s;
    const auto p10 = esbgk_basis(xi);
    const auto p5 = bgk_basis(xi);
    const Real wg = grid.w[k] * g[k];
    G10 += wg * p10;
    J10 += wg * p10 * p10.transpose();
    J5 += wg * p5 * p5.transpose();
    H10 += wg * p5 * p10.transpose();
  }
  Eigen::Matrix<Real, 10, 1> G;
  Eigen::Matrix<Real, 10, 10> J;
  kernel.basis_moments<10>(g.data(), G, &J);
  EXPECT_LT(max_abs(G - G10), 1e-13 * max_abs(G10));
  EXPECT_LT(max_abs(J - J10), 1e-13 * max_abs(J10));
  Eigen::Matrix<Real, 5, 1> g5;
  Eigen::Matrix<Real, 5, 5> j5;
  kernel.basis_moments<5>(g.data(), g5, &j5);
  EXPECT_LT(max_abs(j5 - J5), 1e-13 * max_abs(J5));
  Eigen::Matrix<Real, 5, 10> H;
  kernel.conserved_product_moments<10>(g.data(), H);
  EXPECT_LT(max_abs(H - H10), 1e-13 * max_abs(H10));

  // g_k phi_k^T Y for a random Y (10 x 5).
  const Eigen::Matrix<Real, 10, 5> Y = Eigen::Matrix<Real, 10, 5>::Random();
  std::vector<Real> out(5 * grid.size());
  kernel.basis_combination<10, 5>(g.data(), Y, out.data());
  Real err = 0, scale = 0;
  for (Index k = 0; k < grid.size(); ++k) {
    const Eigen::Matrix<Real, 1, 5> direct =
        g[k] * (esbgk_basis(grid.c[k] * inv_s).transpose() * Y);
    for (int j = 0; j < 5; ++j) {
      err = std::max(err, std::abs(out[5 * k + j] - direct[j]));
      scale = std::max(scale, std::abs(direct[j]));
    }
  }
  EXPECT_LT(err, 1e-13 * scale);
}

TEST(EquilibriumTensorKernel, CellMomentsMatchMacroscopicState) {
  const VelocityGrid grid = anisotropic_grid();
  const std::vector<Real> f = random_distribution(grid, 11);
  const MacroState a = moments(f, grid, kArgon);
  const MacroState b = cell_moments(f, grid, kArgon);
  EXPECT_NEAR(b.rho, a.rho, 1e-12 * a.rho);
  EXPECT_LT((b.u - a.u).norm(), 1e-12 * grid.reference_speed);
  EXPECT_NEAR(b.T, a.T, 1e-12 * a.T);
  EXPECT_LT(max_abs(b.pressure_tensor - a.pressure_tensor), 1e-12 * a.p);
  EXPECT_LT(max_abs(b.stress - a.stress), 1e-12 * a.p);
  EXPECT_LT((b.heat_flux - a.heat_flux).norm(), 1e-12 * a.heat_flux.norm());
  EXPECT_GT(a.heat_flux.norm(), 0.0);
}

TEST(EquilibriumTensorKernel, NonTensorGridTakesTheDensePathToTheSameEquilibrium) {
  const VelocityGrid grid = anisotropic_grid();
  VelocityGrid swapped = grid;
  std::swap(swapped.c[0], swapped.c[1]);
  EXPECT_FALSE(EquilibriumTensorKernel(swapped).valid());
  for (CollisionModel model : {CollisionModel::Esbgk, CollisionModel::Bgk}) {
    const EquilibriumTarget t = sheared_target();
    std::vector<Real> f(grid.size()), fs(grid.size());
    EquilibriumCoefficients a, as;
    solve_equilibrium(t, model, grid, a, f);
    solve_equilibrium(t, model, swapped, as, fs);
    std::swap(fs[0], fs[1]);
    Real err = 0, scale = 0;
    for (Index k = 0; k < grid.size(); ++k) {
      err = std::max(err, std::abs(f[k] - fs[k]));
      scale = std::max(scale, f[k]);
    }
    EXPECT_LT(err, 1e-12 * scale) << collision_model_name(model);
    // Both reproduce the target's density and momentum (discrete conservation).
    for (const auto* values : {&f, &fs}) {
      const MacroState m = moments(*values, grid, KineticGas::argon(model));
      EXPECT_NEAR(m.rho, t.rho, 1e-13 * t.rho);
      EXPECT_LT((m.u - t.u).norm(), 1e-11 * grid.reference_speed);
    }
    // A second solve from the stored state (tensor path) does not move.
    const EquilibriumSolveInfo again = solve_equilibrium(t, model, grid, a, f);
    EXPECT_EQ(again.iterations, 0);
  }
}

}  // namespace

// The velocity grid's quadrature rules (kinetic/velocity_quadrature.hpp) and the discrete
// equilibrium on the non-uniform grids they make (kinetic/velocity_grid.hpp, equilibrium.hpp):
//  1. Gauss-Hermite with N points integrates x^p exp(-x^2) over the line exactly (1e-13 of
//     Gamma((p + 1) / 2)) for p <= 2N - 1, and misses p = 2N (the degree is sharp);
//  2. half-range Gauss-Hermite with N points integrates x^p exp(-x^2) over each half-line
//     exactly for p <= N - 1: the half-range moments a diffuse wall sends and receives;
//  3. every rule is mirror-symmetric; uniform is the midpoint rule of the old grid; the sinh
//     stretch puts its smallest node 1/(the stretch's clustering) nearer to 0 and its weights
//     sum to 2E;
//  4. on product grids of each rule the tensor kernel is valid, its moments equal the direct
//     sums (1e-12), and a specular wall along each axis maps ordinates onto their exact
//     mirror images;
//  5. the discrete conservative equilibrium (BGK and ESBGK) of a drifting, warmer and cooler
//     Maxwellian has the target's density, velocity and temperature to round-off on every
//     rule, the Gauss-Hermite ones with as few as 3 points a direction along the walls.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "physics/gas/kinetic/equilibrium.hpp"
#include "physics/gas/kinetic/equilibrium_tensor_kernel.hpp"
#include "physics/gas/kinetic/macroscopic_state.hpp"
#include "physics/gas/kinetic/velocity_grid.hpp"

using namespace rfmems;

namespace {

Real gaussian_moment(const VelocityAxis& a, int p, bool positive_half) {
  Real s = 0;
  for (std::size_t i = 0; i < a.x.size(); ++i)
    if (!positive_half || a.x[i] > 0)
      s += a.w[i] * std::pow(a.x[i], p) * std::exp(-a.x[i] * a.x[i]);
  return s;
}

TEST(VelocityQuadrature, GaussHermiteIsExactToDegree2NMinus1) {
  for (int n : {3, 4, 6, 8, 16, 24}) {
    const VelocityAxis a = gauss_hermite_axis(n);
    ASSERT_EQ(static_cast<int>(a.x.size()), n);
    for (int p = 0; p <= 2 * n - 1; ++p) {
      const Real exact = p % 2 ? 0.0 : std::tgamma((p + 1) / 2.0);
      EXPECT_NEAR(gaussian_moment(a, p, false), exact, 1e-13 * std::tgamma((p + 1) / 2.0))
          << "n = " << n << ", p = " << p;
    }
    // Degree 2N is not integrated exactly (relative miss n! sqrt(pi) / (2^n Gamma(n + 1/2)),
    // 0.02 at n = 8): the exactness above is the rule's, not luck.
    if (n <= 8) {
      const Real miss = gaussian_moment(a, 2 * n, false) / std::tgamma(n + 0.5) - 1;
      EXPECT_GT(std::abs(miss), 1e-2) << "n = " << n;
    }
  }
}

TEST(VelocityQuadrature, HalfRangeHermiteIsExactOnEachHalf) {
  for (int n : {4, 8, 16, 32, 64}) {
    const VelocityAxis a = half_range_hermite_axis(n);
    ASSERT_EQ(static_cast<int>(a.x.size()), n);
    EXPECT_GT(a.x[n / 2], 0.0);
    for (int p = 0; p <= n - 1; ++p) {
      const Real exact = 0.5 * std::tgamma((p + 1) / 2.0);
      EXPECT_NEAR(gaussian_moment(a, p, true) / exact, 1.0, 1e-13) << "n = " << n << ", p = " << p;
    }
    if (n <= 8) {
      const Real miss = gaussian_moment(a, n, true) / (0.5 * std::tgamma((n + 1) / 2.0)) - 1;
      EXPECT_GT(std::abs(miss), 1e-6) << "n = " << n;
    }
  }
  EXPECT_THROW(half_range_hermite_axis(7), InputError);
}

TEST(VelocityQuadrature, RulesAreSymmetricUniformIsTheMidpointRule) {
  for (VelocityRule rule : {VelocityRule::Uniform, VelocityRule::GaussHermite,
                            VelocityRule::HalfRangeHermite, VelocityRule::SinhStretched}) {
    const VelocityAxis a = velocity_axis(rule, 12, 4.0, 3.0);
    for (int i = 0; i < 12; ++i) {
      EXPECT_EQ(a.x[i], -a.x[11 - i]) << velocity_rule_name(rule);
      EXPECT_EQ(a.w[i], a.w[11 - i]) << velocity_rule_name(rule);
      if (i > 0) {
        EXPECT_GT(a.x[i], a.x[i - 1]) << velocity_rule_name(rule);
      }
    }
    EXPECT_EQ(velocity_rule_from_name(velocity_rule_name(rule)), rule);
  }
  const VelocityAxis u = uniform_axis(10, 3.5);
  for (int i = 0; i < 10; ++i) {
    EXPECT_NEAR(u.x[i], -3.5 + (i + 0.5) * 0.7, 1e-15);
    EXPECT_DOUBLE_EQ(u.w[i], 0.7);
  }
  // sinh: the first cell near 0 is sinh(a ds/2)/sinh(a) E against ds/2 E uniform.
  const VelocityAxis s = sinh_stretched_axis(16, 4.0, 3.0);
  Real sum = 0;
  for (Real w : s.w) sum += w;
  EXPECT_NEAR(sum, 8.0, 0.08);  // midpoint rule of int cosh: 2E to O(a^2 ds^2 / 24)
  EXPECT_NEAR(s.x[8], 4.0 * std::sinh(3.0 / 16) / std::sinh(3.0), 1e-14);
  EXPECT_LT(s.x[8], 0.31 * uniform_axis(16, 4.0).x[8]);  // a / sinh(a) = 0.30
  EXPECT_THROW(velocity_axis(VelocityRule::GaussHermite, 1, 4, 3), InputError);
}

const KineticGas kArgon = KineticGas::argon(CollisionModel::Esbgk);
constexpr Real kT0 = 273.15, kRho0 = 1e-5;

struct GridCase {
  std::string name;
  std::array<VelocityRule, 3> rule;
  std::array<int, 3> n;
};

std::vector<GridCase> grid_cases() {
  using R = VelocityRule;
  return {{"uniform", {R::Uniform, R::Uniform, R::Uniform}, {10, 12, 8}},
          {"gauss_hermite", {R::GaussHermite, R::GaussHermite, R::GaussHermite}, {3, 8, 5}},
          {"wall_half_range", {R::GaussHermite, R::HalfRangeHermite, R::GaussHermite}, {4, 16, 3}},
          {"sinh_stretched", {R::Uniform, R::SinhStretched, R::Uniform}, {10, 16, 10}}};
}

VelocityGrid grid_of(const GridCase& g) {
  return VelocityGrid::product(g.rule, g.n, Vec3(4.0, 4.0, 4.0), 2.5, kArgon.thermal_speed(kT0));
}

TEST(VelocityGridProduct, TensorKernelAndReflectionsOnEveryRule) {
  for (const GridCase& gc : grid_cases()) {
    const VelocityGrid grid = grid_of(gc);
    ASSERT_EQ(grid.size(), Index(gc.n[0]) * gc.n[1] * gc.n[2]);
    const EquilibriumTensorKernel kernel(grid);
    ASSERT_TRUE(kernel.valid()) << gc.name;
    // A drifting Maxwellian at 1.2 T0 sampled on the grid: nested against direct moments.
    std::vector<Real> f(grid.size());
    sample_maxwellian(kRho0, Vec3(40, -30, 20), 1.2 * kT0, kArgon, grid, f);
    const MacroState direct = moments(f, grid, kArgon);
    const MacroState nested = cell_moments(f, grid, kArgon);
    EXPECT_NEAR(nested.rho / direct.rho, 1, 1e-12) << gc.name;
    EXPECT_NEAR((nested.u - direct.u).norm(), 0, 1e-10) << gc.name;
    EXPECT_NEAR(nested.T / direct.T, 1, 1e-12) << gc.name;
    EXPECT_NEAR(kernel.weighted_sum(f.data()) / direct.rho, 1, 1e-12) << gc.name;
    for (int d = 0; d < 3; ++d) {
      Vec3 normal = Vec3::Zero();
      normal[d] = 1;
      const std::vector<Index> map = grid.reflection_map(normal);
      for (Index k = 0; k < grid.size(); ++k) {
        Vec3 image = grid.c[k];
        image[d] = -image[d];
        ASSERT_EQ(grid.c[map[k]], image) << gc.name << " axis " << d << " ordinate " << k;
        ASSERT_EQ(grid.w[map[k]], grid.w[k]) << gc.name;
      }
    }
    // Gauss-Hermite directions have no extent; truncated ones theirs.
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(std::isfinite(grid.extent[d]), velocity_rule_is_truncated(gc.rule[d])) << gc.name;
  }
}

TEST(VelocityGridProduct, DiscreteEquilibriumIsExactOnEveryRule) {
  for (const GridCase& gc : grid_cases())
    for (CollisionModel model : {CollisionModel::Bgk, CollisionModel::Esbgk})
      for (Real temperature : {0.8 * kT0, 1.0 * kT0, 1.3 * kT0}) {
        const KineticGas gas = KineticGas::argon(model);
        const VelocityGrid grid = grid_of(gc);
        const Vec3 u(25, -15, 10);
        const EquilibriumTarget target = maxwellian_target(kRho0, u, temperature, gas);
        SCOPED_TRACE(gc.name + (model == CollisionModel::Bgk ? " bgk" : " esbgk") +
                     " T/T0 = " + std::to_string(temperature / kT0));
        const EquilibriumCoefficients a = equilibrium(target, model, grid);
        std::vector<Real> f(grid.size());
        evaluate_equilibrium(a, grid, f);
        const MacroState m = moments(f, grid, gas);  // direct sums, not the kernel's
        const std::string what = gc.name + (model == CollisionModel::Bgk ? " bgk" : " esbgk") +
                                 " T = " + std::to_string(temperature);
        EXPECT_NEAR(m.rho / kRho0, 1, 1e-13) << what;
        EXPECT_NEAR((m.u - u).norm() / kArgon.thermal_speed(kT0), 0, 1e-13) << what;
        EXPECT_NEAR(m.T / temperature, 1, 1e-12) << what;
        if (model == CollisionModel::Esbgk) {  // every diagonal of the covariance, not its trace
          for (int d = 0; d < 3; ++d) {
            EXPECT_NEAR(m.pressure_tensor(d, d) / (kRho0 * gas.R * temperature), 1, 1e-12) << what;
          }
        }
      }
}

}  // namespace

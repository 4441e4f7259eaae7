// The discrete collision operator Q(f) = nu (f_eq(f) - f) of equilibrium.hpp:
//  1. conserves mass, momentum and energy to <= 1e-12 relative for a random non-equilibrium f
//     (BGK and ESBGK), and ESBGK's f_eq carries exactly Holway's second moments
//     rho (u u^T + Lambda), Lambda = (1/Pr) R T I + (1 - 1/Pr) Theta;
//  2. a discrete Maxwellian at rest is a fixed point (f_eq(f) = f to round-off), and Newton
//     from the continuous start reaches it in a few iterations, from a warm start in <= 1;
//  3. d f_eq / d u (COMET's arrowhead column) matches central differences of the discrete
//     equilibrium to 1e-7 relative;
//  4. homogeneous relaxation df/dt = Q(f) (RK4): the shear stress decays at nu / Pr and the
//     heat flux at nu, so their rate ratio is Pr = 2/3 for ESBGK and 1 for BGK.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "physics/gas/kinetic/equilibrium.hpp"
#include "physics/gas/kinetic/macroscopic_state.hpp"

using namespace rfmems;

namespace {

const KineticGas kArgonBgk = KineticGas::argon(CollisionModel::Bgk);
const KineticGas kArgonEs = KineticGas::argon(CollisionModel::Esbgk);
constexpr Real kT0 = 273.15, kRho0 = 9.28e-6;

VelocityGrid grid_for(int n) {
  return VelocityGrid::uniform(n, n, n, 4.0 * kArgonEs.thermal_speed(kT0));
}

// A non-equilibrium distribution: a drifting, anisotropic Maxwellian times (1 + 0.4 noise).
std::vector<Real> random_distribution(const VelocityGrid& grid, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> noise(-0.4, 0.4);
  std::vector<Real> f(grid.size());
  const Real vx = 2 * kArgonEs.R * kT0, vy = 1.5 * kArgonEs.R * kT0, vz = kArgonEs.R * kT0;
  for (Index k = 0; k < grid.size(); ++k) {
    const Vec3 C = grid.c[k] - Vec3(60, -25, 10);
    f[k] = kRho0 *
           std::exp(-C.x() * C.x() / (2 * vx) - C.y() * C.y() / (2 * vy) -
                    C.z() * C.z() / (2 * vz) + 0.3 * C.x() * C.y() / vx) *
           (1 + noise(rng)) * 1e-7;
  }
  return f;
}

struct Moments {
  Real mass = 0, energy = 0;
  Vec3 momentum = Vec3::Zero();
  Mat3 second = Mat3::Zero();
};

Moments raw_moments(const std::vector<Real>& f, const VelocityGrid& grid) {
  Moments m;
  for (Index k = 0; k < grid.size(); ++k) {
    const Real wf = grid.w[k] * f[k];
    m.mass += wf;
    m.momentum += wf * grid.c[k];
    m.energy += 0.5 * wf * grid.c[k].squaredNorm();
    m.second += wf * grid.c[k] * grid.c[k].transpose();
  }
  return m;
}

void check_conservation(const KineticGas& gas) {
  const VelocityGrid grid = grid_for(12);
  for (unsigned seed : {1u, 2u, 3u}) {
    const std::vector<Real> f = random_distribution(grid, seed);
    const MacroState macro = moments(f, grid, gas);
    const EquilibriumTarget target = equilibrium_target(macro, gas);
    const EquilibriumCoefficients a = equilibrium(target, gas.model, grid);
    std::vector<Real> feq(grid.size());
    evaluate_equilibrium(a, grid, feq);
    const Moments mf = raw_moments(f, grid), me = raw_moments(feq, grid);
    const Real speed = std::sqrt(mf.energy * 2 / mf.mass);
    EXPECT_LE(std::abs(me.mass - mf.mass) / mf.mass, 1e-12);
    EXPECT_LE((me.momentum - mf.momentum).norm() / (mf.mass * speed), 1e-12);
    EXPECT_LE(std::abs(me.energy - mf.energy) / mf.energy, 1e-12);
    if (gas.model == CollisionModel::Esbgk) {
      const Mat3 holway = macro.rho * (macro.u * macro.u.transpose() + target.covariance);
      EXPECT_LE((me.second - holway).norm() / holway.norm(), 1e-12);
      // And it is not the BGK target: the anisotropy of f shows in f_eq.
      EXPECT_GT(std::abs(me.second(0, 0) - me.second(2, 2)) / holway.norm(), 1e-3);
    }
  }
}

}  // namespace

TEST(KineticCollision, BgkConservesMassMomentumEnergy) { check_conservation(kArgonBgk); }
TEST(KineticCollision, EsbgkConservesMassMomentumEnergyAndHolwayMoments) {
  check_conservation(kArgonEs);
}

TEST(KineticCollision, DiscreteMaxwellianAtRestIsAFixedPoint) {
  const VelocityGrid grid = grid_for(10);
  for (const KineticGas& gas : {kArgonBgk, kArgonEs}) {
    // The discrete Maxwellian: exact discrete moments rho, 0, T.
    const EquilibriumCoefficients a0 =
        equilibrium(maxwellian_target(kRho0, Vec3::Zero(), kT0, gas), gas.model, grid);
    std::vector<Real> f(grid.size()), feq(grid.size());
    evaluate_equilibrium(a0, grid, f);
    const MacroState m = moments(f, grid, gas);
    EXPECT_NEAR(m.rho / kRho0, 1, 1e-13);
    EXPECT_NEAR(m.T / kT0, 1, 1e-13);
    EXPECT_LE(m.u.norm(), 1e-12 * gas.thermal_speed(kT0));
    EquilibriumCoefficients a = a0;  // warm start at the solution
    const EquilibriumSolveInfo info =
        solve_equilibrium(equilibrium_target(m, gas), gas.model, grid, a);
    EXPECT_LE(info.iterations, 1);
    evaluate_equilibrium(a, grid, feq);
    Real diff = 0, scale = 0;
    for (Index k = 0; k < grid.size(); ++k) {
      diff = std::max(diff, std::abs(feq[k] - f[k]));
      scale = std::max(scale, f[k]);
    }
    EXPECT_LE(diff / scale, 1e-12) << collision_model_name(gas.model);
    // From the continuous start, Newton needs only a few iterations (quadratic convergence).
    EquilibriumCoefficients cold;
    const EquilibriumSolveInfo cold_info =
        solve_equilibrium(equilibrium_target(m, gas), gas.model, grid, cold);
    EXPECT_LE(cold_info.iterations, 8);
    EXPECT_LE(cold_info.residual, 1e-13);
  }
}

TEST(KineticCollision, VelocityDerivativeMatchesFiniteDifferences) {
  const VelocityGrid grid = grid_for(10);
  for (const KineticGas& gas : {kArgonBgk, kArgonEs}) {
    const std::vector<Real> f = random_distribution(grid, 7);
    const EquilibriumTarget target = equilibrium_target(moments(f, grid, gas), gas);
    const EquilibriumCoefficients a = equilibrium(target, gas.model, grid);
    std::vector<Real> feq(grid.size()), dfdu(3 * grid.size()), fp(grid.size()), fm(grid.size());
    evaluate_equilibrium(a, grid, feq);
    equilibrium_velocity_derivative(a, target, grid, feq, dfdu);
    const Real h = 1e-3;  // m/s, against a thermal speed of 337 m/s
    Real max_err = 0, max_val = 0;
    for (int j = 0; j < 3; ++j) {
      EquilibriumTarget tp = target, tm = target;
      tp.u[j] += h;
      tm.u[j] -= h;
      EquilibriumCoefficients ap = a, am = a;
      solve_equilibrium(tp, gas.model, grid, ap);
      solve_equilibrium(tm, gas.model, grid, am);
      evaluate_equilibrium(ap, grid, fp);
      evaluate_equilibrium(am, grid, fm);
      for (Index k = 0; k < grid.size(); ++k) {
        const Real fd = (fp[k] - fm[k]) / (2 * h);
        max_err = std::max(max_err, std::abs(fd - dfdu[3 * k + j]));
        max_val = std::max(max_val, std::abs(dfdu[3 * k + j]));
      }
    }
    EXPECT_LE(max_err / max_val, 1e-7) << collision_model_name(gas.model);
  }
}

namespace {

// Rates of decay of the shear stress and the heat flux in df/dt = nu (f_eq(f) - f), RK4 over
// t = 1 / nu.
std::pair<Real, Real> relaxation_rates(const KineticGas& gas) {
  const VelocityGrid grid = grid_for(16);
  // A Grad-like perturbation of a drifting Maxwellian: shear stress and heat flux well above
  // the quadrature error of the equilibrium's own heat flux, plus noise.
  std::vector<Real> f(grid.size());
  {
    std::mt19937 rng(5);
    std::uniform_real_distribution<Real> noise(-0.05, 0.05);
    const Real RT = gas.R * kT0;
    for (Index k = 0; k < grid.size(); ++k) {
      const Vec3 C = grid.c[k] - Vec3(30, -20, 10);
      const Real s2 = C.squaredNorm() / (2 * RT);
      f[k] =
          1e-13 * std::exp(-s2) *
          (1 + 0.2 * C.x() * C.y() / RT + 0.1 * C.sum() / std::sqrt(RT) * (s2 - 2.5) + noise(rng));
    }
  }
  const MacroState m0 = moments(f, grid, gas);
  const Real nu = gas.collision_frequency(m0.rho, m0.T);  // rho, T conserved: nu is constant
  EquilibriumCoefficients a;
  auto rhs = [&](const std::vector<Real>& g, std::vector<Real>& dg) {
    const MacroState m = moments(g, grid, gas);
    solve_equilibrium(equilibrium_target(m, gas), gas.model, grid, a);
    evaluate_equilibrium(a, grid, dg);
    for (Index k = 0; k < grid.size(); ++k) dg[k] = nu * (dg[k] - g[k]);
  };
  const int steps = 100;
  const Real dt = 1.0 / nu / steps;
  const Index n = grid.size();
  std::vector<Real> k1(n), k2(n), k3(n), k4(n), tmp(n);
  for (int s = 0; s < steps; ++s) {
    rhs(f, k1);
    for (Index i = 0; i < n; ++i) tmp[i] = f[i] + 0.5 * dt * k1[i];
    rhs(tmp, k2);
    for (Index i = 0; i < n; ++i) tmp[i] = f[i] + 0.5 * dt * k2[i];
    rhs(tmp, k3);
    for (Index i = 0; i < n; ++i) tmp[i] = f[i] + dt * k3[i];
    rhs(tmp, k4);
    for (Index i = 0; i < n; ++i) f[i] += dt / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
  const MacroState m1 = moments(f, grid, gas);
  const Real t = steps * dt;
  EXPECT_NEAR(m1.rho / m0.rho, 1, 1e-12);
  EXPECT_NEAR(m1.T / m0.T, 1, 1e-12);
  // Projections on the initial directions: the equilibrium's own (quadrature-error) heat flux
  // and the noise's small components do not distort the rates.
  const Real rate_stress =
      -std::log((m1.stress.cwiseProduct(m0.stress)).sum() / m0.stress.squaredNorm()) / t;
  const Real rate_heat = -std::log(m1.heat_flux.dot(m0.heat_flux) / m0.heat_flux.squaredNorm()) / t;
  return {rate_stress / nu, rate_heat / nu};
}

}  // namespace

TEST(KineticCollision, EsbgkRelaxationGivesPrandtlTwoThirds) {
  const auto [stress, heat] = relaxation_rates(kArgonEs);
  // ESBGK: shear stress at nu / Pr = 1.5 nu, heat flux at nu.
  EXPECT_NEAR(stress, 1.5, 2e-3);
  EXPECT_NEAR(heat, 1.0, 2e-3);
  EXPECT_NEAR(heat / stress, 2.0 / 3.0, 2e-3);
}

TEST(KineticCollision, BgkRelaxationGivesPrandtlOne) {
  const auto [stress, heat] = relaxation_rates(kArgonBgk);
  EXPECT_NEAR(stress, 1.0, 2e-3);
  EXPECT_NEAR(heat / stress, 1.0, 2e-3);
}

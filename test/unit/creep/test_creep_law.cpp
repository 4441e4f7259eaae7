// The strain-hardening power creep law (materials/creep_law.hpp) and the material point
// operator: analytic stress and hardening derivatives against central differences, the flow
// rule's invariants (traceless, effective rate), the point's Jacobian, and a uniaxial specimen
// under constant stress integrated by IDA against the closed-form integral of the hardening
// law (relative error <= 1e-4 over 500 h), for the thesis's two parameter sets.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../../support/jacobian_check.hpp"
#include "materials/creep_law.hpp"
#include "physics/creep/material_point_creep.hpp"
#include "solvers/ida_integrator.hpp"

using namespace rfmems;

namespace {

// Thesis Table 4.1 (fixed-fixed plates, grain-boundary sliding) and sec. 4.6.2 (Coble creep
// in nanocrystalline nickel).
CreepLaw sliding_law() { return {8.33e-6, 1.8e8, 2, 2, 1e9}; }
CreepLaw coble_law() { return {2.08e-10, 20, 1, 0.5, 0.7e9}; }

Mat3 random_stress(std::mt19937& rng, Real scale) {
  std::uniform_real_distribution<Real> u(-scale, scale);
  Mat3 s;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) s(i, j) = s(j, i) = u(rng);
  return s;
}

Real max_abs(const Mat3& m) { return m.cwiseAbs().maxCoeff(); }

}  // namespace

TEST(CreepLaw, FlowRuleIsDeviatoricWithTheEffectiveRate) {
  std::mt19937 rng(3);
  const CreepLaw law = sliding_law();
  for (int k = 0; k < 5; ++k) {
    const Mat3 sigma = random_stress(rng, 3e8);
    const CreepRate r = law.rate(sigma, 2e-8);
    EXPECT_NEAR(r.strain_rate.trace(), 0.0, 1e-14 * r.effective_rate);
    const Real equivalent = std::sqrt(2.0 / 3.0 * (r.strain_rate.array().square()).sum());
    EXPECT_NEAR(equivalent, r.effective_rate, 1e-12 * r.effective_rate);
    const Real se = CreepLaw::effective_stress(sigma);
    EXPECT_NEAR(r.effective_rate,
                law.A * std::pow(se / (law.sigma_y0 * std::pow(1 + law.B * 2e-8, law.n)), law.m),
                1e-12 * r.effective_rate);
  }
  // Uniaxial tension: eps_xx' = eps_eff', eps_yy' = eps_zz' = -eps_xx'/2.
  Mat3 uni = Mat3::Zero();
  uni(0, 0) = 2e8;
  const CreepRate r = law.rate(uni, 0);
  EXPECT_NEAR(r.strain_rate(0, 0), r.effective_rate, 1e-15 * r.effective_rate);
  EXPECT_NEAR(r.strain_rate(1, 1), -0.5 * r.effective_rate, 1e-15 * r.effective_rate);
  EXPECT_NEAR(r.effective_rate, 8.33e-6 * 0.04, 1e-18);
}

TEST(CreepLaw, DerivativesMatchCentralDifferences) {
  std::mt19937 rng(11);
  for (const CreepLaw& law : {sliding_law(), coble_law(), CreepLaw{1e-4, 30, 4.5, 1.3, 5e8}}) {
    for (int k = 0; k < 4; ++k) {
      const Mat3 sigma = random_stress(rng, 3e8);
      const Mat3 direction = random_stress(rng, 1.0);
      const Real eps = 1e-8 * (k + 1) * (law.B > 1e3 ? 1.0 : 1e4);
      const CreepRate d = law.rate_stress_derivative(sigma, eps, direction);
      const Real h = 1e-3 * 3e8 * 1e-3;
      const CreepRate p = law.rate(sigma + h * direction, eps),
                      m = law.rate(sigma - h * direction, eps);
      const Mat3 fd = (p.strain_rate - m.strain_rate) / (2 * h);
      EXPECT_LT(max_abs(fd - d.strain_rate), 1e-6 * max_abs(d.strain_rate));
      EXPECT_NEAR((p.effective_rate - m.effective_rate) / (2 * h), d.effective_rate,
                  1e-6 * std::abs(d.effective_rate));

      const CreepRate dh = law.rate_hardening_derivative(sigma, eps);
      const Real he = 1e-5 * eps;
      const CreepRate ph = law.rate(sigma, eps + he), mh = law.rate(sigma, eps - he);
      EXPECT_LT(max_abs((ph.strain_rate - mh.strain_rate) / (2 * he) - dh.strain_rate),
                1e-6 * max_abs(dh.strain_rate));
      EXPECT_NEAR((ph.effective_rate - mh.effective_rate) / (2 * he), dh.effective_rate,
                  1e-6 * std::abs(dh.effective_rate));
    }
  }
}

TEST(CreepLaw, BadParametersAreInputErrors) {
  EXPECT_THROW((CreepLaw{1e-6, 1, 0.5, 1, 1e9}.validate()), InputError);
  EXPECT_THROW((CreepLaw{1e-6, 1, 2, 1, 0}.validate()), InputError);
  EXPECT_THROW((CreepLaw{-1, 1, 2, 1, 1e9}.validate()), InputError);
}

TEST(MaterialPointCreep, JacobianMatchesFiniteDifferences) {
  Mat3 sigma = Mat3::Zero();
  sigma(0, 0) = 1.5e8;
  sigma(1, 1) = -4e7;
  sigma(0, 1) = sigma(1, 0) = 3e7;
  MaterialPointCreep point(sliding_law(), [&](Real) { return sigma; });
  std::vector<Real> y{1e-8, -4e-9, -6e-9, 0, 0, 2e-9, 1.2e-8}, yp(7, 0.0);
  const auto check = test_support::check_jacobian(point, 0.0, 1e3, y, yp, 1e-13);
  EXPECT_LT(check.max_row_relative, 1e-6);
}

// Uniaxial specimen under constant stress: IDA (BDF, adaptive) against the closed form
// eps(t) = ((1 + (mn+1) B a t)^(1/(mn+1)) - 1)/B.
TEST(MaterialPointCreep, UniaxialCreepStrainMatchesTheClosedForm) {
  struct Case {
    CreepLaw law;
    Real stress;
  };
  for (const Case& c :
       {Case{sliding_law(), 1.08e8}, Case{sliding_law(), 2e8}, Case{coble_law(), 1.5e8}}) {
    Mat3 sigma = Mat3::Zero();
    sigma(0, 0) = c.stress;
    MaterialPointCreep point(c.law, [&](Real) { return sigma; });
    std::vector<Real> y(7, 0.0);
    const std::vector<Real> yp = point.rates(0, y);
    IdaOptions options;
    options.rtol = 1e-7;
    options.atol = 1e-14 * c.law.uniaxial_strain(c.stress, 1.8e6);
    IdaIntegrator ida(point, options);
    ida.initialize(0, y, yp);
    Real worst = 0;
    for (Real hours : {1.0, 10.0, 100.0, 500.0}) {
      ida.advance(hours * 3600);
      const Real exact = c.law.uniaxial_strain(c.stress, hours * 3600);
      worst = std::max(worst, std::abs(ida.y()[0] / exact - 1));
      EXPECT_NEAR(ida.y()[MaterialPointCreep::kEff], ida.y()[0], 1e-9 * exact);
      EXPECT_NEAR(ida.y()[1], -0.5 * ida.y()[0], 1e-9 * exact);
    }
    EXPECT_LE(worst, 1e-4) << "stress " << c.stress;
    std::printf("uniaxial m=%g sigma=%.3g: eps(500 h) = %.6e, worst rel. error %.2e, %ld steps\n",
                c.law.m, c.stress, c.law.uniaxial_strain(c.stress, 1.8e6), worst,
                ida.stats().steps);
  }
}

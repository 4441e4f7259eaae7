// The analytic Jacobian blocks of the squeeze-film Reynolds operator against central finite
// differences of its residual: dF/dp + c_j dF/dp' and dF/dg + c_j dF/dg', on a skewed,
// jittered, graded mesh, with Veijola rarefaction at 1 atm (Kn ~ 0.03) and at 1 kPa
// (Kn ~ 3, where the rarefaction factor dominates D), and with the kinetic flow-factor table
// (docs/data/flow_factor_bgk.csv), random positive p and gap, Open and Wall edges. Every entry
// (also those outside the pattern, which must be zero) is compared; c_j = 0 checks the flux part,
// c_j = 1e7 /s puts the storage part at the same scale. (test/support/jacobian_check.hpp takes one
// step for y and y'; here the rate step must be much larger than the state step, so the comparison
// is written out.) The IDA adaptor's Jacobian is checked in both of its unknowns (p, and p g /
// g_ref).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>

#include "core/error.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/gas/reynolds_film.hpp"
#include "physics/gas/reynolds_prescribed_motion.hpp"

using namespace rfmems;

namespace {

constexpr double kLength = 200e-6, kWidth = 100e-6;

// 12 x 7 cells over 200 um x 100 um, sheared by 20 degrees, bent, graded and jittered.
Mesh skewed_mesh() {
  BoxSpec spec;
  spec.upper = Vec3(kLength, kWidth, 0);
  spec.n[0] = 12;
  spec.n[1] = 7;
  spec.grading[0] = 1.5;
  auto rng = std::make_shared<std::mt19937>(7);
  return make_structured_mesh(spec, [rng](const Vec3& x) {
    std::uniform_real_distribution<double> jitter(-1.5e-6, 1.5e-6);
    Vec3 y = x;
    y.x() += 0.36 * x.y() + 6e-6 * std::sin(x.y() / kWidth * 3.0) + jitter(*rng);
    y.y() += 5e-6 * std::sin(x.x() / kLength * 4.0) + jitter(*rng);
    return y;
  });
}

std::vector<FilmBoundary> mixed_boundaries(const Mesh& mesh) {
  std::vector<FilmBoundary> bcs(mesh.patches().size());
  for (std::size_t i = 0; i < bcs.size(); ++i)
    bcs[i].kind =
        mesh.patches()[i].name == "bottom" ? FilmBoundary::Kind::Wall : FilmBoundary::Kind::Open;
  return bcs;
}

std::vector<double> uniform(Index n, double lo, double hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> dist(lo, hi);
  std::vector<double> v(n);
  for (double& x : v) x = dist(rng);
  return v;
}

struct State {
  std::vector<double> p, p_rate, gap, gap_rate;
};

State random_state(Index n, double pa) {
  return {uniform(n, 0.6 * pa, 1.4 * pa, 1), uniform(n, -1e3 * pa, 1e3 * pa, 2),
          uniform(n, 1e-6, 3e-6, 3), uniform(n, -0.5, 0.5, 4)};
}

// max |J_fd - J| / max |J| over all n x n entries of J = dF/dy + c_j dF/dy' (CSR values on
// `pattern`), F(y, y') given by `residual`. dF/dy by central differences with a relative step;
// F is affine in y', so dF/dy' by a difference with a step as large as the rates themselves
// (a small one would drown A g in the round-off of the flux terms).
template <class Residual>
double max_difference(const Residual& residual, const CsrPattern& pattern,
                      const std::vector<double>& values, double c_j, const std::vector<double>& y,
                      const std::vector<double>& yp) {
  const Index n = static_cast<Index>(y.size());
  double max_entry = 0;
  for (double v : values) max_entry = std::max(max_entry, std::abs(v));
  double rate_step = 1.0;
  for (double v : yp) rate_step = std::max(rate_step, std::abs(v));

  double max_diff = 0;
  std::vector<double> yy = y, yyp = yp, rp(n), rm(n), column(n);
  for (Index j = 0; j < n; ++j) {
    const double h = 1e-6 * std::abs(y[j]);
    yy[j] = y[j] + h;
    residual(yy, yp, rp);
    yy[j] = y[j] - h;
    residual(yy, yp, rm);
    yy[j] = y[j];
    for (Index i = 0; i < n; ++i) column[i] = (rp[i] - rm[i]) / (2 * h);
    yyp[j] = yp[j] + rate_step;
    residual(y, yyp, rp);
    yyp[j] = yp[j] - rate_step;
    residual(y, yyp, rm);
    yyp[j] = yp[j];
    for (Index i = 0; i < n; ++i) column[i] += c_j * (rp[i] - rm[i]) / (2 * rate_step);
    for (Index i = 0; i < n; ++i) {
      Index pos = pattern.find(i, j);
      double analytic = pos >= 0 ? values[pos] : 0.0;
      max_diff = std::max(max_diff, std::abs(column[i] - analytic));
    }
  }
  return max_diff / max_entry;
}

enum class Block { Pressure, Gap };

double block_difference(const ReynoldsFilm& film, Block block, double c_j, const State& s) {
  std::vector<double> values(film.cell_pattern().nnz());
  if (block == Block::Pressure) {
    film.pressure_jacobian(c_j, s.p, s.p_rate, s.gap, s.gap_rate, values);
    auto residual = [&](const std::vector<double>& p, const std::vector<double>& p_rate,
                        std::vector<double>& r) { film.residual(p, p_rate, s.gap, s.gap_rate, r); };
    return max_difference(residual, film.cell_pattern(), values, c_j, s.p, s.p_rate);
  }
  film.gap_jacobian(c_j, s.p, s.p_rate, s.gap, s.gap_rate, values);
  auto residual = [&](const std::vector<double>& g, const std::vector<double>& g_rate,
                      std::vector<double>& r) { film.residual(s.p, s.p_rate, g, g_rate, r); };
  return max_difference(residual, film.cell_pattern(), values, c_j, s.gap, s.gap_rate);
}

class ReynoldsJacobian : public ::testing::TestWithParam<double> {};

TEST_P(ReynoldsJacobian, BothBlocksMatchFiniteDifferences) {
  Mesh mesh = skewed_mesh();
  GasProperties gas;
  gas.ambient_pressure = GetParam();
  ASSERT_EQ(gas.rarefaction, Rarefaction::Veijola);
  ReynoldsFilm film(mesh, gas, mixed_boundaries(mesh));
  State s = random_state(film.size(), gas.ambient_pressure);
  // The state really exercises rarefaction: Q(Kn) at the extremes of p and g.
  double kn = gas.knudsen(gas.ambient_pressure, 2e-6);
  ASSERT_GT(gas.rarefaction_factor(kn), 1.15);

  for (double c_j : {0.0, 1e7}) {
    double dp = block_difference(film, Block::Pressure, c_j, s);
    double dg = block_difference(film, Block::Gap, c_j, s);
    EXPECT_LE(dp, 1e-6) << "pressure block, c_j = " << c_j;
    EXPECT_LE(dg, 1e-6) << "gap block, c_j = " << c_j;
    std::printf("p_a = %g Pa, c_j = %g: pressure block %.2e, gap block %.2e\n",
                gas.ambient_pressure, c_j, dp, dg);
  }
}

INSTANTIATE_TEST_SUITE_P(AmbientPressures, ReynoldsJacobian, ::testing::Values(101325.0, 1000.0));

// The same with the kinetic solver's flow-factor table: at 1 atm inside the table
// (Kn 0.02 - 0.11), at 1 kPa across its largest Kn (10) into the free-molecular extrapolation.
TEST(ReynoldsJacobianTable, BothBlocksMatchFiniteDifferences) {
  Mesh mesh = skewed_mesh();
  for (double pa : {101325.0, 1000.0}) {
    GasProperties gas;
    gas.ambient_pressure = pa;
    gas.rarefaction = Rarefaction::Table;
    gas.flow_factor_table = std::make_shared<const FlowFactorTable>(
        FlowFactorTable::read(std::string(RFMEMS_SOURCE_DIR) + "/docs/data/flow_factor_bgk.csv"));
    ReynoldsFilm film(mesh, gas, mixed_boundaries(mesh));
    State s = random_state(film.size(), pa);
    if (pa < 1e5) {
      const double kn_max = gas.knudsen(0.6 * pa, 1e-6);
      ASSERT_GT(kn_max, gas.flow_factor_table->max_knudsen());
    }
    for (double c_j : {0.0, 1e7}) {
      double dp = block_difference(film, Block::Pressure, c_j, s);
      double dg = block_difference(film, Block::Gap, c_j, s);
      EXPECT_LE(dp, 1e-6) << "pressure block, p_a = " << pa << ", c_j = " << c_j;
      EXPECT_LE(dg, 1e-6) << "gap block, p_a = " << pa << ", c_j = " << c_j;
      std::printf("table, p_a = %g Pa, c_j = %g: pressure block %.2e, gap block %.2e\n", pa, c_j,
                  dp, dg);
    }
  }
}

TEST(ReynoldsPrescribedMotion, AdaptorJacobianMatchesFiniteDifferences) {
  Mesh mesh = skewed_mesh();
  GasProperties gas;
  ReynoldsFilm film(mesh, gas, mixed_boundaries(mesh));
  const double g0 = 2e-6, omega = 2e5;
  auto gap = [&](const Vec3& x, double t) {
    return g0 *
           (1 + 0.3 * std::sin(x.x() / kLength * 3.0) * std::cos(omega * t) + 0.1 * x.y() / kWidth);
  };
  auto gap_rate = [&](const Vec3& x, double t) {
    return -g0 * 0.3 * std::sin(x.x() / kLength * 3.0) * omega * std::sin(omega * t);
  };
  for (auto unknown : {ReynoldsPrescribedMotion::Unknown::Pressure,
                       ReynoldsPrescribedMotion::Unknown::GapPressure}) {
    ReynoldsPrescribedMotion op(film, gap, gap_rate, unknown);
    const double t = 3e-6;
    auto p = uniform(op.size(), 0.7 * gas.ambient_pressure, 1.3 * gas.ambient_pressure, 5);
    auto y = op.state(t, p);
    auto yp = uniform(op.size(), -1e8, 1e8, 6);
    for (double c_j : {0.0, 1e7}) {
      std::vector<double> values(op.jacobian_pattern().nnz());
      op.jacobian(t, c_j, y, yp, values);
      auto residual = [&](const std::vector<double>& yy, const std::vector<double>& yyp,
                          std::vector<double>& r) { op.residual(t, yy, yyp, r); };
      EXPECT_LE(max_difference(residual, op.jacobian_pattern(), values, c_j, y, yp), 1e-6)
          << "unknown " << static_cast<int>(unknown) << ", c_j = " << c_j;
    }
    // consistent_rate zeroes the residual.
    auto rate = op.consistent_rate(t, y);
    std::vector<double> r(op.size());
    op.residual(t, y, rate, r);
    double scale = 0;
    std::vector<double> zero(op.size(), 0.0), r0(op.size());
    op.residual(t, y, zero, r0);
    for (double v : r0) scale = std::max(scale, std::abs(v));
    for (double v : r) EXPECT_LE(std::abs(v), 1e-12 * scale);
  }
}

TEST(GasProperties, VeijolaFactorAndKnudsenNumber) {
  GasProperties air;
  // Kn = 68 nm / 2 um at 1 atm; 101.325 times larger at 1 kPa.
  EXPECT_NEAR(air.knudsen(101325.0, 2e-6), 0.034, 1e-15);
  EXPECT_NEAR(air.knudsen(1000.0, 2e-6), 0.034 * 101.325, 1e-12);
  // Q = 1 + 9.638 Kn^1.159: 1.19134 at Kn = 0.034 (hand value, log form).
  EXPECT_NEAR(air.rarefaction_factor(0.034), 1.0 + 9.638 * std::exp(1.159 * std::log(0.034)),
              1e-14);
  EXPECT_NEAR(air.rarefaction_factor(0.034), 1.1914, 5e-4);
  // dQ/dKn by central differences.
  const double kn = 0.7, h = 1e-6;
  EXPECT_NEAR(air.rarefaction_factor_derivative(kn),
              (air.rarefaction_factor(kn + h) - air.rarefaction_factor(kn - h)) / (2 * h), 1e-8);
  GasProperties continuum = air;
  continuum.rarefaction = Rarefaction::None;
  EXPECT_EQ(continuum.effective_viscosity(1000.0, 1e-6), air.viscosity);
  EXPECT_NEAR(air.effective_viscosity(101325.0, 2e-6), 1.85e-5 / 1.1914, 1e-8);
}

TEST(ReynoldsFilm, RejectsBadInputAndNonPositiveStates) {
  Mesh mesh = skewed_mesh();
  GasProperties gas;
  EXPECT_THROW(ReynoldsFilm(mesh, gas, {}), InputError);
  gas.viscosity = 0;
  EXPECT_THROW(ReynoldsFilm(mesh, gas, mixed_boundaries(mesh)), InputError);
  ReynoldsFilm film(mesh, GasProperties{}, mixed_boundaries(mesh));
  State s = random_state(film.size(), 1e5);
  std::vector<double> r(film.size());
  s.gap[3] = 0;
  EXPECT_THROW(film.residual(s.p, s.p_rate, s.gap, s.gap_rate, r), RecoverableError);
  s.gap[3] = 1e-6;
  s.p[5] = -1;
  EXPECT_THROW(film.residual(s.p, s.p_rate, s.gap, s.gap_rate, r), RecoverableError);
}

}  // namespace

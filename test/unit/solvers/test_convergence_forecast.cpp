// The contraction-rate forecast of a linearly converging iteration:
//  1. a geometric sequence r_n = rho^n: the rate is rho and the iterations to the tolerance
//     log(tol / r_n) / log(rho), both to round-off; nothing before kMinIterations;
//  2. two modes, a fast one and a slow one that dominates later: the forecast is optimistic
//     (never more iterations than the sequence really needs), the property the early stop
//     rests on;
//  3. a stagnating sequence: no number of iterations suffices, and the stop says "no progress";
//     a forecast that fits in the cap does not stop, nor does a converging sequence with a
//     short flat stretch at its end (a cycle or a few that gain nothing);
//  4. the sequential kinetic solver near the continuum (plane Couette flow, Kn = 1e-4, source
//     iteration's rate near 1) with a cap of 20000: it stops within the first tenth of its cap
//     with the forecast's sentence (measured: 1623), where it would have run to the cap; the
//     residual the
//     iteration really reaches at twice that many iterations is no lower than the forecast
//     said.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../../support/kinetic_slab.hpp"
#include "physics/gas/kinetic/sequential_solver.hpp"
#include "solvers/convergence_forecast.hpp"

using namespace rfmems;

namespace {

std::vector<Real> sequence(int n, auto&& r) {
  std::vector<Real> out;
  for (int k = 1; k <= n; ++k) out.push_back(r(k));
  return out;
}

}  // namespace

TEST(ConvergenceForecast, GeometricSequenceGivesItsRateAndRemainingIterations) {
  const Real rho = 0.97, tol = 1e-8;
  const auto r = sequence(100, [&](int k) { return std::pow(rho, k); });
  const auto f = ConvergenceForecast::of(r, tol);
  ASSERT_TRUE(f);
  EXPECT_NEAR(f->rate, rho, 1e-13);
  const Real exact = std::log(tol) / std::log(rho) - 100;  // rho^(100 + k) = tol
  EXPECT_NEAR(f->remaining, exact, 1e-9 * exact);
  const std::vector<Real> few(r.begin(), r.begin() + ConvergenceForecast::kMinIterations - 1);
  EXPECT_FALSE(ConvergenceForecast::of(few, tol));
}

TEST(ConvergenceForecast, IsOptimisticWhenASlowModeTakesOver) {
  const Real tol = 1e-6;
  auto r = [](int k) { return 0.9 * std::pow(0.5, k) + 0.1 * std::pow(0.995, k); };
  for (int n : {40, 60, 100, 200, 400}) {
    const auto f = ConvergenceForecast::of(sequence(n, r), tol);
    ASSERT_TRUE(f);
    int needed = n;
    while (r(needed) > tol) ++needed;
    EXPECT_LE(f->remaining, Real(needed - n) * (1 + 1e-9)) << "after " << n;
    EXPECT_GE(f->remaining, 0.95 * Real(needed - n)) << "after " << n;  // and close to it
  }
}

TEST(ConvergenceForecast, StagnationIsHopelessAndAFittingForecastIsNot) {
  const auto flat = sequence(50, [](int) { return 3e-3; });
  const auto f = ConvergenceForecast::of(flat, 1e-6);
  ASSERT_TRUE(f);
  EXPECT_TRUE(std::isinf(f->remaining));
  const std::string why = ConvergenceForecast::hopeless(flat, 1e-6, 1000, "the solver");
  EXPECT_NE(why.find("no progress"), std::string::npos) << why;
  const auto fast = sequence(50, [](int k) { return std::pow(0.9, k); });  // 1e-6 at 131
  EXPECT_TRUE(ConvergenceForecast::hopeless(fast, 1e-6, 140, "the solver").empty());
  EXPECT_FALSE(ConvergenceForecast::hopeless(fast, 1e-6, 120, "the solver").empty());
  const auto pause = sequence(60, [](int k) { return std::pow(0.9, std::min(k, 45)); });
  EXPECT_TRUE(ConvergenceForecast::hopeless(pause, 1e-6, 1000, "the solver").empty());
}

TEST(ConvergenceForecast, SequentialKineticSolverStopsEarlyNearTheContinuum) {
  constexpr Real H = 1e-3, T0 = 273.15, kn = 1e-4;
  const FaceGraph g = test_support::kinetic_slab(H, 1, 40);
  const KineticGas gas = KineticGas::argon();
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::specular_wall());
  bcs[g.find_patch("bottom")] = KineticBoundary::diffuse_wall(T0);
  bcs[g.find_patch("top")] = KineticBoundary::diffuse_wall(T0, Vec3(0, 0, 10));
  KineticOperator op(g, VelocityGrid::uniform(6, 6, 6, 3.5 * gas.thermal_speed(T0)), gas, bcs);
  const Real rho = gas.density_for_knudsen(kn, T0, H);
  auto at_rest = [&] {
    std::vector<Real> f(op.size());
    op.initialize(f, [&](const Vec3&) { return GasState{rho, Vec3::Zero(), T0}; });
    return f;
  };

  SequentialOptions capped;
  capped.max_iterations = 20000;
  std::vector<Real> f = at_rest();
  const KineticSolveResult stopped = solve_sequential(op, f, capped);
  std::printf("stopped after %d iterations: %s\n", stopped.iterations, stopped.stop_reason.c_str());
  EXPECT_FALSE(stopped.converged);
  EXPECT_LE(stopped.iterations, capped.max_iterations / 10);
  EXPECT_NE(stopped.stop_reason.find("contraction rate"), std::string::npos);
  const auto forecast = ConvergenceForecast::of(stopped.history, capped.tolerance);
  ASSERT_TRUE(forecast);
  EXPECT_GT(stopped.iterations + forecast->remaining, capped.max_iterations);

  // Run on to 2n: the forecast was optimistic, the residual there is no lower than its
  // extrapolation r_n rho^n.
  SequentialOptions on;
  on.max_iterations = 2 * stopped.iterations;
  on.stop_when_hopeless = false;
  f = at_rest();
  const KineticSolveResult longer = solve_sequential(op, f, on);
  ASSERT_EQ(longer.iterations, on.max_iterations);
  const Real extrapolated = stopped.history.back() * std::pow(forecast->rate, stopped.iterations);
  std::printf("ratio at %d: %.4e, extrapolated %.4e (rate %.6f)\n", longer.iterations,
              longer.residual_ratio, extrapolated, forecast->rate);
  EXPECT_GE(longer.residual_ratio, 0.999 * extrapolated);
}

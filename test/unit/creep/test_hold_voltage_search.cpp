// find_hold_voltage (physics/creep/hold_voltage_search.hpp) on a lumped parallel-plate actuator
// with a closed form: a plate of area S on a spring k above an electrode, gap g0 at rest. Its
// stable equilibria k (g0 - g) = eps0 S V^2 / (2 g^2) exist for g in (2/3 g0, g0], so the
// voltage that holds the gap at g is V(g) = g sqrt(2 k (g0 - g) / (eps0 S)), up to the pull-in
// voltage V(2/3 g0); above it there is no equilibrium. Numbers near the frogleg varactor's
// (k = 100 N/m, S = 2 x 40 x 220 um^2, g0 = 1.8 um: V_PI = 33.3 V).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>

#include "core/error.hpp"
#include "physics/creep/hold_voltage_search.hpp"

using namespace rfmems;

namespace {

constexpr Real kEps0 = 8.8541878128e-12, kK = 100, kArea = 2 * 40e-6 * 220e-6, kG0 = 1.8e-6;

Real exact_voltage(Real g) { return g * std::sqrt(2 * kK * (kG0 - g) / (kEps0 * kArea)); }

// The stable equilibrium at V by bisection on (2/3 g0, g0] (to round-off), or none.
std::optional<Real> lumped_gap(Real v) {
  auto h = [v](Real g) { return kK * (kG0 - g) * g * g - 0.5 * kEps0 * kArea * v * v; };
  Real lo = 2 * kG0 / 3, hi = kG0;  // h(lo) >= 0 at or below pull-in, h(hi) <= 0
  if (h(lo) < 0) return std::nullopt;
  for (int i = 0; i < 200 && hi - lo > 1e-17; ++i) {
    const Real mid = 0.5 * (lo + hi);
    (h(mid) >= 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST(HoldVoltageSearch, FindsTheClosedFormVoltageInAFewTrials) {
  const Real target = 1.43e-6;
  const HoldVoltageSearchResult r = find_hold_voltage(lumped_gap, target);
  EXPECT_NEAR(r.gap, target, 1e-12);
  // |dV/dg| ~ 3e7 V/m here, so the gap tolerance 1e-12 m bounds the voltage error by ~3e-5 V.
  EXPECT_NEAR(r.voltage, exact_voltage(target), 5e-5);
  EXPECT_EQ(r.trials.front().voltage, 0.0);
  EXPECT_LE(r.trials.size(), 12u);  // superlinear (false position, Illinois), not bisection
  std::printf("V = %.9f V (exact %.9f V), %zu trials\n", r.voltage, exact_voltage(target),
              r.trials.size());
}

TEST(HoldVoltageSearch, BisectsBackFromVoltagesWithoutEquilibrium) {
  // Just above the fold (g = 0.68 g0, V = 0.9997 V_PI); the first guess 100 V has no
  // equilibrium, nor do some chord steps.
  const Real target = 0.68 * kG0;
  HoldVoltageSearchOptions options;
  options.first_voltage = 100;
  const HoldVoltageSearchResult r = find_hold_voltage(lumped_gap, target, options);
  EXPECT_NEAR(r.gap, target, 1e-12);
  EXPECT_NEAR(r.voltage, exact_voltage(target), 1e-3);
  EXPECT_FALSE(r.trials[1].gap.has_value());
}

TEST(HoldVoltageSearch, RejectsGapsItCannotHold) {
  // Beyond the fold (the unstable branch) and at or above the rest gap.
  EXPECT_THROW(find_hold_voltage(lumped_gap, 0.6 * kG0), SolverError);
  EXPECT_THROW(find_hold_voltage(lumped_gap, kG0), SolverError);
  EXPECT_THROW(find_hold_voltage(lumped_gap, 1.1 * kG0), SolverError);
}

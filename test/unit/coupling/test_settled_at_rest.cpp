// The settle rule (coupling/settled_at_rest.hpp) on synthetic overdamped histories, a first-
// order creep x' = -(F_el - K x) / c whose film force c x' carries the static imbalance:
//   - below the fold, towards the stable equilibrium x_eq = x_s (1 - e^{-t/tau}): settles
//     once |v| <= s v_peak, i.e. at t = tau ln(1/s), within s |x_s| of x_eq;
//   - just above the fold (the saddle-node normal form x' = -(mu + (x - x_f)^2 / l)), where the
//     motion slows down near x_f but the film still carries the imbalance mu c: never settles;
//   - at rest beyond the fold (near the saddle): never settles;
//   - an underdamped swing's extreme (v = 0, no film force, above the fold): not at rest;
//   - a slow passage within 0.1 % above the fold voltage, whose film share falls below s: looks
//     settled by the forces alone, not once the rule knows V > V_qs.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "coupling/settled_at_rest.hpp"

using namespace rfmems;

namespace {

constexpr double kFold = -1e-7, kElectrostatic = -1e-4;  // [m], [N]

struct Watched {
  bool settled = false;
  double time = 0, x = 0;
};

// Integrates x' = rate(x) from 0 by forward Euler in dt; the film force is c x' with c such
// that the initial film force equals the electrostatic force (no elastic force at rest).
// voltage, fold_voltage: the run's step and V_qs (0: the rule without the bound).
Watched watch(const std::function<double(double)>& rate, double dt, double t_end,
              double voltage = 0, double fold_voltage = 0) {
  SettledAtRest rule(kSettleTolerance, kFold, fold_voltage);
  const double c = kElectrostatic / rate(0.0);
  Watched out;
  double x = 0;
  for (double t = dt; t <= t_end; t += dt) {
    const double v = rate(x);
    x += dt * v;
    if (rule.at_step(t, x, v, c * v, kElectrostatic, voltage)) return {true, t, x};
  }
  return out;
}

}  // namespace

TEST(SettledAtRest, OverdampedCreepSettlesAtItsEquilibrium) {
  const double tau = 1e-6, x_s = 0.6 * kFold;
  const Watched w = watch([&](double x) { return (x_s - x) / tau; }, 1e-3 * tau, 50 * tau);
  ASSERT_TRUE(w.settled);
  EXPECT_NEAR(w.time, tau * std::log(1 / kSettleTolerance), 0.01 * tau);
  EXPECT_NEAR(w.x, x_s, 1.01 * kSettleTolerance * std::abs(x_s));
}

TEST(SettledAtRest, SlowPassageJustAboveTheFoldDoesNotSettle) {
  // mu: the imbalance at the fold, 6 % of the initial rate (1.03 V_qs); l sets the curvature.
  const double r0 = -1.0, mu = 0.06, l = kFold * kFold / (1 - mu);  // rate(0) = r0
  const Watched w =
      watch([&](double x) { return r0 * (mu + (x - kFold) * (x - kFold) / l); }, 1e-11, 2e-6);
  EXPECT_FALSE(w.settled);
}

TEST(SettledAtRest, RestBeyondTheFoldIsNotStable) {
  const double tau = 1e-6, x_saddle = 1.3 * kFold;
  const Watched w = watch([&](double x) { return (x_saddle - x) / tau; }, 1e-3 * tau, 50 * tau);
  EXPECT_FALSE(w.settled);
}

TEST(SettledAtRest, OffWithoutTheFoldOrTolerance) {
  EXPECT_FALSE(SettledAtRest(kSettleTolerance, 0.0).armed());
  EXPECT_FALSE(SettledAtRest(0.0, kFold).armed());
}

TEST(SettledAtRest, UnderdampedExtremeIsNotAtRest) {
  // x = x_s (1 - cos w t): the first extreme at t = pi / w, 2 x_s above the fold, no film.
  const double w = 2 * M_PI * 1e5, x_s = 0.4 * kFold;
  SettledAtRest rule(kSettleTolerance, kFold);
  bool settled = false;
  for (double t = 1e-3 / w; t <= 1.5 * M_PI / w; t += 1e-3 / w)
    settled = settled || rule.at_step(t, x_s * (1 - std::cos(w * t)), x_s * w * std::sin(w * t),
                                      0.0, kElectrostatic);
  EXPECT_FALSE(settled);
}

TEST(SettledAtRest, NoRestAboveTheFoldVoltage) {
  // mu = 2 (V / V_qs - 1) = 0.1 % of the initial rate: the film's share at the bottleneck is
  // below s = 1 %, so the forces alone cannot tell the passage from a rest.
  const double r0 = -1.0, mu = 1e-3, l = kFold * kFold / (1 - mu);
  auto rate = [&](double x) { return r0 * (mu + (x - kFold) * (x - kFold) / l); };
  const double v_qs = 50, v = v_qs * (1 + mu / 2);
  EXPECT_TRUE(watch(rate, 1e-10, 2e-5).settled);
  EXPECT_FALSE(watch(rate, 1e-10, 2e-5, v, v_qs).settled);
  // Below V_qs the bound does not get in the way (the creep of the first test).
  const double tau = 1e-6, x_s = 0.6 * kFold;
  EXPECT_TRUE(
      watch([&](double x) { return (x_s - x) / tau; }, 1e-3 * tau, 50 * tau, 0.99 * v_qs, v_qs)
          .settled);
}

// The past-fold rule (coupling/past_unstable_equilibrium.hpp):
//   - on the parallel-plate spring's exact curve, x (1 - x / g)^2 = (4/27) g (V / V_qs)^2, the
//     threshold is the first unstable sample at or below V: never short of the exact unstable
//     equilibrium x_u(V), at most one sample spacing plus the margin beyond it; 0 above V_qs;
//   - on the one-degree-of-freedom switch m x'' + c x' + k x = F_el(x, V), for damping ratios
//     from 0 to 5 and step voltages on both sides of V_dyn and V_qs: a run that fires never
//     turns back afterwards and touches down, and every run that touches down fires first;
//   - on the default plate (cases/switch_plate, 40 x 4 cells, Reynolds film at 1 atm, zeta 0.012,
//     many modes): the bisection gives the same V_dyn, lower end and pull-in time with the rule
//     as without it (the upper end's touch-down time from its step run again), and the lower
//     end's whole history to end_time - it turns back several times - stays short of the
//     threshold even without the margin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "coupling/dynamic_pull_in.hpp"
#include "coupling/past_unstable_equilibrium.hpp"
#include "coupling/pull_in_study.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/switch_scene.hpp"
#include "coupling/switch_system.hpp"
#include "io/case_file.hpp"

using namespace rfmems;

namespace {

constexpr double kGapLength = 1.0;  // lengths in units of the gap, voltages of V_qs
constexpr int kSamples = 40;

// V / V_qs at the deflection x (< 0) of the parallel-plate spring.
double plate_law_voltage(double x) {
  const double s = -x / kGapLength;
  return std::sqrt(27.0 / 4.0 * s * (1 - s) * (1 - s));
}

// The exact unstable equilibrium at r = V / V_qs < 1 (bisection on s in [1/3, 1]).
double exact_unstable(double r) {
  double a = 1.0 / 3.0, b = 1.0;
  for (int i = 0; i < 100; ++i) {
    const double m = 0.5 * (a + b);
    (plate_law_voltage(-m * kGapLength) > r ? a : b) = m;
  }
  return -0.5 * (a + b) * kGapLength;
}

// The curve as trace_pull_in samples it: -k/N 0.9 g, k = 1..N, and the fold at g/3.
QuasiStaticPullIn plate_law_curve() {
  QuasiStaticPullIn qs;
  const double fold = -kGapLength / 3;
  for (int k = 1; k <= kSamples; ++k) {
    const double x = -0.9 * kGapLength * k / kSamples;
    qs.curve.push_back({x, plate_law_voltage(x), kGapLength + x, x >= fold, 0});
  }
  qs.curve.push_back({fold, 1.0, kGapLength + fold, true, 0});
  std::sort(qs.curve.begin(), qs.curve.end(), [](const PullInPoint& p, const PullInPoint& q) {
    return p.displacement > q.displacement;
  });
  qs.pull_in_voltage = 1.0;
  qs.pull_in_displacement = fold;
  return qs;
}

}  // namespace

TEST(PastUnstableEquilibrium, ThresholdIsNeverShortOfTheUnstableEquilibrium) {
  const FoldBranch fold = FoldBranch::of(plate_law_curve());
  const double spacing = 0.9 * kGapLength / kSamples;
  for (const double margin : {0.0, kPastFoldMargin}) {
    const PastUnstableEquilibrium rule(fold, margin);
    ASSERT_TRUE(rule.armed());
    for (double r = 0.3; r <= 1.0; r += 0.01) {
      const double x_u = exact_unstable(r), x = rule.threshold(r);
      EXPECT_LE(x, x_u) << r;
      EXPECT_GE(x, x_u - spacing - margin * kGapLength / 3 - 1e-12) << r;
    }
    EXPECT_EQ(rule.threshold(1.001), 0.0);          // above V_qs: no equilibrium at all
    EXPECT_TRUE(std::isinf(rule.threshold(0.05)));  // below the last sample: never
  }
  EXPECT_FALSE(PastUnstableEquilibrium(fold, -1).armed());
  EXPECT_FALSE(PastUnstableEquilibrium(FoldBranch{}, kPastFoldMargin).armed());
  // Fires only moving towards the electrode, and once.
  PastUnstableEquilibrium rule(fold, kPastFoldMargin);
  const double deep = rule.threshold(0.9) - 0.01;
  EXPECT_FALSE(rule.at_step(0.9, deep, +1.0));
  EXPECT_TRUE(rule.at_step(0.9, deep, -1.0));
  EXPECT_FALSE(rule.at_step(0.9, deep, -1.0));
  EXPECT_TRUE(rule.past());
}

TEST(PastUnstableEquilibrium, OneDegreeOfFreedomPullsInOnceFired) {
  // s'' + 2 zeta s' + s = (4/27) r^2 / (1 - s)^2 in the time 1 / omega_0, s = -x / g from rest
  // (RK4); touch-down at s = 0.98 (the drivers' contact gap).
  const FoldBranch fold = FoldBranch::of(plate_law_curve());
  int fired_below_qs = 0, pulled_in = 0;
  for (const double zeta : {0.0, 0.1, 0.5, 1.7, 5.0}) {
    for (double r = 0.85; r <= 1.05 + 1e-9; r += 0.005) {
      PastUnstableEquilibrium rule(fold, kPastFoldMargin);
      auto accel = [&](double s, double v) {
        return 4.0 / 27.0 * r * r / ((1 - s) * (1 - s)) - s - 2 * zeta * v;
      };
      double s = 0, v = 0;
      bool fired = false, turned_after = false, touched = false;
      const double dt = 2e-3, t_end = 400;
      for (double t = 0; t < t_end && !touched; t += dt) {
        const double k1s = v, k1v = accel(s, v);
        const double k2s = v + 0.5 * dt * k1v, k2v = accel(s + 0.5 * dt * k1s, k2s);
        const double k3s = v + 0.5 * dt * k2v, k3v = accel(s + 0.5 * dt * k2s, k3s);
        const double k4s = v + dt * k3v, k4v = accel(s + dt * k3s, k4s);
        s += dt / 6 * (k1s + 2 * k2s + 2 * k3s + k4s);
        v += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        touched = s >= 0.98;
        if (fired) turned_after = turned_after || v <= 0;
        if (!fired && !touched && rule.at_step(r, -s * kGapLength, -v * kGapLength)) {
          fired = true;
          fired_below_qs += r < 1;
        }
      }
      pulled_in += touched;
      EXPECT_FALSE(turned_after) << "zeta " << zeta << ", V/V_qs " << r;
      EXPECT_EQ(fired, touched) << "zeta " << zeta << ", V/V_qs " << r;
    }
  }
  // The rule has something to decide: underdamped runs overshoot past x_u below V_qs.
  EXPECT_GT(fired_below_qs, 5);
  EXPECT_GT(pulled_in, 20);
}

TEST(PastUnstableEquilibrium, DefaultPlateKeepsItsBisectionAndTurnsBackShortOfTheThreshold) {
  const std::string path = std::string(RFMEMS_SOURCE_DIR) + "/cases/switch_plate/case.yaml";
  const CaseFile cf = CaseFile::load(path, {});
  SwitchScene scene =
      build_switch_scene(cf.root(), std::filesystem::path(path).parent_path().string());
  const PullInSettings st = read_pull_in_settings(cf.root(), scene);
  const QuasiStaticPullIn qs = trace_pull_in(*scene.actuation, scene.control, st.quasi_static);
  const auto system = make_switch_system(scene);
  DynamicOptions with = st.run;
  with.fold = FoldBranch::of(qs);
  DynamicOptions without = with;
  without.stop_past_fold = false;
  const Real low = 0.8 * qs.pull_in_voltage, high = 1.02 * qs.pull_in_voltage;
  const DynamicPullIn a =
      find_dynamic_pull_in(*system, scene.control, low, high, st.tolerance, with);
  const DynamicPullIn b =
      find_dynamic_pull_in(*system, scene.control, low, high, st.tolerance, without);
  EXPECT_EQ(a.voltage, b.voltage);
  EXPECT_EQ(a.lower, b.lower);
  EXPECT_EQ(a.pull_in_time, b.pull_in_time);
  EXPECT_GT(a.past_fold_runs, 0);
  EXPECT_EQ(b.past_fold_runs, 0);
  EXPECT_TRUE(a.upper_past_fold);
  // docs/pull-in.md, "The pull-in time and its check": (173.5823, 173.9059] V, and t_PI at
  // rtol 1e-3 within 1 % of the converged 11.82289 us (rtol 1e-6 at 173.9059 V; the driver's
  // own estimate of its error is 0.37 %).
  EXPECT_NEAR(a.voltage, 173.9059, 1e-3);
  EXPECT_NEAR(a.lower, 173.5823, 1e-3);
  EXPECT_NEAR(a.pull_in_time / 11.82289e-6, 1.0, 0.01);

  // The lower end, the run that comes closest without pulling in, to end_time.
  DynamicOptions whole = st.run;
  whole.stop_at_turning = false;
  const DynamicRun run = run_dynamic(
      *system, scene.control, [&](Real) { return a.lower; }, whole);
  ASSERT_FALSE(run.pulled_in);
  const Real x_fold = std::abs(qs.pull_in_displacement);
  const Real bare = PastUnstableEquilibrium(with.fold, 0.0).threshold(a.lower);
  const Real rule = PastUnstableEquilibrium(with.fold, kPastFoldMargin).threshold(a.lower);
  // x_u lies between the threshold's sample and the one before it (the fold, or shallower).
  const std::vector<Real>& xs = with.fold.unstable_control;
  const auto k = std::find(xs.begin(), xs.end(), bare) - xs.begin();
  const Real shallower = k > 0 ? xs[k - 1] : qs.pull_in_displacement;
  std::printf(
      "V_qs %.4f V, V_dyn (%.4f, %.4f] V, t_PI %.3f us; runs %d / %d, past fold %d; "
      "lower end's extreme %.4f |x_fold|, x_u in [%.4f, %.4f], threshold %.4f\n",
      qs.pull_in_voltage, a.lower, a.voltage, 1e6 * a.pull_in_time, a.runs, b.runs,
      a.past_fold_runs, run.extreme_control / x_fold, bare / x_fold, shallower / x_fold,
      rule / x_fold);
  EXPECT_GT(run.extreme_control, bare);
  EXPECT_GT(run.extreme_control, rule);
}

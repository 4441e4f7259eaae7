// The turning-back rule (coupling/turning_back.hpp) on synthetic control histories, its two
// root functions watched for sign changes on a fine time grid as IDA does between steps (a
// root return at the sample after the change, where the functions are evaluated afresh):
//   - a creep towards the electrode (the damped plate's fundamental, zeta = 0.54, towards a
//     deflection it never leaves) carrying a weakly damped higher mode whose velocity
//     reverses the control's many times: no turning (the velocity zero alone, the former
//     rule, would have ended the run at the first reversal);
//   - an underdamped step response (zeta = 0.0115, the default switch at 1 atm) with the same
//     higher mode: a turning, reported at the first extreme t = pi / w_d.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "coupling/turning_back.hpp"
#include "physics/structure/step_response_fit.hpp"

using namespace rfmems;

namespace {

constexpr double kW = 2 * M_PI * 1.31e5, kStatic = -3e-7;

struct Watched {
  bool turned = false;
  double turning_time = 0, detected_at = 0;
  int velocity_reversals = 0;  // rising zeros of the velocity after moving down
};

// x(t) (and its velocity by central differences) on a grid of dt, up to t_end.
Watched watch(const std::function<double(double)>& x, double t_end) {
  TurningBack rule(kTurningRetreat);
  const double dt = 1e-3 / kW, h = 1e-4 * dt;
  auto velocity = [&](double t) { return (x(t + h) - x(t - h)) / (2 * h); };
  Watched out;
  double g_prev[2];
  rule.roots(x(0), 0.0, g_prev);
  for (double t = dt; t <= t_end; t += dt) {
    double g[2];
    rule.roots(x(t), velocity(t), g);
    int flag[2];
    for (int k = 0; k < 2; ++k)
      flag[k] = g_prev[k] < 0 && g[k] >= 0 ? 1 : g_prev[k] > 0 && g[k] <= 0 ? -1 : 0;
    if (flag[0] > 0 && x(t) < 0) ++out.velocity_reversals;
    if ((flag[0] != 0 || flag[1] != 0) && rule.at_root(t, x(t), flag[0], flag[1])) {
      out.turned = true;
      out.turning_time = rule.turning_time();
      out.detected_at = t;
    }
    rule.roots(x(t), velocity(t), g_prev);
  }
  return out;
}

// A weakly damped higher mode at 7 w from rest, 0.5 % of the static deflection.
double higher_mode(double t) {
  return 0.005 * kStatic * (1 - step_response_shape(t, 0.005, 7 * kW));
}

}  // namespace

TEST(TurningBack, HigherModeWigglesOnADampedCreepDoNotTurn) {
  // The creep: x_s (1 - phi) at zeta = 1.5 (the fundamental past the point where the film and
  // the electrostatic softening make it overdamped), monotone towards x_s.
  auto x = [](double t) {
    return kStatic * (1 - step_response_shape(t, 1.5, kW)) + higher_mode(t);
  };
  const Watched w = watch(x, 40 * 2 * M_PI / kW);
  EXPECT_GT(w.velocity_reversals, 20);  // the former rule's trigger is there
  EXPECT_FALSE(w.turned);
}

TEST(TurningBack, UnderdampedReturnTurnsAtTheFirstExtreme) {
  const double zeta = 0.0115, wd = kW * std::sqrt(1 - zeta * zeta);
  auto x = [&](double t) {
    return kStatic * (1 - step_response_shape(t, zeta, kW)) + higher_mode(t);
  };
  const Watched w = watch(x, 2 * 2 * M_PI / kW);
  ASSERT_TRUE(w.turned);
  // The extreme of the sum: the higher mode's phase moves it by at most its own period.
  EXPECT_NEAR(w.turning_time * wd / M_PI, 1.0, 2.0 / 7);
  // Detected once back by 2 % of the ~2 x_s swing: (1 - cos(w (t - t_ext))) x_s ~ 0.04 x_s,
  // about 0.29 rad after the extreme (plus the higher mode's shift).
  EXPECT_GT(w.detected_at, w.turning_time);
  EXPECT_LT((w.detected_at - w.turning_time) * kW, 0.29 + 2 * M_PI / 7);
}

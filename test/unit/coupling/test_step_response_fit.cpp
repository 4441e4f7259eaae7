// The fundamental's damping ratio and frequency by the step-response fit
// (physics/structure/step_response_fit.hpp, through free_response in coupling/dynamic_pull_in.hpp)
// on sampled step responses from rest x = x_s (1 - phi(t; zeta, w)) with known zeta (light,
// squeeze-film-like and overdamped), plus a weakly damped higher mode of 0.5 % of the
// static deflection at 7 w (the damped plate's case, docs/pull-in.md, "Damped switches"), sampled
// at 80 points per fundamental period over 6 periods, as the driver's 0.1 us output at 130 kHz.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/dynamic_pull_in.hpp"
#include "physics/structure/step_response_fit.hpp"

using namespace rfmems;

namespace {

constexpr double kF = 1.3e5, kW = 2 * M_PI * kF, kStatic = -3e-8;

std::vector<DynamicSample> history(double zeta, double higher) {
  std::vector<DynamicSample> h;
  const double dt = 1 / (80 * kF);
  for (int i = 0; i <= 80 * 6; ++i) {
    const double t = i * dt;
    const double x = kStatic * (1 - step_response_shape(t, zeta, kW)) +
                     higher * kStatic * (1 - step_response_shape(t, 0.005, 7 * kW));
    h.push_back({t, x, 0, 0, 0});
  }
  return h;
}

}  // namespace

// phi(0) = 1, phi'(0) = 0, phi -> 0, and the under-, critically and overdamped forms meet.
TEST(StepResponseShape, StartsAtRestAndIsContinuousAcrossCriticalDamping) {
  for (const double zeta : {0.01, 0.5, 1.0, 2.0}) {
    EXPECT_DOUBLE_EQ(step_response_shape(0, zeta, kW), 1.0);
    const double h = 1e-3 / kW;
    EXPECT_NEAR((step_response_shape(h, zeta, kW) - 1) / h, 0.0, 1e-2 * kW) << zeta;
    EXPECT_LT(std::abs(step_response_shape(2000 / kW, zeta, kW)), 1e-6) << zeta;
  }
  for (const double t : {0.3 / kW, 2 / kW, 10 / kW}) {
    const double critical = (1 + kW * t) * std::exp(-kW * t);
    EXPECT_NEAR(step_response_shape(t, 1 - 1e-7, kW), critical, 1e-6);
    EXPECT_NEAR(step_response_shape(t, 1 + 1e-7, kW), critical, 1e-6);
  }
}

TEST(StepResponseFit, RecoversTheFundamentalUnderAHigherMode) {
  for (const double zeta : {0.01, 0.5, 2.0}) {
    for (const double higher : {0.0, 0.005}) {
      const FreeResponse r = free_response(history(zeta, higher));
      ASSERT_TRUE(r.fitted);
      // With the higher mode: its fast rise is part of the early motion, which alone carries
      // an overdamped response's zeta and w (4 % at zeta = 2).
      const double tol = higher == 0 ? 1e-6 : zeta < 1 ? 0.03 : 0.06;
      EXPECT_NEAR(r.fit_damping_ratio / zeta, 1.0, tol) << "zeta " << zeta << " higher " << higher;
      if (zeta < 1) {
        EXPECT_NEAR(r.fit_frequency / (kF * std::sqrt(1 - zeta * zeta)), 1.0, tol) << zeta;
      } else {  // no log decrement to prefer: the fit's figures are the reported ones
        EXPECT_FALSE(r.from_log_decrement);
        EXPECT_NEAR(r.natural_frequency / kF, 1.0, tol) << "zeta " << zeta << " higher " << higher;
        EXPECT_EQ(r.frequency, 0.0);
      }
      // The misfit is the higher mode's oscillation (rms ~ 0.7 of its amplitude at most).
      EXPECT_LT(r.residual, higher > 0 ? 0.8 * higher : 1e-6) << zeta;
    }
  }
}

// The reason for the fit: at zeta = 0.5 the fundamental has one overshoot, and the extrema the
// logarithmic decrement uses are the higher mode's (its frequency, and its light damping).
TEST(StepResponseFit, LogDecrementMeasuresTheHigherModeWhereTheFitDoesNot) {
  const FreeResponse r = free_response(history(0.5, 0.005));
  ASSERT_GE(r.log_decrement.swings, 8);
  EXPECT_GT(r.log_decrement.frequency, 4 * kF);
  EXPECT_LT(r.log_decrement.damping_ratio, 0.1);
  EXPECT_NEAR(r.damping_ratio, 0.5, 0.015);
}

// Light damping: the log decrement's extrema are the fundamental's (its frequency is the
// fit's), and its figures are reported; at zeta = 0.5 they are not (the higher mode's).
TEST(StepResponseFit, LogDecrementReportedWhereItsExtremaAreTheFundamentals) {
  const FreeResponse light = free_response(history(0.01, 0.005));
  EXPECT_TRUE(light.from_log_decrement);
  EXPECT_EQ(light.damping_ratio, light.log_decrement.damping_ratio);
  EXPECT_NEAR(light.fit_damping_ratio / 0.01, 1.0, 0.03);
  EXPECT_FALSE(free_response(history(0.5, 0.005)).from_log_decrement);
}

TEST(StepResponseFit, NothingToFitWithoutMotion) {
  std::vector<DynamicSample> h;
  for (int i = 0; i <= 100; ++i) h.push_back({i * 1e-8, 0.0, 0, 0, 0});
  EXPECT_FALSE(free_response(h).fitted);
  h.resize(5);
  EXPECT_FALSE(free_response(h).fitted);
}

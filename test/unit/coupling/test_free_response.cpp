// The logarithmic decrement (physics/structure/free_response.hpp: damping ratio from the decay of
// the extrema, damped frequency from their spacing) on sampled damped cosines x_eq + a
// exp(-zeta w t) cos(w_d t) with known zeta and w_d, and the voltage waveforms' shapes. The
// step-response fit that free_response reports: test_step_response_fit.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/dynamic_pull_in.hpp"

using namespace rfmems;

TEST(LogDecrement, RecoversDampingRatioAndFrequency) {
  for (const double zeta : {0.001, 0.012, 0.1}) {
    const double f = 1.3e5, w = 2 * M_PI * f / std::sqrt(1 - zeta * zeta);  // f: damped
    std::vector<double> t, x;
    const double dt = 1 / (f * 80);  // 80 samples per period, as a 0.1 us output at 130 kHz
    for (int i = 0; i <= 80 * 5; ++i) {
      t.push_back(i * dt);
      x.push_back(-1e-7 -
                  2e-7 * std::exp(-zeta * w * t.back()) * std::cos(2 * M_PI * f * t.back()));
    }
    const LogDecrement r = log_decrement(t, x);
    EXPECT_GE(r.swings, 8);
    EXPECT_NEAR(r.damping_ratio, zeta, 2e-4 + 1e-2 * zeta) << "zeta " << zeta;
    EXPECT_NEAR(r.frequency / f, 1.0, 1e-3);
  }
}

TEST(LogDecrement, NothingToMeasureWithoutOscillation) {
  std::vector<double> t, x;
  for (int i = 0; i <= 100; ++i) {
    t.push_back(i * 1e-8);
    x.push_back(-1e-7 * (1 - std::exp(-i / 20.0)));
  }
  EXPECT_EQ(log_decrement(t, x).swings, 0);
}

TEST(VoltageWaveform, Shapes) {
  VoltageWaveform step;
  EXPECT_DOUBLE_EQ(step.at(100)(0.0), 100);
  VoltageWaveform ramp{VoltageWaveform::Kind::Ramp, 2e-6, 0, 0};
  EXPECT_DOUBLE_EQ(ramp.at(100)(0.5e-6), 25);
  EXPECT_DOUBLE_EQ(ramp.at(100)(5e-6), 100);
  VoltageWaveform pulse{VoltageWaveform::Kind::Pulse, 0, 10e-6, 0.3};
  EXPECT_DOUBLE_EQ(pulse.at(100)(9e-6), 100);
  EXPECT_DOUBLE_EQ(pulse.at(100)(10e-6), 30);
}

// The creep run (physics/creep/creep_run.hpp) on a problem with a closed-form life: a bar of
// length L under a constant stress sigma0, extending towards a stop at distance g0.
//
//   state [u | e]:  F_u = E (u/L - e) - sigma0 = 0            (algebraic: equilibrium)
//                   F_e = e' - A (sigma / sigma_y(e))^m         (differential: the creep law)
//   sigma = E (u/L - e) = sigma0,   sigma_y = sigma_y0 (1 + B e)^n
//
// so e(t) is the uniaxial closed form of materials/creep_law.hpp and the gap g0 - u reaches
// the threshold g_c when e = e_c = (g0 - g_c)/L - sigma0/E, at
//   t_life = ((1 + B e_c)^(k+1) - 1) / ((k+1) B a),   a = A (sigma0/sigma_y0)^m, k = m n.
// Asserted: the IDA gap root finds t_life to 1e-5; the explicit run's interpolated crossing
// converges at first order in dt; a run restarted from its checkpoint ends bit for bit where
// the uninterrupted run ends (implicit and explicit); a checkpoint of other settings is
// refused.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "core/error.hpp"
#include "materials/creep_law.hpp"
#include "physics/creep/creep_run.hpp"

namespace rfmems {
namespace {

constexpr Real kE = 200e9, kL = 1e-3, kSigma0 = 100e6, kHours = 3600;
const CreepLaw kLaw{1e-8, 20, 1, 0.5, 0.7e9};
constexpr Real kLifeStrain = 2e-3;                                   // e_c
constexpr Real kGap0 = 5e-6, kThreshold = kGap0 - kL * (kLifeStrain + kSigma0 / kE);

class BarCreep : public CreepSystem {
 public:
  BarCreep() {
    pattern_.row_ptr = {0, 2, 4};
    pattern_.col_idx = {0, 1, 0, 1};
  }
  Index size() const override { return 2; }
  Index structural_size() const override { return 1; }
  std::vector<Real> differential_components() const override { return {0, 1}; }
  Real stress(std::span<const Real> y) const { return kE * (y[0] / kL - y[1]); }
  Real rate(std::span<const Real> y) const {
    return kLaw.effective_rate(std::abs(stress(y)), y[1]);
  }
  void residual(Real, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override {
    r[0] = stress(y) - kSigma0;
    r[1] = yp[1] - rate(y);
  }
  const CsrPattern& jacobian_pattern() const override { return pattern_; }
  void jacobian(Real, Real c_j, std::span<const Real> y, std::span<const Real>,
                std::span<Real> v) override {
    const Real s = stress(y), r = rate(y);
    const Real dr_ds = kLaw.m * r / s;
    const Real dr_de = -kLaw.m * r * kLaw.yield_stress_derivative(y[1]) / kLaw.yield_stress(y[1]);
    v[0] = kE / kL;
    v[1] = -kE;
    v[2] = -dr_ds * kE / kL;
    v[3] = c_j - (dr_ds * -kE + dr_de);
  }
  void creep_rates(Real, std::span<const Real> y, std::span<Real> rates) override {
    rates[0] = rate(y);
  }
  void equilibrate(Real, std::span<Real> y) override { y[0] = kL * (y[1] + kSigma0 / kE); }
  void initial_state(Real t, std::vector<Real>& y, std::vector<Real>& yp) override {
    y.assign(2, 0.0);
    equilibrate(t, y);
    yp = {kL * rate(y), rate(y)};
  }

 private:
  CsrPattern pattern_;
};

Real closed_form_life() {
  const Real a = kLaw.A * std::pow(kSigma0 / kLaw.sigma_y0, kLaw.m), k = kLaw.m * kLaw.n;
  return (std::pow(1 + kLaw.B * kLifeStrain, k + 1) - 1) / ((k + 1) * kLaw.B * a);
}

CreepRunModel bar_model() {
  CreepRunModel m;
  m.make_system = [] { return std::make_unique<BarCreep>(); };
  m.min_gap = [](std::span<const Real> y) { return kGap0 - y[0]; };
  m.min_gap_rate = [](std::span<const Real>, std::span<const Real> yp) { return -yp[0]; };
  m.series_columns = {"u", "e"};
  m.sample = [](CreepSystem&, Real, std::span<const Real> y) {
    return std::vector<double>{y[0], y[1]};
  };
  return m;
}

CreepRunSettings settings(Real end, int outputs) {
  CreepRunSettings s;
  for (int k = 1; k <= outputs; ++k) s.output_times.push_back(end * k / outputs);
  s.rtol = 1e-8;
  s.atol = 1e-14;
  s.krylov = false;
  s.gap_threshold_event = true;
  s.gap_threshold = kThreshold;
  s.settings_hash = "bar";
  return s;
}

std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("rfmems_creep_lifetime_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

TEST(CreepLifetime, IdaGapRootFindsTheClosedFormLife) {
  const Real life = closed_form_life();
  ASSERT_GT(life, 100 * kHours);
  const CreepRunResult r = run_creep(bar_model(), settings(2 * life, 20));
  std::printf("closed-form life %.6f h, IDA root %.6f h (%ld steps, %ld segments)\n",
              life / kHours, r.lifetime / kHours, r.steps, r.segments);
  EXPECT_EQ(r.end, CreepRunResult::End::GapThreshold);
  EXPECT_NEAR(r.lifetime, life, 1e-5 * life);
  EXPECT_NEAR(kGap0 - r.state[0], kThreshold, 1e-6 * kThreshold);
  // The last series row and output are the event.
  EXPECT_EQ(r.series_times.back(), r.lifetime);
  EXPECT_EQ(r.outputs.back().time, r.lifetime);
}

TEST(CreepLifetime, ExplicitCrossingConvergesAtFirstOrder) {
  const Real life = closed_form_life();
  Real previous = 0;
  for (Real dt : {40 * kHours, 10 * kHours, 2.5 * kHours}) {
    CreepRunSettings s = settings(2 * life, 7);
    s.integration = CreepRunSettings::Integration::Explicit;
    s.explicit_dt = dt;
    const CreepRunResult r = run_creep(bar_model(), s);
    ASSERT_EQ(r.end, CreepRunResult::End::GapThreshold);
    const Real error = std::abs(r.lifetime / life - 1);
    std::printf("explicit dt = %5.1f h: life %.5f h, relative error %.3e\n", dt / kHours,
                r.lifetime / kHours, error);
    if (previous > 0) {
      EXPECT_GT(previous / error, 3.0);  // 4 for first order
      EXPECT_LT(previous / error, 5.5);
    }
    previous = error;
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(CreepLifetime, RestartFromACheckpointIsBitForBit) {
  for (auto integration :
       {CreepRunSettings::Integration::Implicit, CreepRunSettings::Integration::Explicit}) {
    CreepRunSettings s = settings(0.8 * closed_form_life(), 12);
    s.gap_threshold_event = false;
    s.integration = integration;
    s.explicit_dt = 5 * kHours;
    s.checkpoint_path = scratch("bar.checkpoint.h5");
    s.checkpoint_every_steps = 1;  // at every output but the last: the file holds output 11
    const CreepRunResult full = run_creep(bar_model(), s);
    EXPECT_EQ(full.checkpoints_written, 11);
    const Checkpoint cp = read_checkpoint(s.checkpoint_path);
    EXPECT_EQ(cp.time, s.output_times[10]);
    s.checkpoint_path.clear();
    const CreepRunResult again = run_creep(bar_model(), s, &cp, "bar.checkpoint.h5");
    EXPECT_TRUE(again.restarted);
    EXPECT_EQ(again.segments, 1);
    EXPECT_EQ(again.state, full.state);  // exact
    EXPECT_EQ(again.series, full.series);
    EXPECT_EQ(again.series_times, full.series_times);
    EXPECT_EQ(again.steps, full.steps);

    CreepRunSettings other = s;
    other.settings_hash = "another bar";
    EXPECT_THROW(run_creep(bar_model(), other, &cp, "bar.checkpoint.h5"), InputError);
  }
}

}  // namespace
}  // namespace rfmems

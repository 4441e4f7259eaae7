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
//
// The collapse event on a lumped held switch with a closed-form creep-induced pull-in: a
// spring k whose rest position p creeps at a constant rate c towards an electrode at g0, held
// by a parallel-plate force at voltage V:
//   F_x = k (x - p) - eps0 S V^2 / (2 (g0 - x)^2) = 0,   F_p = p' - c
// The equilibrium exists while the gap from the rest position g0 - p exceeds the pull-in gap
// of the voltage, (27 eps0 S V^2 / (8 k))^(1/3) (V_PI^2 = 8 k (g0 - p)^3 / (27 eps0 S)), so
// the life is t_f = (g0 - (27 eps0 S V^2 / (8 k))^(1/3)) / c, where x' ~ 1/sqrt(t_f - t).
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
constexpr Real kLifeStrain = 2e-3;  // e_c
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
  std::printf("closed-form life %.6f h, IDA root %.6f h (%ld steps, %ld segments)\n", life / kHours,
              r.lifetime / kHours, r.steps, r.segments);
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

constexpr Real kEps0 = 8.8541878128e-12, kSpring = 10, kArea = 1e-8, kGapHeld = 3e-6;
constexpr Real kRestRate = 1e-6 / (1000 * kHours);  // c: 1 um per 1000 h

class HeldSpringCreep : public CreepSystem {
 public:
  explicit HeldSpringCreep(Real voltage) : v2_(voltage * voltage) {
    pattern_.row_ptr = {0, 2, 3};
    pattern_.col_idx = {0, 1, 1};
  }
  Index size() const override { return 2; }
  Index structural_size() const override { return 1; }
  std::vector<Real> differential_components() const override { return {0, 1}; }
  Real force(Real x) const { return kEps0 * kArea * v2_ / (2 * (kGapHeld - x) * (kGapHeld - x)); }
  Real force_derivative(Real x) const { return 2 * force(x) / (kGapHeld - x); }
  void residual(Real, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override {
    if (y[0] >= kGapHeld) throw RecoverableError("held spring: gap closed");
    r[0] = kSpring * (y[0] - y[1]) - force(y[0]);
    r[1] = yp[1] - kRestRate;
  }
  const CsrPattern& jacobian_pattern() const override { return pattern_; }
  void jacobian(Real, Real c_j, std::span<const Real> y, std::span<const Real>,
                std::span<Real> v) override {
    v[0] = kSpring - force_derivative(y[0]);
    v[1] = -kSpring;
    v[2] = c_j;
  }
  void creep_rates(Real, std::span<const Real>, std::span<Real> rates) override {
    rates[0] = kRestRate;
  }
  void equilibrate(Real, std::span<Real> y) override {  // Newton from the rest position
    Real x = y[1];
    for (int it = 0; it < 100; ++it) {
      const Real r = kSpring * (x - y[1]) - force(x), d = kSpring - force_derivative(x);
      if (!(d > 0)) throw SolverError("held spring: no equilibrium (past the fold)");
      x -= r / d;
      if (!(x < kGapHeld)) throw SolverError("held spring: no equilibrium (gap closed)");
      if (std::abs(r) < 1e-15 * kSpring * kGapHeld) break;
    }
    y[0] = x;
  }
  void initial_state(Real t, std::vector<Real>& y, std::vector<Real>& yp) override {
    y.assign(2, 0.0);
    equilibrate(t, y);
    yp = {kSpring * kRestRate / (kSpring - force_derivative(y[0])), kRestRate};
  }

 private:
  Real v2_;
  CsrPattern pattern_;
};

Real held_pull_in_voltage() {
  return std::sqrt(8 * kSpring * std::pow(kGapHeld, 3) / (27 * kEps0 * kArea));
}
Real held_life(Real voltage) {
  const Real gap_pi = std::cbrt(27 * kEps0 * kArea * voltage * voltage / (8 * kSpring));
  return (kGapHeld - gap_pi) / kRestRate;
}

CreepRunModel held_model(Real voltage) {
  CreepRunModel m;
  m.make_system = [voltage] { return std::make_unique<HeldSpringCreep>(voltage); };
  m.min_gap = [](std::span<const Real> y) { return kGapHeld - y[0]; };
  m.min_gap_rate = [](std::span<const Real>, std::span<const Real> yp) { return -yp[0]; };
  m.series_columns = {"x"};
  m.sample = [](CreepSystem&, Real, std::span<const Real> y) { return std::vector<double>{y[0]}; };
  return m;
}

TEST(CreepLifetime, CollapseRootFindsTheClosedFormCreepInducedPullIn) {
  for (Real ratio : {0.5, 0.8, 0.95}) {
    const Real voltage = ratio * held_pull_in_voltage(), life = held_life(voltage);
    for (Real fraction : {1e-3, 1e-4}) {
      CreepRunSettings s;
      for (int k = 1; k <= 10; ++k) s.output_times.push_back(1.5 * life * k / 10);
      s.rtol = 1e-8;
      s.atol = 1e-16;
      s.krylov = false;
      s.collapse_event = true;
      s.collapse_fraction = fraction;
      const CreepRunResult r = run_creep(held_model(voltage), s);
      std::printf("V = %.2f V_PI, eps %.0e: life %.6f h (closed form %.6f h), %s, %ld steps\n",
                  ratio, fraction, r.lifetime / kHours, life / kHours, to_string(r.end).c_str(),
                  r.steps);
      EXPECT_EQ(r.end, CreepRunResult::End::Collapse);
      EXPECT_LE(r.lifetime, life);  // the root fires before the fold
      EXPECT_NEAR(r.lifetime, life, 10 * fraction * fraction * life + 1e-6 * life);
    }
  }
}

}  // namespace
}  // namespace rfmems

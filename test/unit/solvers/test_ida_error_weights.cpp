// IDA's error weights (IdaOptions::atols, suppress_algebraic) and the fixed step that may cut
// (fixed_step_min), on a system whose step counts can be predicted:
//
//   slow oscillator   u1' = v1, v1' = -w1^2 u1       (w1 = 1, amplitude 1)
//   fast oscillator   u2' = v2, v2' = -w2^2 u2       (w2 = 200, amplitude 1e-4)
//   algebraic         0 = z - a sin(W t)             (W = 300, a = 1e-4)
//
// The slow oscillator is "the quantity of interest". With one tiny scalar atol, the local
// error test follows the fast oscillator and the fast algebraic forcing: BDF's local error of a
// mode grows like (w h)^(q+1) times its amplitude, so h shrinks with 1/w2. With atol 1e-2 on
// the fast oscillator (100 x its amplitude, velocity atol scaled by w2) and z left out of the
// test, the step is set by the slow oscillator alone: the same step count as the slow
// oscillator integrated by itself (to a few steps), and u1 as accurate.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "solvers/ida_integrator.hpp"

using namespace rfmems;

namespace {

constexpr double w1 = 1.0, w2 = 200.0, W = 300.0, a = 1e-4, fast_amplitude = 1e-4;

class SlowFastSystem : public SystemOperator {
 public:
  // with_fast false: the slow oscillator alone (2 unknowns).
  explicit SlowFastSystem(bool with_fast) : n_(with_fast ? 5 : 2) {
    auto row = [&](std::initializer_list<Index> cols) {
      for (Index c : cols) pattern_.col_idx.push_back(c);
      pattern_.row_ptr.push_back(pattern_.nnz());
    };
    row({0, 1});
    row({0, 1});
    if (n_ == 5) {
      row({2, 3});
      row({2, 3});
      row({4});
    }
  }
  Index size() const override { return n_; }
  std::vector<Real> differential_components() const override {
    std::vector<Real> id(n_, 1.0);
    if (n_ == 5) id[4] = 0.0;
    return id;
  }
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override {
    if (fail_after >= 0 && t > fail_after && !failed_once) {
      failed_once = true;
      throw RecoverableError("a Newton iterate the model refuses");
    }
    r[0] = yp[0] - y[1];
    r[1] = yp[1] + w1 * w1 * y[0];
    if (n_ == 5) {
      r[2] = yp[2] - y[3];
      r[3] = yp[3] + w2 * w2 * y[2];
      r[4] = y[4] - a * std::sin(W * t);
    }
  }
  const CsrPattern& jacobian_pattern() const override { return pattern_; }
  void jacobian(Real, Real c_j, std::span<const Real>, std::span<const Real>,
                std::span<Real> v) override {
    v[0] = c_j, v[1] = -1;
    v[2] = w1 * w1, v[3] = c_j;
    if (n_ == 5) {
      v[4] = c_j, v[5] = -1;
      v[6] = w2 * w2, v[7] = c_j;
      v[8] = 1;
    }
  }
  // Consistent state at t = 0: u1 = 1, u2 = fast_amplitude, both at rest; z = 0.
  void initial_state(std::vector<Real>& y, std::vector<Real>& yp) const {
    y.assign(n_, 0.0);
    yp.assign(n_, 0.0);
    y[0] = 1, yp[1] = -w1 * w1;
    if (n_ == 5) y[2] = fast_amplitude, yp[3] = -w2 * w2 * fast_amplitude;
  }
  double fail_after = -1;
  bool failed_once = false;

 private:
  Index n_;
  CsrPattern pattern_;
};

struct Result {
  long steps;
  double u1;
};

Result integrate(SlowFastSystem& system, const IdaOptions& options, double t_end) {
  IdaIntegrator ida(system, options);
  std::vector<Real> y, yp;
  system.initial_state(y, yp);
  ida.initialize(0.0, y, yp);
  ida.advance(t_end);
  return {ida.stats().steps, ida.y()[0]};
}

IdaOptions base_options() {
  IdaOptions o;
  o.rtol = 1e-6;
  o.atol = 1e-10;
  o.max_order = 5;
  o.max_steps = 1000000;
  return o;
}

}  // namespace

TEST(IdaErrorWeights, VectorAtolAndSuppressedAlgebraicLetTheSlowModeSetTheStep) {
  const double t_end = 2 * M_PI;  // one slow period: ~300 fast ones
  SlowFastSystem slow(false), both(true);
  const Result alone = integrate(slow, base_options(), t_end);

  const Result scalar = integrate(both, base_options(), t_end);

  IdaOptions weighted = base_options();
  const double fast_atol = 100 * fast_amplitude;
  weighted.atols = {1e-10, 1e-10, fast_atol, fast_atol * w2, 1e-10};
  weighted.suppress_algebraic = true;
  const Result w = integrate(both, weighted, t_end);

  // The slow oscillator alone is accurate: the baseline is a faithful one.
  EXPECT_NEAR(alone.u1, std::cos(w1 * t_end), 1e-5);
  // Scalar atol: the fast parts set the step (w2 / w1 = 200: many times the slow count).
  EXPECT_GT(scalar.steps, 5 * alone.steps)
      << "scalar " << scalar.steps << ", alone " << alone.steps;
  // Weighted: the step count of the slow oscillator by itself (a few start-up steps apart), u1
  // as accurate as alone.
  EXPECT_LE(std::abs(w.steps - alone.steps), 0.15 * alone.steps + 5)
      << "weighted " << w.steps << ", alone " << alone.steps;
  EXPECT_NEAR(w.u1, std::cos(w1 * t_end), 1e-5);
}

TEST(IdaErrorWeights, OnlyTheAtolOfTheFastOscillatorIsNotEnough) {
  // With the fast oscillator loosened but z still in the error test, the algebraic forcing
  // (W = 300) keeps the step small: the suppression is what removes it.
  const double t_end = 2 * M_PI;
  SlowFastSystem slow(false), both(true);
  const Result alone = integrate(slow, base_options(), t_end);
  IdaOptions o = base_options();
  const double fast_atol = 100 * fast_amplitude;
  o.atols = {1e-10, 1e-10, fast_atol, fast_atol * w2, 1e-10};
  const Result r = integrate(both, o, t_end);
  EXPECT_GT(r.steps, 5 * alone.steps) << "z in the test: " << r.steps << ", alone " << alone.steps;
}

TEST(IdaErrorWeights, WrongNumberOfAtolsIsAnError) {
  SlowFastSystem both(true);
  IdaOptions o = base_options();
  o.atols = {1e-10, 1e-10};
  IdaIntegrator ida(both, o);
  std::vector<Real> y, yp;
  both.initial_state(y, yp);
  EXPECT_THROW(ida.initialize(0.0, y, yp), SolverError);
}

TEST(IdaFixedStep, MayCutAfterAFailedSolveWhenAllowed) {
  // A residual that refuses one iterate at t > 0.3: an exact fixed step cannot retry, one
  // allowed to cut (fixed_step_min) retries smaller and grows back to the fixed step.
  const double h = 0.01;
  IdaOptions o;
  o.max_order = 1;
  o.fixed_step = h;
  {
    SlowFastSystem s(false);
    s.fail_after = 0.3;
    IdaIntegrator ida(s, o);
    std::vector<Real> y, yp;
    s.initial_state(y, yp);
    ida.initialize(0.0, y, yp);
    EXPECT_THROW(ida.advance(1.0), SolverError);
  }
  SlowFastSystem s(false);
  s.fail_after = 0.3;
  o.fixed_step_min = 1e-4 * h;
  IdaIntegrator ida(s, o);
  std::vector<Real> y, yp;
  s.initial_state(y, yp);
  ida.initialize(0.0, y, yp);
  ida.advance(1.0);
  EXPECT_TRUE(s.failed_once);
  EXPECT_NEAR(ida.time(), 1.0, 1e-12);
  // One cut (by IDA's 1/4) and the way back at most doubling per step: a few more steps than
  // the 100 of the uncut run, not many.
  EXPECT_GT(ida.stats().steps, 100);
  EXPECT_LT(ida.stats().steps, 110);
  EXPECT_EQ(ida.stats().last_step, h);
  // Backward Euler's amplitude decay over t = 1 at w h = 0.01: (1 + h^2)^(-t/2h) = 0.9950;
  // the cut steps damp a little less (measured: 1.2e-5 more). Held to 1e-4.
  const double energy = std::hypot(ida.y()[0], ida.y()[1]);
  EXPECT_NEAR(energy, std::pow(1 + h * h, -0.5 / h), 1e-4);
}

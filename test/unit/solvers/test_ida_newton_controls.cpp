// IDA's Newton and step controls (IdaOptions::nonlinear_convergence, max_newton_iterations,
// jacobian_cj_change, step_growth_threshold, max_step_growth, convergence_failure_cut,
// initial_step) on the lumped parallel-plate actuator, in units of the gap g0, the spring k and
// the mass m (time in 1/omega_0):
//
//   x' = v,   v' = -x + beta / (1 - x)^2,   x(0) = v(0) = 0,   contact at 1 - x = 0.02
//
// Without damping the energy is conserved, v^2 / 2 = beta (1 / (1 - x) - 1) - x^2 / 2, so the
// pull-in time is the quadrature t_PI = int_0^{x_c} dx / v(x) (x = s^2 removes the 1/sqrt(x)
// of the start from rest). beta = 0.14 is 1.12 x the dynamic pull-in load 1/8 (V / V_dyn =
// 1.06, as the plate switch at 180 V): the actuator lingers near the unstable equilibrium
// x = 0.5, so t_PI measures the whole trajectory, and ends in the 1/g^2 touch-down where
// Newton may fail (a trial state at or beyond the electrode is refused, as the switch's
// ParallelPlateActuation does).
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "solvers/ida_integrator.hpp"

using namespace rfmems;

namespace {

constexpr double beta = 0.14, contact = 0.02;

class LumpedActuator : public SystemOperator {
 public:
  LumpedActuator() {
    pattern_.row_ptr = {0, 2, 4};
    pattern_.col_idx = {0, 1, 0, 1};
  }
  Index size() const override { return 2; }
  std::vector<Real> differential_components() const override { return {1.0, 1.0}; }
  void residual(Real, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override {
    const Real gap = 1 - y[0];
    if (!(gap > 0)) throw RecoverableError("trial state beyond the electrode");
    r[0] = yp[0] - y[1];
    r[1] = yp[1] + y[0] - beta / (gap * gap);
  }
  const CsrPattern& jacobian_pattern() const override { return pattern_; }
  void jacobian(Real, Real c_j, std::span<const Real> y, std::span<const Real>,
                std::span<Real> v) override {
    const Real gap = 1 - y[0];
    v[0] = c_j, v[1] = -1;
    v[2] = 1 - 2 * beta / (gap * gap * gap), v[3] = c_j;
  }

 private:
  CsrPattern pattern_;
};

// t_PI by composite Simpson in s = sqrt(x) (integrand 2 s / v(s^2), 2 / sqrt(2 beta) at 0).
double quadrature_pull_in_time() {
  const int n = 20000;
  const double s_end = std::sqrt(1 - contact), h = s_end / n;
  auto f = [](double s) {
    if (s == 0) return 2 / std::sqrt(2 * beta);
    const double x = s * s;
    return 2 * s / std::sqrt(2 * (beta * (1 / (1 - x) - 1) - 0.5 * x * x));
  };
  double sum = f(0) + f(s_end);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * f(i * h);
  return sum * h / 3;
}

struct PullIn {
  double t;
  IntegratorStats stats;
};

PullIn pull_in(const IdaOptions& options) {
  LumpedActuator system;
  IdaIntegrator ida(system, options);
  ida.initialize(0.0, std::vector<Real>{0.0, 0.0}, std::vector<Real>{0.0, beta});
  ida.set_roots(1, [](Real, std::span<const Real> y, std::span<const Real>, std::span<Real> g) {
    g[0] = 1 - y[0] - contact;
  });
  EXPECT_EQ(ida.advance(20.0), IdaIntegrator::Status::Root);
  return {ida.time(), ida.stats()};
}

IdaOptions options(double rtol) {
  IdaOptions o;
  o.rtol = rtol;
  o.atol = rtol;  // x and v are O(1) in these units
  o.max_order = 5;
  return o;
}

}  // namespace

TEST(LumpedActuator, QuadratureIsConverged) {
  // Simpson's error ~ h^4: the quadrature with 20000 intervals agrees with a high-order ODE
  // solution (DOP853 at rtol 1e-12: 4.80720974) and is its own reference to 1e-10.
  EXPECT_NEAR(quadrature_pull_in_time(), 4.80720974, 1e-8);
}

TEST(IdaNewtonControls, DefaultsMeetThePullInTimeAtTheTolerance) {
  const double t_ref = quadrature_pull_in_time();
  for (double rtol : {1e-4, 1e-6}) {
    const PullIn p = pull_in(options(rtol));
    EXPECT_LT(std::abs(p.t - t_ref) / t_ref, 30 * rtol) << "rtol " << rtol;
  }
}

TEST(IdaNewtonControls, EachReachesIdaAndKeepsThePullInTime) {
  // Each control changes the work the way IDA's documentation says it should, which shows it
  // is passed on, and none spoils t_PI beyond what the local error test allows.
  const double rtol = 1e-4, t_ref = quadrature_pull_in_time();
  const PullIn base = pull_in(options(rtol));
  auto check_time = [&](const PullIn& p, const char* what) {
    EXPECT_LT(std::abs(p.t - t_ref) / t_ref, 30 * rtol) << what;
  };
  {
    // A looser Newton test (IDASetNonlinConvCoef 0.33 -> 1) accepts earlier iterates.
    IdaOptions o = options(rtol);
    o.nonlinear_convergence = 1.0;
    const PullIn p = pull_in(o);
    check_time(p, "nonlinear_convergence");
    EXPECT_LT(static_cast<double>(p.stats.newton_iters) / p.stats.steps,
              static_cast<double>(base.stats.newton_iters) / base.stats.steps);
  }
  {
    // One Newton iteration per attempt (IDASetMaxNonlinIters 4 -> 1): the steps whose first
    // correction does not pass the test fail and are retried smaller.
    IdaOptions o = options(rtol);
    o.max_newton_iterations = 1;
    const PullIn p = pull_in(o);
    check_time(p, "max_newton_iterations");
    EXPECT_GT(p.stats.newton_fails, base.stats.newton_fails + 5);
  }
  {
    // The Jacobian refreshed at every change of c_j above 1e-3 (IDASetDeltaCjLSetup 0.25).
    IdaOptions o = options(rtol);
    o.jacobian_cj_change = 1e-3;
    const PullIn p = pull_in(o);
    check_time(p, "jacobian_cj_change");
    EXPECT_GT(p.stats.jacobian_evals, base.stats.jacobian_evals);
  }
  {
    // Growth by up to 4 whenever the error allows 1.2 (IDASetEtaFixedStepBounds, IDASetEtaMax:
    // IDA's 2 and 2): fewer steps.
    IdaOptions o = options(rtol);
    o.step_growth_threshold = 1.2;
    o.max_step_growth = 4;
    const PullIn p = pull_in(o);
    check_time(p, "step growth");
    EXPECT_LT(p.stats.steps, base.stats.steps);
  }
  {
    // A first step of 1e-2 / omega_0 (the start from rest: x = beta t^2 / 2 has a local
    // error ~ beta h^2 / 2 ~ 1e-5 at order 1) instead of IDA's estimate from y'.
    IdaOptions o = options(rtol);
    o.initial_step = 1e-2;
    const PullIn p = pull_in(o);
    check_time(p, "initial_step");
    EXPECT_NE(p.stats.steps, base.stats.steps);
  }
}

// A failure the caller handles (here: stepping on past the contact, where every trial state is
// refused) is a SolverError carrying IDA's own message, and IDA prints nothing on stderr.
TEST(IdaMessages, AFailureCarriesIdasMessageAndPrintsNothing) {
  LumpedActuator system;
  IdaIntegrator ida(system, options(1e-8));
  ida.initialize(0.0, std::vector<Real>{0.0, 0.0}, std::vector<Real>{0.0, beta});
  testing::internal::CaptureStderr();
  std::string message;
  try {
    ida.advance(20.0);
  } catch (const SolverError& e) {
    message = e.what();
  }
  const std::string printed = testing::internal::GetCapturedStderr();
  EXPECT_NE(message.find("IDA failed"), std::string::npos) << message;
  EXPECT_NE(message.find("IDASolve"), std::string::npos) << message;  // IDA's own words
  EXPECT_EQ(printed, "");
}

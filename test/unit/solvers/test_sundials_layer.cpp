// The SUNDIALS layer on problems with closed-form answers:
//  - IDA (KLU and SPGMR) on undamped oscillators m u'' + k u = 0: u = cos(w t);
//  - IDA root finding: the first zero of u at t = pi / (2 w);
//  - fixed-step mode with max order 1 is exactly backward Euler (discrete recurrence);
//  - a RecoverableError in the residual makes IDA retry with a smaller step;
//  - KINSOL with the exact Jacobian on a nonlinear system, and the one-step linear case;
//  - KINSOL's sparse direct solver with UMFPACK (solvers/sparse_direct_solver.hpp) gives KLU's
//    answer and Newton history on a coupled nonlinear chain, refactorising when the Jacobian is
//    kept, and one step on a linear one;
//  - IDA one-step mode (step) to a stop time, and per-unknown absolute tolerances.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/structural_systems.hpp"
#include "solvers/ida_integrator.hpp"
#include "solvers/kinsol_solver.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;

namespace {

// n independent oscillators m u'' + k_i u + c_i u^3 = f_i.
class Oscillators : public SecondOrderOperator {
 public:
  Oscillators(std::vector<double> k, std::vector<double> cubic = {}, std::vector<double> f = {})
      : k_(std::move(k)), c_(cubic), f_(f) {
    c_.resize(k_.size(), 0.0);
    f_.resize(k_.size(), 0.0);
    for (std::size_t i = 0; i < k_.size(); ++i) {
      pattern_.col_idx.push_back(static_cast<Index>(i));
      pattern_.row_ptr.push_back(static_cast<Index>(i + 1));
    }
  }
  Index size() const override { return static_cast<Index>(k_.size()); }
  void internal_residual(Real t, std::span<const Real> y, std::span<Real> r) override {
    if (fail_after >= 0 && t > fail_after && !failed_once) {
      failed_once = true;
      throw RecoverableError("try a smaller step");
    }
    for (std::size_t i = 0; i < k_.size(); ++i)
      r[i] = k_[i] * y[i] + c_[i] * std::pow(y[i], 3) - f_[i];
  }
  const CsrPattern& stiffness_pattern() const override { return pattern_; }
  void stiffness(Real, std::span<const Real> y, std::span<Real> v) override {
    for (std::size_t i = 0; i < k_.size(); ++i) v[i] = k_[i] + 3 * c_[i] * y[i] * y[i];
  }
  std::vector<Real> mass_diagonal() const override { return std::vector<Real>(k_.size(), 1.0); }
  double fail_after = -1;
  bool failed_once = false;

 private:
  std::vector<double> k_, c_, f_;
  CsrPattern pattern_;
};

// A chain of n unit springs between fixed ends, each node also on a linear spring g and a cubic
// spring c to the ground: (2 + g) u_i - u_{i-1} - u_{i+1} + c u_i^3 = f_i = a (1 + i mod 7)
// (u_0 = u_{n+1} = 0):
// coupled, tridiagonal; well conditioned with g = 1, soft (smallest eigenvalue ~ (pi/n)^2) with
// g = 0.
class Chain : public SecondOrderOperator {
 public:
  Chain(Index n, double cubic, double ground = 1, double load = 0.2)
      : n_(n), c_(cubic), g_(ground), a_(load) {
    for (Index i = 0; i < n; ++i) {
      for (Index j = std::max<Index>(i - 1, 0); j <= std::min<Index>(i + 1, n - 1); ++j)
        pattern_.col_idx.push_back(j);
      pattern_.row_ptr.push_back(pattern_.nnz());
    }
  }
  Index size() const override { return n_; }
  void internal_residual(Real, std::span<const Real> y, std::span<Real> r) override {
    for (Index i = 0; i < n_; ++i) {
      const double left = i > 0 ? y[i - 1] : 0.0, right = i + 1 < n_ ? y[i + 1] : 0.0;
      r[i] = (2 + g_) * y[i] - left - right + c_ * std::pow(y[i], 3) - a_ * (1 + i % 7);
    }
  }
  const CsrPattern& stiffness_pattern() const override { return pattern_; }
  void stiffness(Real, std::span<const Real> y, std::span<Real> v) override {
    for (Index i = 0; i < n_; ++i)
      for (Index p = pattern_.row_ptr[i]; p < pattern_.row_ptr[i + 1]; ++p)
        v[p] = pattern_.col_idx[p] == i ? 2 + g_ + 3 * c_ * y[i] * y[i] : -1.0;
  }
  std::vector<Real> mass_diagonal() const override { return std::vector<Real>(n_, 1.0); }

 private:
  Index n_;
  double c_, g_, a_;
  CsrPattern pattern_;
};

// umfpack_from: the direct solver factorises with UMFPACK from this many unknowns (the
// oscillators have 6).
void run_oscillators(IdaOptions::LinearSolver solver, Index umfpack_from = 50000) {
  Oscillators osc({1.0, 4.0, 25.0});  // w = 1, 2, 5
  FirstOrderSystem system(osc);
  IdaOptions options;
  options.rtol = 1e-9;
  options.atol = 1e-12;
  options.linear_solver = solver;
  options.umfpack_from = umfpack_from;
  IdaIntegrator ida(system, options);
  std::vector<double> y0 = {1, 1, 1, 0, 0, 0}, yp0 = {0, 0, 0, -1, -4, -25};
  ida.initialize(0.0, y0, yp0);
  ida.advance(3.0);
  const double w[3] = {1, 2, 5};
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(ida.y()[i], std::cos(w[i] * 3.0), 1e-6) << "oscillator " << i;
  IntegratorStats s = ida.stats();
  EXPECT_GT(s.steps, 50);
  EXPECT_EQ(s.umfpack, solver == IdaOptions::LinearSolver::Direct && umfpack_from <= 6);
  if (solver == IdaOptions::LinearSolver::Spgmr) {
    EXPECT_GT(s.linear_iters, 0);
  }
}

}  // namespace

TEST(Ida, OscillatorsWithKlu) { run_oscillators(IdaOptions::LinearSolver::Direct); }
TEST(Ida, OscillatorsWithUmfpack) { run_oscillators(IdaOptions::LinearSolver::Direct, 1); }
TEST(Ida, OscillatorsWithPreconditionedSpgmr) { run_oscillators(IdaOptions::LinearSolver::Spgmr); }

TEST(Ida, RootFindingLocatesTheFirstZero) {
  Oscillators osc({4.0});
  FirstOrderSystem system(osc);
  IdaOptions options;
  options.rtol = 1e-8;
  options.atol = 1e-12;
  IdaIntegrator ida(system, options);
  ida.set_roots(1, [](double, std::span<const double> y, std::span<const double>,
                      std::span<double> g) { g[0] = y[0]; });
  std::vector<double> y0 = {1, 0}, yp0 = {0, -4};
  ida.initialize(0.0, y0, yp0);
  EXPECT_EQ(ida.advance(10.0), IdaIntegrator::Status::Root);
  EXPECT_NEAR(ida.time(), M_PI / 4, 1e-6);
  EXPECT_EQ(ida.roots_found()[0], -1);  // falling through zero
}

TEST(Ida, FixedStepOrderOneIsBackwardEuler) {
  const double w2 = 9.0, h = 0.01;
  Oscillators osc({w2});
  FirstOrderSystem system(osc);
  IdaOptions options;
  options.max_order = 1;
  options.fixed_step = h;
  IdaIntegrator ida(system, options);
  std::vector<double> y0 = {1, 0}, yp0 = {0, -w2};
  ida.initialize(0.0, y0, yp0);
  ida.advance(0.5);
  // Backward Euler: u' = v, v' = -w2 u  =>  [1, -h; h w2, 1] x_{n+1} = x_n.
  double u = 1, v = 0;
  const int steps = static_cast<int>(std::round(ida.time() / h));
  for (int n = 0; n < steps; ++n) {
    double det = 1 + h * h * w2;
    double un = (u + h * v) / det, vn = (v - h * w2 * u) / det;
    u = un;
    v = vn;
  }
  EXPECT_EQ(ida.stats().steps, steps);
  EXPECT_NEAR(ida.y()[0], u, 1e-9);
  EXPECT_NEAR(ida.y()[1], v, 1e-8);
}

TEST(Ida, RecoverableErrorRetriesTheStep) {
  Oscillators osc({1.0});
  osc.fail_after = 0.5;
  FirstOrderSystem system(osc);
  IdaOptions options;
  options.rtol = 1e-8;
  options.atol = 1e-12;
  IdaIntegrator ida(system, options);
  std::vector<double> y0 = {1, 0}, yp0 = {0, -1};
  ida.initialize(0.0, y0, yp0);
  ida.advance(2.0);
  EXPECT_TRUE(osc.failed_once);
  EXPECT_NEAR(ida.y()[0], std::cos(2.0), 1e-6);
}

TEST(Kinsol, NewtonOnANonlinearSystem) {
  // u + u^3 = 10 has the root u = 2.
  Oscillators osc({1.0, 1.0}, {1.0, 0.0}, {10.0, 3.0});
  KinsolOptions options;
  options.relative_tolerance = 1e-12;
  options.line_search = true;
  StaticSolution s = solve_static(osc, 0.0, options, {1.0, 0.0});
  EXPECT_NEAR(s.y[0], 2.0, 1e-10);
  EXPECT_NEAR(s.y[1], 3.0, 1e-12);
  EXPECT_GT(s.stats.newton_iters, 2);
  EXPECT_LT(s.stats.final_residual, 1e-10);
}

TEST(Kinsol, LinearProblemTakesOneNewtonStep) {
  Oscillators osc({2.0, 5.0}, {}, {4.0, -10.0});
  StaticSolution s = solve_static(osc, 0.0);
  EXPECT_EQ(s.stats.newton_iters, 1);
  EXPECT_NEAR(s.y[0], 2.0, 1e-12);
  EXPECT_NEAR(s.y[1], -2.0, 1e-12);
}

TEST(Kinsol, UmfpackGivesKlusAnswer) {
  Chain chain(300, 5.0);
  std::vector<Real> start;  // keep_jacobian (continuation): from 0.95 x the solution
  for (const bool keep : {false, true}) {
    KinsolOptions options;
    options.relative_tolerance = 1e-12;
    options.keep_jacobian = keep;
    const StaticSolution klu = solve_static(chain, 0.0, options, start);
    options.umfpack_from = 0;  // every size
    const StaticSolution umfpack = solve_static(chain, 0.0, options, start);
    EXPECT_FALSE(klu.stats.umfpack);
    EXPECT_TRUE(umfpack.stats.umfpack);
    EXPECT_EQ(umfpack.stats.newton_iters, klu.stats.newton_iters) << "keep " << keep;
    EXPECT_GE(umfpack.stats.newton_iters, 3);
    EXPECT_GT(umfpack.stats.factor_entries, 0);
    // One symbolic analysis; every later setup a numeric refactorisation.
    EXPECT_EQ(umfpack.stats.fresh_factorizations, 1);
    EXPECT_EQ(umfpack.stats.refactorizations, umfpack.stats.jacobian_evals - 1);
    double largest = 0, difference = 0;
    for (Index i = 0; i < chain.size(); ++i) {
      ASSERT_TRUE(std::isfinite(umfpack.y[i]));
      largest = std::max(largest, std::abs(klu.y[i]));
      difference = std::max(difference, std::abs(umfpack.y[i] - klu.y[i]));
    }
    EXPECT_GT(largest, 0.1);
    EXPECT_LT(difference, 1e-12 * largest) << "keep " << keep;
    EXPECT_LT(umfpack.stats.final_residual, 1e-11);
    start = klu.y;
    for (Real& v : start) v *= 0.95;
  }
  // Linear: one Newton step, as with KLU.
  Chain linear(300, 0.0);
  KinsolOptions options;
  options.umfpack_from = 0;
  const StaticSolution s = solve_static(linear, 0.0, options);
  EXPECT_TRUE(s.stats.umfpack);
  EXPECT_EQ(s.stats.newton_iters, 1);
}

// Modified Newton (the Jacobian kept) from rest on the soft chain: the first step overshoots by
// orders of magnitude, the cubic term then overflows; that is a failure, not a solution with a
// residual of "0" (a NaN compares false with every bound).
TEST(Kinsol, ANonFiniteStateIsAFailure) {
  Chain soft(300, 5.0, 0.0, 0.01);
  KinsolOptions options;
  options.keep_jacobian = true;
  EXPECT_THROW(solve_static(soft, 0.0, options), SolverError);
}

// step(): one internal step per call (Stepped), ending exactly at the stop time (Reached), with
// the same answer as advance(); per-unknown tolerances (atols) are honoured: a loose
// velocity tolerance takes fewer steps than the uniform tight one.
TEST(Ida, OneStepModeEndsAtTheStopTime) {
  auto run = [](std::vector<Real> atols, int& calls) {
    Oscillators osc({4.0});
    FirstOrderSystem system(osc);
    IdaOptions options;
    options.rtol = 1e-8;
    options.atol = 1e-12;
    options.atols = std::move(atols);
    IdaIntegrator ida(system, options);
    std::vector<double> y0 = {1, 0}, yp0 = {0, -4};
    ida.initialize(0.0, y0, yp0);
    calls = 0;
    IdaIntegrator::Status status;
    do {
      status = ida.step(2.0);
      ++calls;
      EXPECT_LE(ida.time(), 2.0);
    } while (status == IdaIntegrator::Status::Stepped);
    EXPECT_EQ(status, IdaIntegrator::Status::Reached);
    EXPECT_DOUBLE_EQ(ida.time(), 2.0);
    EXPECT_NEAR(ida.y()[0], std::cos(4.0), 1e-5);
    EXPECT_EQ(calls, ida.stats().steps);
    return ida.stats().steps;
  };
  int a = 0, b = 0;
  const long uniform = run({}, a);
  const long loose_velocity = run({1e-12, 1e-4}, b);
  EXPECT_GT(uniform, 20);
  EXPECT_LT(loose_velocity, uniform);
}

// Undamped vibration of a fixed-fixed plate (thesis sec. 3.6.3, Fig. 3.9, Table 3.5): a strip
// L = 400 um, h = 2 um (L/h = 200; the thesis's 6.497e4 Hz fixes h/L^2 = 12.5 /m), width
// L/10, clamped at x = 0 and x = L, free long edges; E = 200 GPa, rho = 7854 kg/m^3, nu = 0
// (cylindrical bending, so the strip is exactly a Timoshenko beam and the width and the number
// of cells across it do not matter: 40 x 4 cells stand for the thesis's 40 x 40). At rest at
// t = 0, then a uniform pressure q = -1 Pa is applied (step load). Cubic reconstruction.
//
// References: the thesis's 1.03 (h/L^2) sqrt(E/rho) = 6.497e4 Hz; the exact Euler-Bernoulli
// coefficient 4.7300^2/(2 pi sqrt 12) = 1.02792 gives 6.4839e4 Hz, which is what the thesis's
// computed 6.485e4 Hz matches (shear and rotary inertia lower it by ~1e-4 at L/h = 200).
//
// Asserts:
//  - adaptive IDA (BDF, order capped at 2: BDF3-5 are not A-stable and IDA collapses its step
//    on the imaginary-axis eigenvalues of undamped dynamics) on the reduced-inertia form
//    (rotations quasi-static, see core/reduced_inertia_system.hpp: with rotary
//    inertia the undamped 5.5e9 rad/s thickness-shear branch drives adaptive steps to 1e-11 s):
//    frequency within 0.5 % of 6.497e4 Hz and 0.1 % of Euler-Bernoulli, amplitude kept within
//    1 % over 10 periods, dynamic amplitude = static deflection (step load);
//  - fixed-step BDF2 (IDA, max_order 2, dt = 10 ns as the thesis) with the full mass (rotary
//    inertia included): the same frequency checks;
//  - fixed-step runs to t = 25 us (the thesis's Table 3.5 instant), full mass, Richardson's
//    order from three steps halved in turn: ~1 with max_order 1 (backward Euler) on the
//    thesis's own run (step load, dt = 5, 2.5, 1.25 ns; thesis 0.992), whose three deflections
//    also match Table 3.5 within 0.5 %; ~2 with max_order 2 (BDF2, dt = 40, 20, 10 ns) after a
//    C1 start of the load (see the note at that test).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "../support/oscillation.hpp"
#include "core/reduced_inertia_system.hpp"
#include "core/structural_systems.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/plate/plate_operator.hpp"
#include "solvers/ida_integrator.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using Kind = PlateBoundary::Kind;

namespace {

constexpr double L = 400e-6, h = 2e-6, E = 200e9, rho = 7854, q = -1.0;
const double thesis_frequency = 1.03 * h / (L * L) * std::sqrt(E / rho);
const double euler_bernoulli_frequency = 4.730040744862704 * 4.730040744862704 /
                                         (2 * M_PI * std::sqrt(12.0)) * h / (L * L) *
                                         std::sqrt(E / rho);

// The load: the thesis's step q at t = 0, or a smooth start q sin^2(pi t / (2 t_ramp)) for
// t < t_ramp (C1, so the stiff high modes are hardly excited).
ScalarField load(double t_ramp) {
  return [t_ramp](const Vec3&, double t) {
    if (t_ramp <= 0 || t >= t_ramp) return q;
    const double s = std::sin(M_PI * t / (2 * t_ramp));
    return q * s * s;
  };
}

struct Strip {
  Mesh mesh;
  std::unique_ptr<PlateOperator> op;
  std::vector<Index> centre_cells;

  explicit Strip(double t_ramp = 0) : mesh(make_mesh()) {
    std::vector<PlateBoundary> bcs(mesh.patches().size());
    for (std::size_t p = 0; p < bcs.size(); ++p) {
      const std::string& name = mesh.patches()[p].name;
      bcs[p].kind = name == "left" || name == "right" ? Kind::Clamped : Kind::Free;
    }
    op = std::make_unique<PlateOperator>(mesh, PlateSection{E, 0.0, rho, h}, bcs, load(t_ramp));
    // Cells around the centre (L/2, L/20), a mesh vertex.
    for (Index c = 0; c < mesh.n_cells(); ++c) {
      const Vec3 d = mesh.cell_centroid(c) - centre();
      if (std::abs(d.x()) < L / 40 && std::abs(d.y()) < L / 40) centre_cells.push_back(c);
    }
  }
  static Mesh make_mesh() {
    BoxSpec spec;
    spec.upper = Vec3(L, L / 10, 0);
    spec.n[0] = 40;
    spec.n[1] = 4;
    return make_structured_mesh(spec);
  }
  static Vec3 centre() { return Vec3(L / 2, L / 20, 0); }
  double centre_deflection(std::span<const double> y) const {
    double w = 0;
    for (Index c : centre_cells) w += op->deflection_at(c, centre(), 0.0, y);
    return w / centre_cells.size();
  }
  // State at rest with the consistent initial acceleration M^{-1}(-R(0, 0)).
  void initial_state(std::vector<double>& y0, std::vector<double>& yp0) const {
    const Index n = op->size();
    y0.assign(2 * n, 0.0);
    yp0.assign(2 * n, 0.0);
    std::vector<double> r(n);
    op->internal_residual(0.0, std::span<const double>(y0).subspan(0, n), r);
    auto m = op->mass_diagonal();
    for (Index i = 0; i < n; ++i) yp0[n + i] = -r[i] / m[i];
  }
};

// Centre deflection at t_end with fixed steps.
double fixed_step_deflection(const Strip& strip, int max_order, double dt, double t_end) {
  FirstOrderSystem system(*strip.op);
  IdaOptions options;
  options.max_order = max_order;
  options.fixed_step = dt;
  options.max_steps = 1000000;
  IdaIntegrator ida(system, options);
  std::vector<double> y0, yp0;
  strip.initial_state(y0, yp0);
  ida.initialize(0.0, y0, yp0);
  ida.advance(t_end);
  EXPECT_EQ(ida.stats().last_order, max_order);
  return strip.centre_deflection(ida.y().subspan(0, strip.op->size()));
}

struct Richardson {
  double coarse, medium, fine, order;
};

Richardson richardson(const Strip& strip, int max_order, double dt_finest, double t_end) {
  const double coarse = fixed_step_deflection(strip, max_order, 4 * dt_finest, t_end);
  const double medium = fixed_step_deflection(strip, max_order, 2 * dt_finest, t_end);
  const double fine = fixed_step_deflection(strip, max_order, dt_finest, t_end);
  const double p = std::log((coarse - medium) / (medium - fine)) / std::log(2.0);
  std::printf(
      "max_order %d: w(%.0f us) = %.6e, %.6e, %.6e m for dt = %.3g, %.3g, %.3g ns: order %.3f\n",
      max_order, t_end * 1e6, coarse, medium, fine, 4e9 * dt_finest, 2e9 * dt_finest,
      1e9 * dt_finest, p);
  return {coarse, medium, fine, p};
}

struct FrequencyRun {
  double frequency, first_amplitude, last_amplitude;
  int periods;
  IntegratorStats stats;
  double seconds;
};

// Samples the centre deflection every period/200 over 11.3 periods and measures the
// oscillation about the static deflection.
FrequencyRun run_frequency(const Strip& strip, SystemOperator& system, const IdaOptions& options,
                           std::span<const double> y0, std::span<const double> yp0,
                           double static_centre) {
  auto t0 = std::chrono::steady_clock::now();
  IdaIntegrator ida(system, options);
  ida.initialize(0.0, y0, yp0);
  const double period = 1 / euler_bernoulli_frequency, t_end = 11.3 * period;
  std::vector<double> t, w;
  for (int k = 1; k * period / 200 <= t_end; ++k) {
    ida.advance(k * period / 200);
    t.push_back(ida.time());
    w.push_back(strip.centre_deflection(ida.y().subspan(0, strip.op->size())));
  }
  auto osc = test_support::analyse_oscillation(t, w, static_centre, 0.0);
  FrequencyRun run{1 / osc.period,
                   osc.first_amplitude,
                   osc.last_amplitude,
                   osc.n_periods,
                   ida.stats(),
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
  std::printf(
      "f = %.1f Hz: %+.3f %% from the thesis's 6.497e4 Hz, %+.4f %% from Euler-Bernoulli %.1f Hz; "
      "%d periods, amplitude %.5e -> %.5e m (static %.5e m); IDA: %ld steps, %ld residuals, "
      "%ld Jacobians, last order %d; %.2f s\n",
      run.frequency, 100 * (run.frequency / thesis_frequency - 1),
      100 * (run.frequency / euler_bernoulli_frequency - 1), euler_bernoulli_frequency, run.periods,
      run.first_amplitude, run.last_amplitude, static_centre, run.stats.steps,
      run.stats.residual_evals, run.stats.jacobian_evals, run.stats.last_order, run.seconds);
  return run;
}

void expect_thesis_frequency(const FrequencyRun& run, double static_centre) {
  EXPECT_NEAR(thesis_frequency, 6.497e4, 1.0);
  EXPECT_GE(run.periods, 10);
  EXPECT_NEAR(run.frequency / thesis_frequency, 1.0, 0.005);
  EXPECT_NEAR(run.frequency / euler_bernoulli_frequency, 1.0, 0.001);
  EXPECT_LT(std::abs(1 - run.last_amplitude / run.first_amplitude), 0.01);
  // Step load: the plate swings about the static deflection with that same amplitude.
  EXPECT_NEAR(run.first_amplitude / std::abs(static_centre), 1.0, 0.05);
}

}  // namespace

TEST(PlateVibration, FrequencyUnderAdaptiveBdfWithQuasiStaticRotations) {
  Strip strip;
  ASSERT_EQ(strip.centre_cells.size(), 4u);
  const double static_centre = strip.centre_deflection(solve_static(*strip.op, 0.0).y);
  ReducedInertiaSystem system(*strip.op, strip.op->rotation_components());
  IdaOptions options;
  options.rtol = 1e-4;
  options.atol = 1e-4 * std::abs(static_centre);
  options.max_order = 2;
  options.max_steps = 1000000;
  // At rest: the rotations are in quasi-static equilibrium (R_beta(0, 0) = 0).
  std::vector<double> y0(system.size(), 0.0);
  auto yp0 = system.consistent_derivative(0.0, y0);
  FrequencyRun run = run_frequency(strip, system, options, y0, yp0, static_centre);
  expect_thesis_frequency(run, static_centre);
}

TEST(PlateVibration, FrequencyUnderFixedStepBdf2WithRotaryInertia) {
  Strip strip;
  const double static_centre = strip.centre_deflection(solve_static(*strip.op, 0.0).y);
  FirstOrderSystem system(*strip.op);
  IdaOptions options;
  options.max_order = 2;
  options.fixed_step = 1e-8;
  options.max_steps = 1000000;
  std::vector<double> y0, yp0;
  strip.initial_state(y0, yp0);
  FrequencyRun run = run_frequency(strip, system, options, y0, yp0, static_centre);
  expect_thesis_frequency(run, static_centre);
}

TEST(PlateVibration, BackwardEulerIsFirstOrderAndMatchesThesisTable35) {
  // The thesis's run: step load, backward Euler, dt = 5, 2.5, 1.25 ns, w at t = 25 us.
  Strip strip;
  const Richardson r = richardson(strip, 1, 1.25e-9, 25e-6);
  EXPECT_NEAR(r.order, 1.0, 0.1);  // thesis: 0.992
  EXPECT_NEAR(r.coarse / -8.64166e-10, 1.0, 0.005);
  EXPECT_NEAR(r.medium / -8.66507e-10, 1.0, 0.005);
  EXPECT_NEAR(r.fine / -8.67684e-10, 1.0, 0.005);
}

// BDF2's error at these steps (1e-4 of w) is small enough that, after a step load, the stiff
// high modes it damps (grid-scale bending, omega dt >> 1) make the differences between runs
// non-asymptotic (measured with the step: w = -8.6786, -8.6806, -8.6798e-10 for dt = 20, 10,
// 5 ns, not monotone). With a C1 start over 5 us they are not excited and the order is clean.
TEST(PlateVibration, Bdf2IsSecondOrder) {
  Strip strip(5e-6);
  const Richardson r = richardson(strip, 2, 10e-9, 25e-6);
  EXPECT_NEAR(r.order, 2.0, 0.15);
}

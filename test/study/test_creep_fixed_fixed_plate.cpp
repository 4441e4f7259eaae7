// Creep of a fixed-fixed plate under uniform pressure (thesis sec. 4.6.1, Table 4.1): E =
// 200 GPa, nu = 0.3, A = 8.33e-6 /s, B = 1.8e8, m = 2, n = 2, sigma_y0 = 1 GPa; left and
// right edges clamped, the long edges free; L/h = 10 (q = 4 MPa) and 60 (q = 60 kPa). The
// thesis gives the plate-vs-3D differences (Table 4.2) and plots, not the deflections, so what
// is asserted here is what the plate model itself must satisfy:
//   - the plastic centre deflection after 500 h is time-step independent (IDA at two
//     tolerances within 0.5 %), sags the same way as the load, and is a small fraction of the
//     elastic deflection (the stress is ~0.1-0.2 sigma_y0 and hardens within seconds);
//   - explicit Euler (the thesis's scheme) agrees with IDA as dt -> 0: within 0.5 % at
//     dt = 1 h for the mild Coble law of sec. 4.6.2, and for the Table 4.1 law only at
//     dt ~ 1 s: at dt = 1 h its first step overshoots by orders of magnitude (docs/creep.md).
// Also the whole Table 4.1 series on the thesis's 81 x 21 mesh (L/h = 10 ... 60 with the
// table's loads; the table gives mesh and load only, the deflections were in the lost figures
// 4.3-4.5) and which reading of the parameters makes the thesis's "dt = 1 h is time-step
// independent" true (A per hour, B = 1.8e3). STUDY label (minutes in all). IDA runs use the
// Schur-complement preconditioned SPGMR (physics/creep/plate_creep_schur_complement.hpp).
// Geometry (not in the extracted thesis text): L = 240 um, width L/4, h = L/(L/h). Prints
// steps and wall times of both integrators (the figures of docs/creep.md).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "physics/creep/continuum_plate_comparison.hpp"
#include "physics/creep/explicit_creep_integrator.hpp"
#include "physics/creep/plate_creep_system.hpp"
#include "solvers/ida_integrator.hpp"

using namespace rfmems;

namespace {

constexpr Real kLength = 240e-6, kHours = 3600.0;

CreepLaw table_4_1_law() { return {8.33e-6, 1.8e8, 2, 2, 1e9}; }
CreepLaw coble_law() { return {2.08e-10, 20, 1, 0.5, 0.7e9}; }

using Plate = FixedFixedCreepPlate;

// L = 240 um, width L/4 (the Table 4.1 plate), 20 Simpson intervals.
std::unique_ptr<Plate> make_plate(Real slenderness, Real load, const CreepLaw& law, int nx,
                                  int ny) {
  FixedFixedCreepProblem problem;
  problem.length = kLength;
  problem.width = kLength / 4;
  problem.slenderness = slenderness;
  problem.load = load;
  problem.law = law;
  return make_fixed_fixed_creep_plate(problem, nx, ny);
}

struct Result {
  Real w_elastic = 0, w_plastic = 0;  // centre deflection at t = 0 and w(500 h) - w(0)
  long steps = 0;
  double wall = 0;
};

Result run_implicit(Plate& p, Real rtol, Real end = 500 * kHours) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Real> y, yp;
  p.system->initial_state(0, y, yp);
  Result r;
  r.w_elastic = y[3 * p.centre];
  IdaOptions options;
  options.rtol = rtol;
  options.atol = 1e-5 * rtol;  // 1e-10 rtol made IDA fail at t = 0 (error test, h -> 1e-12)
  options.linear_solver = IdaOptions::LinearSolver::Spgmr;  // the Schur-complement solve
  IdaIntegrator ida(*p.system, options);
  ida.initialize(0, y, yp);
  ida.advance(end);
  r.w_plastic = ida.y()[3 * p.centre] - r.w_elastic;
  r.steps = ida.stats().steps;
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

Result run_explicit(Plate& p, Real dt, Real end = 500 * kHours) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Real> y, yp;
  p.system->initial_state(0, y, yp);
  Result r;
  r.w_elastic = y[3 * p.centre];
  ExplicitCreepIntegrator euler(*p.system, dt);
  euler.initialize(0, y);
  euler.advance(end);
  r.w_plastic = euler.state()[3 * p.centre] - r.w_elastic;
  r.steps = euler.steps();
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

void print(const char* label, const Result& r) {
  std::printf("%-34s w_el = %.5e m  w_p(500 h) = %.5e m  (w_p/w_el %.3e)  %6ld steps  %.2f s\n",
              label, r.w_elastic, r.w_plastic, r.w_plastic / r.w_elastic, r.steps, r.wall);
}

}  // namespace

TEST(CreepFixedFixedPlate, Table41PlasticDeflectionIsStepIndependent) {
  for (auto [slenderness, load] : {std::pair{60.0, 6e4}, std::pair{10.0, 4e6}}) {
    auto plate = make_plate(slenderness, load, table_4_1_law(), 41, 11);
    const Result coarse = run_implicit(*plate, 1e-5), fine = run_implicit(*plate, 1e-6);
    std::printf("L/h = %g, q = %g Pa, 41 x 11:\n", slenderness, load);
    print("  IDA rtol 1e-5", coarse);
    print("  IDA rtol 1e-6", fine);
    EXPECT_LT(coarse.w_elastic, 0);
    EXPECT_LT(fine.w_plastic, 0);  // creep adds to the sag
    EXPECT_LT(std::abs(fine.w_plastic / fine.w_elastic), 0.05);
    EXPECT_NEAR(coarse.w_plastic, fine.w_plastic, 5e-3 * std::abs(fine.w_plastic));
  }
}

TEST(CreepFixedFixedPlate, ExplicitEulerAgreesWithIdaForTheCobleLawAtOneHour) {
  auto plate = make_plate(60.0, 6e4 * 20, coble_law(), 21, 5);
  const Result implicit = run_implicit(*plate, 1e-6);
  const Result explicit_euler = run_explicit(*plate, 1 * kHours);
  std::printf("Coble law, L/h = 60, q = 1.2 MPa, 21 x 5:\n");
  print("  IDA rtol 1e-6", implicit);
  print("  explicit Euler dt = 1 h", explicit_euler);
  EXPECT_NEAR(explicit_euler.w_plastic, implicit.w_plastic, 5e-3 * std::abs(implicit.w_plastic));
}

// Table 4.1 law: the hardening makes the rate Jacobian -m n B eps_dot/(1 + B eps) ~ -70 /s at
// t = 0, so a fixed dt = 1 h overshoots in its first step; Euler converges to IDA only for
// dt ~ 1 s. Checked over the first 2 h on a coarser mesh (the error is made at the start).
TEST(CreepFixedFixedPlate, ExplicitEulerConvergesToIdaForTheTable41Law) {
  auto plate = make_plate(60.0, 6e4, table_4_1_law(), 21, 5);
  const Real end = 2 * kHours;
  const Result implicit = run_implicit(*plate, 1e-7, end);
  print("  IDA rtol 1e-7 (2 h)", implicit);
  Real previous_error = 1e300;
  for (Real dt : {3600.0, 36.0, 0.36}) {
    const Result e = run_explicit(*plate, dt, end);
    const Real error = std::abs(e.w_plastic / implicit.w_plastic - 1);
    char label[64];
    std::snprintf(label, sizeof label, "  explicit dt = %g s (2 h)", dt);
    print(label, e);
    std::printf("    relative difference to IDA: %.3e\n", error);
    EXPECT_LT(error, previous_error);
    previous_error = error;
    if (dt == 3600.0) {
      EXPECT_GT(error, 10.0);  // the overshoot of docs/creep.md
    }
  }
  EXPECT_LT(previous_error, 5e-3);
}

// The thesis's series (Table 4.1: mesh 81 x 21; q = 4 MPa, 0.6 MPa and 60 kPa for L/h = 10,
// 20 and 30-60): plastic centre deflection after 500 h at two IDA tolerances.
TEST(CreepFixedFixedPlate, Table41SeriesOnTheThesisMesh) {
  const std::pair<Real, Real> series[] = {{10, 4e6}, {20, 6e5}, {30, 6e4},
                                          {40, 6e4}, {50, 6e4}, {60, 6e4}};
  std::printf("Table 4.1 law, 81 x 21, 500 h:\n");
  for (auto [slenderness, load] : series) {
    auto plate = make_plate(slenderness, load, table_4_1_law(), 81, 21);
    const Result coarse = run_implicit(*plate, 1e-5), fine = run_implicit(*plate, 1e-6);
    char label[64];
    std::snprintf(label, sizeof label, "  L/h = %2.0f q = %.0e rtol 1e-5", slenderness, load);
    print(label, coarse);
    std::snprintf(label, sizeof label, "  L/h = %2.0f q = %.0e rtol 1e-6", slenderness, load);
    print(label, fine);
    EXPECT_LT(fine.w_plastic, 0);
    EXPECT_NEAR(coarse.w_plastic, fine.w_plastic, 5e-3 * std::abs(fine.w_plastic));
    // The reading B = 1.8e3 (see the next test), for the docs: creep of the order of the
    // elastic deflection.
    auto b_reading = make_plate(slenderness, load, CreepLaw{8.33e-6, 1.8e3, 2, 2, 1e9}, 81, 21);
    const Result b = run_implicit(*b_reading, 1e-6);
    std::snprintf(label, sizeof label, "  L/h = %2.0f B = 1.8e3 rtol 1e-6", slenderness);
    print(label, b);
    EXPECT_LT(b.w_plastic, fine.w_plastic);  // less hardening: more creep
  }
}

// Which transcription of the Table 4.1 law makes explicit Euler at dt = 1 h (the thesis's
// "time-step independent" setting) agree with IDA? L/h = 60, q = 60 kPa, 41 x 11, 500 h.
//   as transcribed   A = 8.33e-6 /s, B = 1.8e8
//   A per hour       A = 8.33e-6 /h = 2.314e-9 /s, B = 1.8e8
//   B = 1.8e3        A = 8.33e-6 /s, B = 1.8e3
// Euler's first step is stable only for dt |dg/deps| = dt m n B a < 2 (a: the initial rate);
// printed with the relative difference of the 500 h plastic deflections.
TEST(CreepFixedFixedPlate, Table41ParameterReadingsAgainstExplicitEulerAtOneHour) {
  struct Reading {
    const char* name;
    CreepLaw law;
  };
  const Reading readings[] = {{"as transcribed", {8.33e-6, 1.8e8, 2, 2, 1e9}},
                              {"A per hour", {8.33e-6 / 3600, 1.8e8, 2, 2, 1e9}},
                              {"B = 1.8e3", {8.33e-6, 1.8e3, 2, 2, 1e9}}};
  std::vector<Real> difference;
  for (const Reading& r : readings) {
    auto plate = make_plate(60.0, 6e4, r.law, 41, 11);
    const Result implicit = run_implicit(*plate, 1e-7);
    const Result euler = run_explicit(*plate, 1 * kHours);
    const Real sigma = 6e4 * 60 * 60 / 2;  // clamped-edge fibre stress q (L/h)^2 / 2
    const Real a = r.law.A * std::pow(sigma / r.law.sigma_y0, r.law.m);
    const Real d = std::abs(euler.w_plastic / implicit.w_plastic - 1);
    std::printf("%-15s dt m n B a = %.3g\n", r.name, 3600 * r.law.m * r.law.n * r.law.B * a);
    print("  IDA rtol 1e-7", implicit);
    print("  explicit Euler dt = 1 h", euler);
    std::printf("    relative difference %.3e\n", d);
    difference.push_back(d);
  }
  // Measured (41 x 11): 324x, 7.9e-2 and 1.1e-3. Only B = 1.8e3 makes dt = 1 h time-step
  // independent, as the thesis states.
  EXPECT_GT(difference[0], 10.0);  // the first-step overshoot
  EXPECT_GT(difference[1], 2e-2);
  EXPECT_LT(difference[2], 5e-3);
}

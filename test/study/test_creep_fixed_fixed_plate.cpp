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
// STUDY label: the implicit runs are slow until the linear solve is restructured (docs/creep.md,
// "Performance"). Geometry (not in the extracted thesis text): L = 240 um, width L/4, h = L/(L/h); mesh 41 x 11
// (the thesis's 81 x 21 is in test/study/test_creep_plate_study.cpp). Prints steps and wall
// times of both integrators (the figures of docs/creep.md).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "mesh/structured_mesh.hpp"
#include "physics/creep/explicit_creep_integrator.hpp"
#include "physics/creep/plate_creep_system.hpp"
#include "solvers/ida_integrator.hpp"

using namespace rfmems;
using Kind = PlateBoundary::Kind;

namespace {

constexpr Real kLength = 240e-6, kHours = 3600.0;

CreepLaw table_4_1_law() { return {8.33e-6, 1.8e8, 2, 2, 1e9}; }
CreepLaw coble_law() { return {2.08e-10, 20, 1, 0.5, 0.7e9}; }

struct Plate {
  Mesh mesh;
  std::unique_ptr<PlateOperator> op;
  std::unique_ptr<PlateCreepSystem> system;
  Index centre = -1;
};

std::unique_ptr<Plate> make_plate(Real slenderness, Real load, const CreepLaw& law, int nx,
                                  int ny) {
  auto p = std::make_unique<Plate>();
  BoxSpec spec;
  spec.upper = Vec3(kLength, kLength / 4, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  p->mesh = make_structured_mesh(spec);
  PlateSection s;
  s.E = 200e9;
  s.nu = 0.3;
  s.rho = 7854;
  s.thickness = kLength / slenderness;
  std::vector<PlateBoundary> bcs(p->mesh.patches().size());
  for (std::size_t k = 0; k < bcs.size(); ++k) {
    const std::string& name = p->mesh.patches()[k].name;
    bcs[k].kind = (name == "left" || name == "right") ? Kind::Clamped : Kind::Free;
  }
  p->op = std::make_unique<PlateOperator>(p->mesh, s, bcs,
                                          [load](const Vec3&, Real) { return -load; });
  p->system = std::make_unique<PlateCreepSystem>(*p->op, law);
  Real best = 1e300;
  for (Index c = 0; c < p->mesh.n_cells(); ++c) {
    const Real d = (p->mesh.cell_centroid(c) - Vec3(kLength / 2, kLength / 8, 0)).norm();
    if (d < best) best = d, p->centre = c;
  }
  return p;
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

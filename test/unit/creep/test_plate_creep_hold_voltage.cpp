// Creep of a fixed-fixed plate held down by a voltage (PlateCreepSystem::set_hold_voltage):
// the electrostatic load grows as creep closes the gap. The Coble law (m = 1, B eps ~ 1e-5: the
// creep is linear in the stress), so under a constant pressure the plastic deflection is a
// fixed multiple of the elastic one whatever the load; under the hold voltage the ratio w_p/w_el
// must be larger (the load rose by ~2 (w_p / g) while creeping). Also: IDA (Schur-preconditioned
// SPGMR, nonlinear y rows) against explicit Euler at dt = 1 h (Newton equilibria), and the
// smallest gap shrinking monotonically. L = 240 um, width L/4, h = 4 um, 21 x 5 cells, gap
// 3 um, 360 V (0.06 MPa, w_el ~ 0.5 um, well below pull-in), 500 h.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "mesh/structured_mesh.hpp"
#include "physics/creep/explicit_creep_integrator.hpp"
#include "physics/creep/plate_creep_system.hpp"
#include "solvers/ida_integrator.hpp"

using namespace rfmems;

namespace {

constexpr Real kLength = 240e-6, kGap = 3e-6, kVoltage = 360, kEnd = 500 * 3600.0;

struct Plate {
  Mesh mesh;
  std::unique_ptr<PlateOperator> op;
  std::unique_ptr<PlateCreepSystem> system;
  Index centre = -1;
};

std::unique_ptr<Plate> make_plate(Real pressure, bool hold) {
  auto p = std::make_unique<Plate>();
  BoxSpec spec;
  spec.upper = Vec3(kLength, kLength / 4, 0);
  spec.n[0] = 21;
  spec.n[1] = 5;
  p->mesh = make_structured_mesh(spec);
  PlateSection s;
  s.E = 200e9;
  s.nu = 0.3;
  s.rho = 7854;
  s.thickness = kLength / 60;
  std::vector<PlateBoundary> bcs(p->mesh.patches().size());
  for (std::size_t k = 0; k < bcs.size(); ++k) {
    const std::string& name = p->mesh.patches()[k].name;
    bcs[k].kind = (name == "left" || name == "right") ? PlateBoundary::Kind::Clamped
                                                      : PlateBoundary::Kind::Free;
  }
  p->op = std::make_unique<PlateOperator>(p->mesh, s, bcs,
                                          [pressure](const Vec3&, Real) { return -pressure; });
  p->system = std::make_unique<PlateCreepSystem>(*p->op, CreepLaw{2.08e-10, 20, 1, 0.5, 0.7e9});
  if (hold) {
    CreepHoldVoltage h;
    h.initial_gap = kGap;
    h.voltage = kVoltage;
    for (Index c = 0; c < p->mesh.n_cells(); ++c)
      h.elements.push_back(
          {3 * c + PlateOperator::kW, p->mesh.cell_volume(c), Vec3::Zero(), Vec3::Zero(), {}});
    p->system->set_hold_voltage(h);
  }
  Real best = 1e300;
  for (Index c = 0; c < p->mesh.n_cells(); ++c) {
    const Real d = (p->mesh.cell_centroid(c) - Vec3(kLength / 2, kLength / 8, 0)).norm();
    if (d < best) best = d, p->centre = c;
  }
  return p;
}

struct CreepRun {
  Real w_elastic, w_plastic;
  std::vector<Real> min_gaps;  // at 0, 1, 10, 100 h, 500 h
};

CreepRun run_implicit(Plate& p) {
  std::vector<Real> y, yp;
  p.system->initial_state(0, y, yp);
  CreepRun r{y[3 * p.centre], 0, {p.system->min_gap(y)}};
  IdaOptions options;
  options.rtol = 1e-7;
  options.atol = 1e-13;
  options.linear_solver = IdaOptions::LinearSolver::Spgmr;
  IdaIntegrator ida(*p.system, options);
  ida.initialize(0, y, yp);
  for (Real t : {3600.0, 36000.0, 360000.0, kEnd}) {
    ida.advance(t);
    r.min_gaps.push_back(p.system->min_gap(ida.y()));
  }
  r.w_plastic = ida.y()[3 * p.centre] - r.w_elastic;
  return r;
}

}  // namespace

TEST(PlateCreepHoldVoltage, TheGrowingLoadAcceleratesCreepAndBothIntegratorsAgree) {
  const Real p0 = kVoltage * kVoltage * ParallelPlateLaw{}.pressure_per_volt2(kGap);
  auto held = make_plate(0.0, true);
  auto pressed = make_plate(p0, false);
  const CreepRun hold = run_implicit(*held), constant = run_implicit(*pressed);
  std::printf("hold %g V: w_el %.5e m, w_p %.5e m (ratio %.4e); min gap %.5e -> %.5e m\n", kVoltage,
              hold.w_elastic, hold.w_plastic, hold.w_plastic / hold.w_elastic,
              hold.min_gaps.front(), hold.min_gaps.back());
  std::printf("constant p(g0) = %.4g Pa: w_el %.5e m, w_p %.5e m (ratio %.4e)\n", p0,
              constant.w_elastic, constant.w_plastic, constant.w_plastic / constant.w_elastic);
  EXPECT_LT(hold.w_elastic, constant.w_elastic);  // the gap closed elastically: more load
  const Real amplification =
      (hold.w_plastic / hold.w_elastic) / (constant.w_plastic / constant.w_elastic);
  std::printf("creep amplification by the growing load: %.5f\n", amplification);
  EXPECT_GT(amplification, 1.01);
  for (std::size_t k = 1; k < hold.min_gaps.size(); ++k)
    EXPECT_LT(hold.min_gaps[k], hold.min_gaps[k - 1]);

  // Explicit Euler at 1 h: Newton equilibria under the hold voltage after every step.
  std::vector<Real> y, yp;
  held->system->initial_state(0, y, yp);
  ExplicitCreepIntegrator euler(*held->system, 3600.0);
  euler.initialize(0, y);
  euler.advance(kEnd);
  const Real w_p_euler = euler.state()[3 * held->centre] - y[3 * held->centre];
  std::printf("explicit Euler dt = 1 h: w_p %.5e m (relative difference %.2e)\n", w_p_euler,
              std::abs(w_p_euler / hold.w_plastic - 1));
  EXPECT_NEAR(w_p_euler, hold.w_plastic, 5e-3 * std::abs(hold.w_plastic));
}

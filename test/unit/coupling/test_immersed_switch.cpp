// The coupled immersed-boundary switch (issue 8): the thesis's cantilever (Fig. 6.5) on
// coarse meshes, against closed forms and the scene's own static solve.
//
// Backgrounds are 151 x 51 / 101 x 31 rather than 150 x 50 / 100 x 30: with those the beam's
// top face and tip lie on grid lines at rest, and a deflection of a few nm then cuts slivers
// off the cells beside them, where lib/ibm gives a spurious force (measured at 50 V: the top
// of the tip's last 3 um pulled up by 4.3e-3 N/m instead of 1.8e-5 after a 44 nm deflection;
// the static fixed point did not converge). docs/immersed_switch.md.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "coupling/immersed_reynolds_film.hpp"
#include "coupling/immersed_switch.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/electrostatics/permittivity.hpp"

namespace rfmems {
namespace {

constexpr Real um = 1e-6;
constexpr Real kGap = 1.5 * um, kLength = 45 * um, kThickness = 1.5 * um;

// Beam 45 um x 1.5 um, bottom 1.5 um above the electrode, clamped at x = 0 (the background's
// left wall); background 75 um x 10 um; electrode [0, electrode_end] on the bottom.
struct Cantilever {
  std::unique_ptr<Mesh> mesh;
  std::unique_ptr<ElasticityOperator> op;
  std::unique_ptr<ImmersedSwitch> scene;
  Cantilever(int bx, int by, int gx, int gy, Real electrode_end = kLength) {
    BoxSpec spec;
    spec.lower = Vec3(0, kGap, 0);
    spec.upper = Vec3(kLength, kGap + kThickness, 0);
    spec.n[0] = bx;
    spec.n[1] = by;
    mesh = std::make_unique<Mesh>(make_structured_mesh(spec));
    const LinearElastic steel{200e9, 0.3, 8912, Hypothesis::PlaneStress};
    std::vector<ElasticityBoundary> bcs(mesh->patches().size());
    bcs[mesh->find_patch("left")].kind = ElasticityBoundary::Kind::Fixed;
    op = std::make_unique<ElasticityOperator>(*mesh, steel, bcs);
    ImmersedSwitchGeometry g;
    g.background_upper = Vec3(75 * um, 10 * um, 0);
    g.background_cells[0] = gx;
    g.background_cells[1] = gy;
    g.electrode_begin = 0;
    g.electrode_end = electrode_end;
    scene = std::make_unique<ImmersedSwitch>(*op, g, /*tip cell, bottom row*/ bx - 1);
  }
};

ImmersedRunOptions run_options(Real end_time, Real atol_fraction) {
  ImmersedRunOptions o;
  o.end_time = end_time;
  o.contact_gap = 0.2 * kGap;
  o.ida.rtol = 1e-4;
  o.ida.atol = atol_fraction * kGap;
  o.ida.max_order = 2;
  return o;
}

// Osterberg & Senturia (1997): the distributed cantilever's quasi-static pull-in, no fringing,
// V = sqrt(0.28 E h^3 g^3 / (eps L^4)) (a fit to 2D FEM within ~1 %): 132.5 V here. The
// lumped closed form of issue 8 (k = 2 E b h^3 / (3 L^3) at the tip, A = b L at the tip gap)
// gives 111 V: it puts the whole area at the tip's gap, so it pulls in too early.
Real distributed_pull_in() {
  return std::sqrt(0.28 * 200e9 * std::pow(kThickness, 3) * std::pow(kGap, 3) /
                   (kVacuumPermittivity * std::pow(kLength, 4)));
}

// At rest, the IBM force on the beam against the parallel plate eps V^2 L / (2 g^2) plus the
// first-order edge correction of a thin plate over a ground plane, eps V^2 / (2 pi g) per free
// edge (dC/dg of the edge capacitance (eps/pi) ln(...)): relative g / (pi L) = 1.06 % for the
// free tip. Tolerance: the beam is as thick as the gap, so its end face and top add field the
// thin-plate estimate lacks (positive, a fraction of the correction), and the 151 x 51
// background's discretisation moved the force by 0.7 % from 150 x 50 to 300 x 100 (bench 13):
// the correction must come out between 0.5 and 2 times the estimate. With the electrode ending
// under the tip (the case's extent) the fringe has no electrode to end on: the force stays
// within one edge correction of the parallel plate.
TEST(ImmersedSwitch, ForceAtRestIsParallelPlatePlusEdgeCorrection) {
  const Real v = 100;
  const Real plate = kVacuumPermittivity * v * v * kLength / (2 * kGap * kGap);
  const Real edge = kGap / (M_PI * kLength);
  Cantilever wide(46, 4, 151, 51, 75 * um);
  const ImmersedLoad a = wide.scene->electrostatic_load(std::vector<Real>(wide.op->size(), 0.0), v);
  const Real correction = -a.total.y() / plate - 1;
  EXPECT_GT(correction, 0.5 * edge);
  EXPECT_LT(correction, 2.0 * edge);
  Cantilever under(46, 4, 151, 51);
  const ImmersedLoad b =
      under.scene->electrostatic_load(std::vector<Real>(under.op->size(), 0.0), v);
  EXPECT_LT(std::abs(-b.total.y() / plate - 1), edge);
  RecordProperty("edge_correction_over_estimate", std::to_string(correction / edge));
  RecordProperty("electrode_under_beam_ratio", std::to_string(-b.total.y() / plate));
}

// A step of 30 V (0.23 of pull-in): undamped, the tip swings to its first turning point at
// about twice the static deflection of the same scene (the fixed point K u = f(u)). Mode 1
// carries ~97 % of a cantilever's static tip deflection under a uniform load and the higher
// modes' phase at the turning point moves the peak by up to their share; the electrostatic
// nonlinearity adds O((u/g)^2) ~ 1e-4. Measured: peak / static = 2.024 (converged in the
// tolerance: 2.02502, 2.02507, 2.02510 at atol 1e-5, 1e-6, 1e-7 g on 101 x 30). Held: within
// 3 % of 2. The staggered scheme (IBM load refreshed after each IDA step, gap-scaled inside
// it) against the implicit one (IBM load in every residual): measured 1e-6 apart, held 1e-3.
TEST(ImmersedSwitch, SmallStepSwingsToTwiceTheStaticDeflection) {
  Cantilever c(46, 4, 101, 31);
  const ImmersedStatic st = c.scene->solve_static(30.0);
  ASSERT_LT(st.control, 0);
  ImmersedRunOptions o = run_options(1.2e-6, 3e-6);
  const DynamicRun staggered = c.scene->run(30.0, o, nullptr);
  ASSERT_GT(staggered.turning_time, 0);
  EXPECT_FALSE(staggered.pulled_in);
  EXPECT_NEAR(staggered.extreme_control / st.control, 2.0, 0.06);
  // The first turning point near half the Euler-Bernoulli period (1.76 us).
  EXPECT_NEAR(staggered.turning_time / (0.5 * c.scene->first_bending_period()), 1.0, 0.05);
  o.coupling = ImmersedCoupling::Implicit;
  const DynamicRun implicit = c.scene->run(30.0, o, nullptr);
  EXPECT_NEAR(staggered.extreme_control / implicit.extreme_control, 1.0, 1e-3);
  RecordProperty("peak_over_static", std::to_string(staggered.extreme_control / st.control));
  RecordProperty("staggered_over_implicit",
                 std::to_string(staggered.extreme_control / implicit.extreme_control));
}

// Dynamic pull-in by bisection on the coarse scene (46 x 4 beam, 101 x 31 background), within
// a bracket from the distributed closed form: 0.91 x 132.5 V = 120.6 V (the undamped
// dynamic/static ratio of a parallel-plate actuator, 0.92 lumped, 0.91 thesis); the coarse
// beam is stiffer by a few per cent, so +-8 %. Measured: 123.6 V on 100 x 30 (grid-aligned).
TEST(ImmersedSwitch, CoarseBisectionWithinTheClosedFormBracket) {
  Cantilever c(46, 4, 101, 31);
  const ImmersedRunOptions o = run_options(4e-6, 3e-5);
  const Real expected = 0.91 * distributed_pull_in();
  const DynamicPullIn pi = find_dynamic_pull_in([&](Real v) { return c.scene->run(v, o, nullptr); },
                                                112, 132, 2.5, o.end_time);
  EXPECT_NEAR(pi.voltage / expected, 1.0, 0.08);
  EXPECT_LE(pi.voltage - pi.lower, 2.5);
  EXPECT_GT(pi.pull_in_time, 0.5 * c.scene->first_bending_period());
  RecordProperty("dynamic_pull_in_V", std::to_string(pi.voltage));
  RecordProperty("pull_in_time_s", std::to_string(pi.pull_in_time));
}

// The Reynolds film under a rigid beam closing at a constant slow velocity w (w < 0) reaches
// the incompressible squeeze film: p - p_a = 6 mu_eff w (x^2 - L^2) / h^3 (zero flux at the
// anchor x = 0, ambient at the tip x = L), force 4 mu_eff |w| L^3 / h^3 (opening). Second-order
// FV on 90 cells: within 0.5 %; with Veijola's mu_eff = mu / (1 + 9.638 Kn^1.159).
TEST(ImmersedSwitch, ReynoldsFilmReachesTheIncompressibleSqueezeForce) {
  const int n = 90;
  std::vector<Vec3> vertices;
  for (int i = 0; i <= n; ++i) vertices.emplace_back(kLength * i / n, kGap, 0);
  vertices.emplace_back(kLength, kGap + kThickness, 0);
  vertices.emplace_back(0, kGap + kThickness, 0);
  ImmersedSurface beam(vertices);
  std::vector<Index> bottom;
  for (Index k = 0; k < beam.n_segments(); ++k)
    if (beam.normal(k).y() < -0.5) bottom.push_back(k);
  ASSERT_EQ(static_cast<int>(bottom.size()), n);
  GasProperties gas;
  gas.ambient_pressure = 1e5;
  gas.reference_pressure = 1e5;
  gas.viscosity = 1.8e-5;
  gas.mean_free_path = 65e-9;
  ImmersedReynoldsFilm film(gas, bottom, 0.0, 0.0, kLength);
  film.reset(beam, 0.0);
  const Real w = -1e-4, dt = 1e-6;  // slow: the film is incompressible (squeeze number << 1)
  std::vector<Vec3> force;
  ImmersedSurface moving = beam;
  for (int step = 1; step <= 40; ++step) {
    moving = beam.translated(Vec3(0, w * dt * step, 0));
    force = film.advance(moving, {}, dt * (step - 1), dt);
  }
  Real total = 0;
  for (const Vec3& f : force) total += f.y();
  const Real h = kGap + w * dt * 40;
  const Real mu_eff = gas.effective_viscosity(gas.ambient_pressure, h);
  const Real expected = 4 * mu_eff * std::abs(w) * std::pow(kLength, 3) / std::pow(h, 3);
  EXPECT_NEAR(total / expected, 1.0, 5e-3);
  EXPECT_GT(film.max_knudsen(), 0.04);
}

}  // namespace
}  // namespace rfmems

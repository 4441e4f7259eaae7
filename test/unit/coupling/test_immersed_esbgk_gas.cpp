// The ESBGK gas in the coupled immersed switch: the ImmersedGasModel adapter
// (ibm/immersed_esbgk_gas.hpp) on a coarse scene (76 x 26 background, 45 x 3 beam, 6^3 velocities),
// against the gas alone (ImmersedKineticGas driven directly) and the gas at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "../../support/cantilever_switch_scene.hpp"
#include "ibm/immersed_boundary_field.hpp"
#include "ibm/immersed_esbgk_gas.hpp"
#include "mesh/structured_mesh.hpp"

namespace rfmems {
namespace {

using namespace rfmems::test;

constexpr Real kP0 = 1.36e4, kT0 = 300;

// The coarse scene: 45 x 3 beam, 76 x 26 background, electrode under the beam.
struct CoarseSwitch : Cantilever {
  CoarseSwitch() : Cantilever(45, 3, 76, 26) {}
};

ImmersedEsbgkSettings air(int velocities, Real tolerance) {
  ImmersedEsbgkSettings s;
  s.gas.R = 287.05;
  s.gas.mu_ref = 1.712e-5;
  s.gas.T_ref = 273.15;
  s.gas.omega = 0.74;
  s.pressure = kP0;
  s.temperature = kT0;
  s.velocities = velocities;
  s.options.step_tolerance = tolerance;
  return s;
}

// The beam's rest shape bent down by the static cantilever shape to tip deflection d.
ImmersedSurface bent(const ImmersedSurface& rest, Real d) {
  std::vector<Vec3> v = rest.vertices();
  for (Vec3& x : v) {
    const Real s = std::clamp(x.x() / kLength, 0.0, 1.0);
    x.y() -= d * s * s * (3 - s) / 2;
  }
  ImmersedSurface out = rest;
  out.set_vertices(v);
  return out;
}

std::vector<Vec3> shape_velocity(const ImmersedSurface& s, Real v_tip) {
  std::vector<Vec3> u;
  for (Index k = 0; k < s.n_segments(); ++k) {
    const Real x = std::clamp(s.midpoint(k).x() / kLength, 0.0, 1.0);
    u.emplace_back(0, -v_tip * x * x * (3 - x) / 2, 0);
  }
  return u;
}

Real perimeter(const ImmersedSurface& s) {
  Real p = 0;
  for (Index k = 0; k < s.n_segments(); ++k) p += s.length(k);
  return p;
}

// A body at rest in gas at (p0, T0) with the walls and the pressure boundaries at (p0, T0):
// the equilibrium stays, so every IB face i feels p0 S_i (S_i its area vector out of the
// fluid) and the segments carry the sum. The beam is clamped in the left wall, so the IB faces
// do not close around it: the net force is -p0 times the IB faces' net x-area on the tip
// (the staircase, 5 cells = 1.92 um here against the 1.5 um tip face) and zero in y, both to
// round-off of p0 times the perimeter (measured: F_y = -7.5e-17 N/m of 1.29 N/m).
TEST(ImmersedEsbgkGas, AtRestEveryIbFaceFeelsTheAmbientPressure) {
  CoarseSwitch c;
  const ImmersedSurface& rest = c.scene->rest_surface();
  ImmersedEsbgkGas gas(c.scene->background(), air(6, 1e-10), 0.0);
  gas.reset(rest, 0.0);
  const std::vector<Vec3> zero(rest.n_segments(), Vec3::Zero());
  const Real scale = kP0 * perimeter(rest);
  for (int step = 0; step < 3; ++step) {
    const std::vector<Vec3> f = gas.advance(rest, zero, step * 1e-8, 1e-8);
    ASSERT_TRUE(gas.last_step().converged);
    // Expected: p0 sum_i S_i over the IB faces.
    const FluidFaceGraph& fluid = gas.kinetic().fluid();
    Vec3 expected = Vec3::Zero();
    for (Index face = fluid.graph.n_interior_faces; face < fluid.graph.n_faces(); ++face)
      if (fluid.ib_face[face] >= 0) expected += kP0 * fluid.graph.face_area[face];
    Vec3 total = Vec3::Zero();
    for (const Vec3& x : f) total += x;
    EXPECT_LT((total - expected).norm(), 1e-10 * scale) << "step " << step;
    EXPECT_LT(std::abs(total.y()), 1e-12 * scale) << "step " << step;
    EXPECT_LT(expected.x(), -kP0 * kThickness) << "the staircase covers at least the tip face";
  }
  EXPECT_NEAR(gas.max_knudsen(), gas.mean_free_path() / kGap, 1e-12);
}

// A prescribed slow closing (tip at 1 m/s, the static cantilever shape, two steps): the adapter
// gives the forces of ImmersedKineticGas::step driven directly with the same conditions, to
// round-off; the gas pushes back (the net force on the beam is upward, against the motion).
TEST(ImmersedEsbgkGas, PrescribedClosingMatchesTheGasAloneAndOpposesTheMotion) {
  CoarseSwitch c;
  const ImmersedSurface& rest = c.scene->rest_surface();
  const ImmersedEsbgkSettings s = air(6, 1e-6);
  ImmersedEsbgkGas model(c.scene->background(), s, 0.0);
  model.reset(rest, 0.0);

  const Mesh& bg = c.scene->background();
  const FaceGraph g = face_graph_of(bg);
  std::vector<KineticBoundary> bcs(g.patch_names.size());
  for (const char* wall : {"electrode", "substrate", "left"})
    bcs[g.find_patch(wall)] = KineticBoundary::diffuse_wall(kT0);
  for (const char* open : {"top", "right"})
    bcs[g.find_patch(open)] = KineticBoundary::pressure_outlet(kP0, kT0);
  ImmersedGasOptions o = s.options;
  o.ib.wall_temperature = kT0;
  ImmersedKineticGas alone(bg, bcs, VelocityGrid::uniform(6, 6, 6, 3.5 * s.gas.thermal_speed(kT0)),
                           s.gas, o);
  alone.set_body(rest, std::vector<Vec3>(rest.n_segments(), Vec3::Zero()));
  alone.initialize({kP0 / (s.gas.R * kT0), Vec3::Zero(), kT0});

  const Real v_tip = 1.0, dt = 2e-8;
  for (int n = 1; n <= 2; ++n) {
    const ImmersedSurface body = bent(rest, v_tip * dt * n);
    const std::vector<Vec3> u = shape_velocity(body, v_tip);
    const std::vector<Vec3> fm = model.advance(body, u, (n - 1) * dt, dt);
    const std::vector<Vec3> fa = alone.step(body, u, dt);
    ASSERT_EQ(fm.size(), fa.size());
    Vec3 total = Vec3::Zero();
    Real diff = 0, ref = 0;
    for (std::size_t k = 0; k < fm.size(); ++k) {
      total += fm[k];
      diff += (fm[k] - fa[k]).norm();
      ref += fa[k].norm();
    }
    EXPECT_LE(diff, 1e-13 * ref) << "step " << n;
    EXPECT_GT(total.y(), 0) << "step " << n;
  }
  EXPECT_EQ(model.stats().steps, 2);
  EXPECT_EQ(model.stats().unconverged, 0);
}

// The step's equation does not depend on how it is solved: the point-coupled sweep (COMET's
// cell solve with the step's b V on the diagonal) started from the extrapolated f gives the
// downwind sweeps' forces to the solve tolerance (two BDF steps of the prescribed closing,
// step residual 1e-7 of ||alpha V h / dt||: net force within 1e-4 of the gas force), in
// fewer sweeps.
TEST(ImmersedEsbgkGas, PointCoupledSweepWithPredictorSolvesTheSameStep) {
  CoarseSwitch c;
  const ImmersedSurface& rest = c.scene->rest_surface();
  ImmersedEsbgkSettings downwind = air(6, 1e-7), point = air(6, 1e-7);
  point.options.smoother = GasSmoother::PointCoupled;
  point.options.predictor = true;
  ImmersedEsbgkGas a(c.scene->background(), downwind, 0.0), b(c.scene->background(), point, 0.0);
  a.reset(rest, 0.0);
  b.reset(rest, 0.0);
  const Real v_tip = 1.0, dt = 1e-8;
  for (int n = 1; n <= 2; ++n) {
    const ImmersedSurface body = bent(rest, v_tip * dt * n);
    const std::vector<Vec3> u = shape_velocity(body, v_tip);
    const std::vector<Vec3> fa = a.advance(body, u, (n - 1) * dt, dt);
    const std::vector<Vec3> fb = b.advance(body, u, (n - 1) * dt, dt);
    Vec3 ta = Vec3::Zero(), tb = Vec3::Zero();
    for (std::size_t k = 0; k < fa.size(); ++k) {
      ta += fa[k];
      tb += fb[k];
    }
    EXPECT_GT(ta.y(), 0);
    EXPECT_NEAR(tb.y(), ta.y(), 1e-4 * ta.y()) << "step " << n;
    EXPECT_EQ(b.last_step().predicted, n > 1);
  }
  EXPECT_EQ(a.stats().unconverged + b.stats().unconverged, 0);
  EXPECT_LT(b.stats().sweeps, a.stats().sweeps);
}

// The coupled switch with the ESBGK gas: at 0 V the beam stays at rest and so does the gas
// (net force zero to round-off); at 80 V over the first 20 ns the beam starts closing and the
// gas force on it is upward (it resists the closing) and far below the electrostatic pull.
TEST(ImmersedEsbgkGas, CoupledSwitchRunsAFewStepsWithTheGasForceOfTheGasAlone) {
  CoarseSwitch c;
  DynamicOptions o;
  o.end_time = 2e-8;
  o.contact_gap = 0.2 * kGap;
  o.ida.rtol = 1e-4;
  o.ida.atol = 1e-2 * kGap;
  o.ida.max_order = 2;
  o.coupling.scheme = CouplingScheme::Staggered;
  o.output_interval = o.end_time / 40;  // the samples the gas force is checked at
  auto kinetic = std::make_unique<ImmersedEsbgkGas>(c.scene->background(), air(6, 1e-8), 0.0);
  ImmersedEsbgkGas& gas = *kinetic;
  const std::unique_ptr<StructureGas> on_surface = c.scene->surface_gas(std::move(kinetic));
  const Real scale = kP0 * perimeter(c.scene->rest_surface());

  // At 0 V the only load is the gas's ambient pressure (whose x part on the tip staircase
  // bends the beam by picometres, measured 3.8e-12 m); the gas force in y stays below 1e-7 of
  // p0 times the perimeter (measured <= 5e-8 N/m of 1.29 N/m; the electrostatic pull at 80 V
  // is ~1e-2 N/m).
  const DynamicRun at_rest = c.coupled->run(0.0, o, on_surface.get());
  ASSERT_GT(gas.stats().steps, 0);
  for (const DynamicSample& s : at_rest.history) EXPECT_LT(std::abs(s.gas_force), 1e-7 * scale);
  EXPECT_LT(std::abs(at_rest.extreme_control), 1e-5 * kGap);

  const DynamicRun closing = c.coupled->run(80.0, o, on_surface.get());
  ASSERT_GT(gas.stats().steps, 1);
  EXPECT_EQ(gas.stats().unconverged, 0);
  EXPECT_LT(closing.extreme_control, 0);
  const DynamicSample& last = closing.history.back();
  EXPECT_GT(last.gas_force, 0);
  EXPECT_LT(last.gas_force, 0.1 * std::abs(last.electrostatic_force));
}

}  // namespace
}  // namespace rfmems

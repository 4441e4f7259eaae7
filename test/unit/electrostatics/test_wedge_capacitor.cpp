// Wedge capacitor after mesh motion. A gap mesh [0, L] x [-g0, 0] (L = 100 um, g0 = 2 um,
// 200 x 20 quads) is moved by MeshMotion so that its top wall becomes a plate tilted by alpha
// about the hinge H = (x_h, -g0), x_h = 2 L, where it meets the electrode line: the beam
// rotated about a point beyond its tip (gap g0 at x = 0, g0/2 at x = L). The side walls go
// onto arcs r = const around H (zero flux is then exact); interior nodes follow by blending
// and smoothing. Electrode phi = 0, plate phi = V. In polar coordinates (r, theta) about H,
// theta = pi on the electrode and pi - alpha on the plate:
//
//   phi = V (pi - theta) / alpha,   |E| = V / (alpha r),   p = eps V^2 / (2 alpha^2 r^2),
//   force on the plate  F = eps V^2/(2 alpha^2) (1/r1 - 1/r2)  along -(sin alpha, cos alpha),
//   moment about H      M = eps V^2/(2 alpha^2) ln(r2/r1),     r1 = x_h - L, r2 = x_h.
//
// Asserted: force components and moment within 1 % (they come out within 1e-5), cell
// potentials within 1e-3 V of the exact field, the mesh valid (min volume ratio reported,
// 0.40; asserted > 0.3).
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/mesh_motion.hpp"
#include "physics/electrostatics/electrostatic_solver.hpp"
#include "physics/electrostatics/gap_mesh.hpp"

namespace rfmems {
namespace {

constexpr Real L = 100e-6, g0 = 2e-6, V = 20.0, eps = kVacuumPermittivity;
constexpr Real x_h = 2 * L;
const Real alpha = std::asin(g0 / x_h);
const Vec3 H(x_h, -g0, 0);

// Where a reference node (x, y) goes: radius x_h - x about H, angle pi - alpha (y + g0)/g0.
Vec3 wedge_position(const Vec3& p) {
  const Real r = x_h - p.x(), theta = M_PI - alpha * (p.y() + g0) / g0;
  return H + r * Vec3(std::cos(theta), std::sin(theta), 0);
}

Real exact_potential(const Vec3& p) {
  const Vec3 d = p - H;
  return V * (M_PI - std::atan2(d.y(), d.x())) / alpha;
}

TEST(WedgeCapacitor, ForceAndMomentAfterMeshMotion) {
  GapMeshSpec spec;
  for (int i = 0; i <= 200; ++i) spec.x.push_back(L * i / 200);
  spec.gap = g0;
  spec.n_y = 20;
  Mesh mesh = make_gap_mesh(spec);
  ASSERT_EQ(mesh.find_patch("substrate"), -1);  // the electrode spans the whole bottom

  MeshMotion motion(mesh, {"top", "left", "right"}, {"electrode"});
  std::vector<Vec3> d;
  for (Index n : motion.moving_nodes()) {
    const Vec3& p = motion.reference_nodes()[n];
    d.push_back(wedge_position(p) - p);
  }
  motion.move(d);
  const Real ratio = motion.min_volume_ratio();
  std::printf("wedge mesh: min cell volume ratio %.3f\n", ratio);
  EXPECT_GT(ratio, 0.3);

  ElectrostaticSolver solver(mesh, {{"electrode", PotentialBoundary::potential(0.0)},
                                    {"top", PotentialBoundary::potential(V)},
                                    {"left", PotentialBoundary::zero_flux()},
                                    {"right", PotentialBoundary::zero_flux()}});
  solver.solve();
  const SurfaceLoad load = solver.surface_load("top");
  Real moment = 0;
  for (std::size_t i = 0; i < load.faces.size(); ++i) {
    const Index f = load.faces[i];
    const Vec3 arm = mesh.face_centroid(f) - H;
    const Vec3 force = load.traction[i] * mesh.face_area(f).norm();
    moment += arm.x() * force.y() - arm.y() * force.x();
  }
  const Real r1 = x_h - L, r2 = x_h, k = eps * V * V / (2 * alpha * alpha);
  const Real F = k * (1 / r1 - 1 / r2), M = k * std::log(r2 / r1);
  const Vec3 exact_force = -F * Vec3(std::sin(alpha), std::cos(alpha), 0);
  std::printf("force (%.6e, %.6e) exact (%.6e, %.6e) N/m; moment %.6e exact %.6e N\n",
              load.force.x(), load.force.y(), exact_force.x(), exact_force.y(), moment, M);
  EXPECT_NEAR(load.force.y() / exact_force.y(), 1.0, 0.01);
  EXPECT_NEAR(load.force.x() / exact_force.x(), 1.0, 0.01);
  EXPECT_NEAR(moment / M, 1.0, 0.01);

  Real worst = 0;
  for (Index c = 0; c < mesh.n_cells(); ++c)
    worst =
        std::max(worst, std::abs(solver.potential()[c] - exact_potential(mesh.cell_centroid(c))));
  std::printf("max cell potential error %.3e V (V = %g V)\n", worst, V);
  EXPECT_LT(worst, 1e-3);
}

}  // namespace
}  // namespace rfmems

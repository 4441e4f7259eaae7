// Parallel-plate capacitor: electrode (phi = 0) at y = -g, plate (phi = V) at y = 0, zero-flux
// sides. The exact potential is linear, phi = V (y + g)/g, so a scheme that is exact for
// linear fields must give, to round-off, on every face of the plate:
//   sigma = eps V / g  (minus that on the electrode),  t = -eps V^2/(2 g^2) e_y,
//   total force -eps V^2 L/(2 g^2) e_y per metre of depth.
// Asserted on an orthogonal mesh and on a strongly skewed one (cells sheared by up to 60
// degrees), for reconstruction degrees 1 and 2, and in 3D on sheared hexahedra; the uncorrected
// two-point flux (degree 0) is asserted to be wrong on the skewed mesh by more than 1 % (the
// correction matters). Also: a floating plate carrying the charge Q = eps V L/g rises to phi = V;
// the charges of the two plates are opposite (Gauss); bad boundary input raises InputError.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/electrostatics/electrostatic_solver.hpp"

namespace rfmems {
namespace {

constexpr Real L = 100e-6, g = 2e-6, V = 10.0, eps = kVacuumPermittivity;

Mesh plate_mesh(bool skewed) {
  BoxSpec spec;
  spec.lower = Vec3(0, -g, 0);
  spec.upper = Vec3(L, 0, 0);
  spec.n[0] = 40;
  spec.n[1] = 10;
  if (!skewed) return make_structured_mesh(spec);
  // Sides stay on x = 0, L and plates on y = -g, 0 (nodes slide along them).
  return make_structured_mesh(spec, [](const Vec3& p) {
    const Real xi = p.x() / L, eta = (p.y() + g) / g;
    return Vec3(p.x() + 0.25 * g * std::sin(M_PI * xi) * std::sin(2 * M_PI * eta),
                p.y() + 0.06 * g * std::sin(M_PI * eta) * std::sin(7 * M_PI * xi + 3 * eta), 0);
  });
}

std::map<std::string, PotentialBoundary> plates(PotentialBoundary top) {
  return {{"bottom", PotentialBoundary::potential(0.0)},
          {"top", top},
          {"left", PotentialBoundary::zero_flux()},
          {"right", PotentialBoundary::zero_flux()}};
}

// Largest relative deviation of the plate load from the parallel-plate values.
Real plate_error(const ElectrostaticSolver& solver) {
  const SurfaceLoad top = solver.surface_load("top");
  const Real sigma = eps * V / g, pressure = eps * V * V / (2 * g * g);
  Real error = 0;
  for (std::size_t i = 0; i < top.faces.size(); ++i) {
    error = std::max(error, std::abs(top.charge_density[i] - sigma) / sigma);
    error = std::max(error, (top.traction[i] - Vec3(0, -pressure, 0)).norm() / pressure);
  }
  error = std::max(error, (top.force - Vec3(0, -pressure * L, 0)).norm() / (pressure * L));
  const SurfaceLoad bottom = solver.surface_load("bottom");
  error = std::max(error, std::abs(bottom.charge + sigma * L) / (sigma * L));
  error = std::max(error, (bottom.force - Vec3(0, pressure * L, 0)).norm() / (pressure * L));
  return error;
}

Real potential_error(const Mesh& mesh, const ElectrostaticSolver& solver) {
  Real error = 0;
  for (Index c = 0; c < mesh.n_cells(); ++c)
    error =
        std::max(error, std::abs(solver.potential()[c] - V * (mesh.cell_centroid(c).y() + g) / g));
  return error / V;
}

TEST(ParallelPlate, ExactOnOrthogonalAndSkewedMeshes) {
  for (bool skewed : {false, true})
    for (int degree : {1, 2}) {
      Mesh mesh = plate_mesh(skewed);
      ElectrostaticSolver solver(mesh, plates(PotentialBoundary::potential(V)), {eps, degree});
      solver.solve();
      const Real e = plate_error(solver), ep = potential_error(mesh, solver);
      std::printf("skewed %d degree %d: plate load error %.2e, potential error %.2e\n", skewed,
                  degree, e, ep);
      EXPECT_LT(e, 1e-9) << "skewed " << skewed << " degree " << degree;
      EXPECT_LT(ep, 1e-10) << "skewed " << skewed << " degree " << degree;
    }
}

TEST(ParallelPlate, ExactInThreeDimensionsOnSkewedHexahedra) {
  BoxSpec spec;
  spec.dim = 3;
  spec.lower = Vec3(0, -g, 0);
  spec.upper = Vec3(4 * g, 0, 3 * g);
  spec.n[0] = 8;
  spec.n[1] = 5;
  spec.n[2] = 6;
  Mesh mesh = make_structured_mesh(spec, [](const Vec3& p) {
    const Real eta = (p.y() + g) / g;  // shear x and z with height: non-orthogonal faces
    return Vec3(p.x() + 0.3 * g * std::sin(M_PI * p.x() / (4 * g)) * eta, p.y(),
                p.z() + 0.2 * g * std::sin(M_PI * p.z() / (3 * g)) * eta * eta);
  });
  auto bcs = plates(PotentialBoundary::potential(V));
  bcs["back"] = bcs["front"] = PotentialBoundary::zero_flux();
  ElectrostaticSolver solver(mesh, bcs);
  solver.solve();
  const SurfaceLoad top = solver.surface_load("top");
  Real area = 0;
  for (Index f : top.faces) area += mesh.face_area(f).norm();
  const Real pressure = eps * V * V / (2 * g * g);
  EXPECT_LT((top.force - Vec3(0, -pressure * area, 0)).norm() / (pressure * area), 1e-9);
  EXPECT_NEAR(top.charge, eps * V / g * area, 1e-9 * eps * V / g * area);
  EXPECT_LT(potential_error(mesh, solver), 1e-10);
}

TEST(ParallelPlate, SkewedMeshNeedsTheCorrection) {
  Mesh mesh = plate_mesh(true);
  // Non-orthogonality actually present: the largest angle between a face normal and d.
  Real worst = 0;
  for (Index f = 0; f < mesh.n_interior_faces(); ++f) {
    Vec3 d = mesh.cell_centroid(mesh.face_neighbour(f)) - mesh.cell_centroid(mesh.face_owner(f));
    worst = std::max(worst, std::acos(d.normalized().dot(mesh.face_area(f).normalized())));
  }
  EXPECT_GT(worst * 180 / M_PI, 45.0);
  ElectrostaticSolver solver(mesh, plates(PotentialBoundary::potential(V)), {eps, 0});
  solver.solve();
  const Real e = plate_error(solver);
  std::printf("two-point flux only: plate load error %.3f (max non-orthogonality %.0f deg)\n", e,
              worst * 180 / M_PI);
  EXPECT_GT(e, 0.01);
}

TEST(ParallelPlate, FloatingPlateTakesThePotentialOfItsCharge) {
  Mesh mesh = plate_mesh(true);
  const Real Q = eps * V * L / g;  // C = eps L / g per metre of depth
  ElectrostaticSolver solver(mesh, plates(PotentialBoundary::floating(Q)));
  solver.solve();
  EXPECT_NEAR(solver.patch_potential("top"), V, 1e-10 * V);
  EXPECT_NEAR(solver.surface_load("top").charge, Q, 1e-10 * Q);
  EXPECT_LT(plate_error(solver), 1e-9);
}

TEST(ParallelPlate, BadBoundariesAreInputErrors) {
  Mesh mesh = plate_mesh(false);
  auto bcs = plates(PotentialBoundary::potential(V));
  bcs.erase("left");
  EXPECT_THROW(ElectrostaticSolver(mesh, bcs), InputError);
  bcs = plates(PotentialBoundary::potential(V));
  bcs["hole"] = PotentialBoundary::zero_flux();
  EXPECT_THROW(ElectrostaticSolver(mesh, bcs), InputError);
  bcs = plates(PotentialBoundary::floating());
  bcs["bottom"] = PotentialBoundary::zero_flux();
  EXPECT_THROW(ElectrostaticSolver(mesh, bcs), InputError);  // no potential anywhere
}

}  // namespace
}  // namespace rfmems

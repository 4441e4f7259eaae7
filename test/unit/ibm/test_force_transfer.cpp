// Tests of the load transfer from IB faces to the surface segments and of the dual velocity
// map (lib/ibm/force_transfer).
//
// Asserted, for a circle and for a beam whose surface comes from a structure mesh:
//  - an arbitrary traction field t(x, n) (shear and pressure parts) on the IB faces: the
//    total force and the total moment (about the origin and about another point) on the
//    segments equal those on the IB faces to round-off (1e-13 relative);
//  - hydrostatic pressure p = rho g (y0 - y): the IB faces bound the SOLID + IB cells, so
//    the force they carry is the buoyancy rho g A ez with A the area of those cells (the
//    midpoint rule is exact for linear p), and the segments receive it;
//  - the power balance sum_k F_k . u(x_k) = sum_j f_j . u_j for arbitrary forces and segment
//    velocities (the velocity map is the adjoint of the force map), and a rigid motion
//    U + omega ez x x of the segments is reproduced at every IB face centroid exactly;
//  - every segment the force lands on is within two cells of its IB face (the map is local).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "ibm/cell_marking.hpp"
#include "ibm/force_transfer.hpp"
#include "mesh/structured_mesh.hpp"

namespace rfmems {
namespace {

Mesh unit_square(int n) {
  BoxSpec spec;
  spec.n[0] = spec.n[1] = n;
  return make_structured_mesh(spec);
}

Vec3 total(const std::vector<Vec3>& f) {
  Vec3 s = Vec3::Zero();
  for (const Vec3& v : f) s += v;
  return s;
}

// z-moment about o of forces f applied at points x.
Real moment(const std::vector<Vec3>& f, const std::vector<Vec3>& x, const Vec3& o) {
  Real m = 0;
  for (std::size_t i = 0; i < f.size(); ++i) m += (x[i] - o).cross(f[i]).z();
  return m;
}

struct Scene {
  Mesh mesh;
  ImmersedSurface body;
  CellMarking marking;
  std::vector<Vec3> face_points, segment_points;
  Scene(Mesh m, ImmersedSurface b) : mesh(std::move(m)), body(std::move(b)) {
    CellMarker marker(mesh);
    marking = marker.mark(body);
    for (Index f : marking.ib_faces) face_points.push_back(mesh.face_centroid(f));
    for (Index k = 0; k < body.n_segments(); ++k) segment_points.push_back(body.midpoint(k));
  }
};

std::vector<Scene> scenes() {
  std::vector<Scene> s;
  s.emplace_back(unit_square(32), ImmersedSurface::circle({0.49, 0.52, 0}, 0.23, 90, 0.2));
  BoxSpec beam;
  beam.lower = Vec3(0.21, 0.43, 0);
  beam.upper = Vec3(0.83, 0.55, 0);
  beam.n[0] = 31;
  beam.n[1] = 5;
  s.emplace_back(unit_square(40), ImmersedSurface::from_mesh_boundary(make_structured_mesh(beam)));
  return s;
}

TEST(ForceTransfer, ConservesTotalForceAndMomentOfAnArbitraryTraction) {
  for (Scene& sc : scenes()) {
    ForceTransfer transfer(sc.mesh, sc.marking, sc.body);
    ASSERT_EQ(transfer.n_ib_faces(), static_cast<Index>(sc.marking.ib_faces.size()));
    auto traction = [](const Vec3& x, const Vec3& n) -> Vec3 {
      const Real p = 3 + std::sin(7 * x.x()) * x.y();
      const Vec3 shear(std::cos(5 * x.y()) + x.x() * x.x(), 0.7 * x.x() - std::sin(3 * x.y()), 0);
      return -p * n + shear;
    };
    const std::vector<Vec3> F = transfer.ib_face_forces(traction);
    const std::vector<Vec3> f = transfer.to_surface(F);
    const Real scale = total(F).norm() + 1.0;
    EXPECT_LT((total(f) - total(F)).norm(), 1e-13 * scale);
    for (const Vec3& o : {Vec3(0, 0, 0), Vec3(0.37, -1.2, 0)}) {
      const Real mF = moment(F, sc.face_points, o), mf = moment(f, sc.segment_points, o);
      EXPECT_NEAR(mf, mF, 1e-13 * (std::abs(mF) + scale)) << "about " << o.transpose();
    }
    std::printf("force %.6e %.6e, moment %.6e on %ld IB faces -> %ld segments\n", total(F).x(),
                total(F).y(), moment(F, sc.face_points, Vec3::Zero()), static_cast<long>(F.size()),
                static_cast<long>(f.size()));
  }
}

TEST(ForceTransfer, HydrostaticPressureGivesTheBuoyancyOfTheMarkedCells) {
  const Real rho = 1.3, g = 9.81, y0 = 2.0;
  for (Scene& sc : scenes()) {
    ForceTransfer transfer(sc.mesh, sc.marking, sc.body);
    // Pressure pushes along the normal out of the fluid, into the body.
    const auto F = transfer.ib_face_forces(
        [&](const Vec3& x, const Vec3& n) -> Vec3 { return rho * g * (y0 - x.y()) * n; });
    const Real area = sc.marking.area(sc.mesh, CellClass::Solid) +
                      sc.marking.area(sc.mesh, CellClass::ImmersedBoundary);
    const Vec3 buoyancy(0, rho * g * area, 0);
    EXPECT_LT((total(F) - buoyancy).norm(), 1e-12 * buoyancy.norm());
    EXPECT_LT((total(transfer.to_surface(F)) - buoyancy).norm(), 1e-12 * buoyancy.norm());
    // and it is the body's buoyancy to within the one-cell-thick IB layer
    EXPECT_NEAR(area, sc.body.area(),
                2.5 * sc.body.perimeter() * std::sqrt(sc.mesh.cell_volume(0)));
  }
}

TEST(ForceTransfer, VelocityMapIsTheAdjointAndReproducesRigidMotion) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(-1, 1);
  for (Scene& sc : scenes()) {
    ForceTransfer transfer(sc.mesh, sc.marking, sc.body);
    std::vector<Vec3> F(transfer.n_ib_faces()), v(transfer.n_segments());
    for (Vec3& x : F) x = Vec3(u(rng), u(rng), 0);
    for (Vec3& x : v) x = Vec3(u(rng), u(rng), 0);
    const auto f = transfer.to_surface(F);
    const auto uf = transfer.to_ib_faces(v);
    Real power_faces = 0, power_segments = 0;
    for (std::size_t k = 0; k < F.size(); ++k) power_faces += F[k].dot(uf[k]);
    for (std::size_t j = 0; j < f.size(); ++j) power_segments += f[j].dot(v[j]);
    EXPECT_NEAR(power_faces, power_segments, 1e-13 * F.size());

    const Vec3 U(0.3, -0.8, 0), z(0, 0, 1);
    const Real omega = 2.5;
    auto rigid = [&](const Vec3& x) -> Vec3 { return U + omega * z.cross(x); };
    std::vector<Vec3> vr;
    for (const Vec3& y : sc.segment_points) vr.push_back(rigid(y));
    const auto ur = transfer.to_ib_faces(vr);
    for (std::size_t k = 0; k < ur.size(); ++k)
      EXPECT_LT((ur[k] - rigid(sc.face_points[k])).norm(), 1e-13) << "IB face " << k;
  }
}

TEST(ForceTransfer, LoadsLandNearTheirFace) {
  for (Scene& sc : scenes()) {
    ForceTransfer transfer(sc.mesh, sc.marking, sc.body);
    const Real h = std::sqrt(sc.mesh.cell_volume(0));
    for (Index k = 0; k < transfer.n_ib_faces(); ++k) {
      std::vector<Vec3> F(transfer.n_ib_faces(), Vec3::Zero());
      F[k] = Vec3(1, 1, 0);
      const auto f = transfer.to_surface(F);
      for (Index j = 0; j < transfer.n_segments(); ++j)
        if (f[j].norm() > 0) {
          EXPECT_LT((sc.segment_points[j] - sc.face_points[k]).norm(), 2.5 * h);
        }
    }
  }
}

}  // namespace
}  // namespace rfmems

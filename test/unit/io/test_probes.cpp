// Point search and probes: the KD-tree against a brute-force search, probes attached to the
// nearest cell, and the errors for points outside the mesh and for bad names.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "core/error.hpp"
#include "io/point_locator.hpp"
#include "io/probes.hpp"
#include "mesh/structured_mesh.hpp"

namespace rfmems {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// 2D points and queries have z = 0, so the 3D distance serves both.
Index brute_force_nearest(const std::vector<Vec3>& points, const Vec3& x) {
  Index best = 0;
  Real best_d = 1e300;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Real d = (points[i] - x).squaredNorm();
    if (d < best_d) best_d = d, best = static_cast<Index>(i);
  }
  return best;
}

TEST(PointLocator, MatchesBruteForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int dim : {2, 3}) {
    std::vector<Vec3> points(500);
    for (Vec3& p : points) p = Vec3(u(rng), u(rng), dim == 3 ? u(rng) : 0.0);
    const PointLocator locator(points, dim);
    EXPECT_EQ(locator.size(), 500);
    for (int q = 0; q < 200; ++q) {
      const Vec3 x(1.5 * u(rng), 1.5 * u(rng), dim == 3 ? 1.5 * u(rng) : 0.0);
      const Index found = locator.nearest(x);
      // Compare distances, not indices: exact ties may resolve either way.
      EXPECT_DOUBLE_EQ((points[found] - x).squaredNorm(),
                       (points[brute_force_nearest(points, x)] - x).squaredNorm());
    }
  }
}

// 2 m x 0.04 m beam, 20 x 4 cells, lower corner (0, -0.02).
Mesh beam() {
  BoxSpec spec;
  spec.lower = Vec3(0, -0.02, 0);
  spec.upper = Vec3(2, 0.02, 0);
  spec.n[0] = 20;
  spec.n[1] = 4;
  return make_structured_mesh(spec);
}

std::vector<Probe> probes_from(const std::string& yaml, const Mesh& mesh) {
  const CaseFile cf = CaseFile::parse(yaml, "p.yaml");
  return read_probes(cf.root().child_or_empty("probes"), mesh);
}

TEST(Probes, AttachToTheNearestCell) {
  const Mesh mesh = beam();
  const auto probes = probes_from(
      "probes:\n  - {name: tip, at: [2 m, 0.015 m]}\n  - {name: root, at: [1 mm, -19 mm]}\n", mesh);
  ASSERT_EQ(probes.size(), 2u);
  EXPECT_EQ(probes[0].name, "tip");
  EXPECT_TRUE(probes[0].at.isApprox(Vec3(2, 0.015, 0)));
  // Cells are 0.1 x 0.01 m: the tip point sits in the last column, top row.
  EXPECT_NEAR(mesh.cell_centroid(probes[0].cell).x(), 1.95, 1e-12);
  EXPECT_NEAR(mesh.cell_centroid(probes[0].cell).y(), 0.015, 1e-12);
  EXPECT_NEAR(mesh.cell_centroid(probes[1].cell).x(), 0.05, 1e-12);
  EXPECT_NEAR(mesh.cell_centroid(probes[1].cell).y(), -0.015, 1e-12);
}

TEST(Probes, NoneWithoutTheKey) { EXPECT_TRUE(probes_from("name: x\n", beam()).empty()); }

TEST(Probes, PointOutsideTheMeshIsAnInputErrorNamingTheProbe) {
  const Mesh mesh = beam();
  const std::string message =
      error_of([&] { probes_from("probes:\n  - {name: far, at: [2.1, 0]}\n", mesh); });
  EXPECT_NE(message.find("p.yaml: key 'probes[0].at'"), std::string::npos) << message;
  EXPECT_NE(message.find("probe 'far' lies outside the mesh"), std::string::npos) << message;
  // On the boundary (within round-off) is inside.
  EXPECT_EQ(
      error_of([&] { probes_from("probes:\n  - {name: edge, at: [2.0000000001, 0.02]}\n", mesh); }),
      "");
}

TEST(Probes, NamesMustBeUniqueAndPlain) {
  const Mesh mesh = beam();
  EXPECT_NE(error_of([&] {
              probes_from("probes:\n  - {name: a, at: [1, 0]}\n  - {name: a, at: [0, 0]}\n", mesh);
            }).find("another probe has this name"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              probes_from("probes:\n  - {name: a/b, at: [1, 0]}\n", mesh);
            }).find("'probes[0].name'"),
            std::string::npos);
}

TEST(ProbeHistory, KeepsSamplesAndExtremes) {
  ProbeHistory h(2);
  h.add(0.0, {Vec3(0, 0, 0), Vec3(1, 1, 1)});
  h.add(0.1, {Vec3(0, -3, 0), Vec3(1, 2, 1)});
  EXPECT_EQ(h.n_samples(), 2u);
  EXPECT_EQ(h.max_abs(0, 1), 3.0);
  EXPECT_EQ(h.max_abs(1, 1), 2.0);
  const auto rows = h.series(0);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1], (std::vector<double>{0, -3, 0}));
  EXPECT_THROW(h.add(0.2, {Vec3::Zero()}), std::logic_error);
}

}  // namespace
}  // namespace rfmems

// The plate's gap quadrature (plate_gap_elements, plate_scene.cpp): the points at which the
// parallel-plate pressure, the contact and the creep hold load sample the gap. With a cubic
// deflection w(x, y) given at the cell centroids and as the edges' prescribed w, the cubic
// reconstruction of w is exact, so each point's u_q is w there and the rule's error is its own:
//   - triangles (7 points: corners 1/20, edge midpoints 2/15, centroid 9/20) and parallelogram
//     quadrilaterals (3 x 3 Simpson points) integrate the cubic exactly: sum_q a_q u_q equals
//     the cell mean of w (against the 4-point degree-3 triangle rule of Strang & Fix, on
//     each triangle, or the two halves of each quadrilateral);
//   - every corner of every cell is a point (so the smallest gap of the reconstructed surface,
//     on the cell's edges where the free edges curl towards the electrode, is sampled).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "mesh/structured_mesh.hpp"
#include "physics/plate/plate_scene.hpp"

using namespace rfmems;

namespace {

Real cubic(const Vec3& p) {
  const Real x = p.x(), y = p.y();
  return 1 + 0.3 * x - 0.2 * y + 0.5 * x * x - 0.4 * x * y + 0.25 * y * y + 0.7 * x * x * x -
         0.3 * x * x * y + 0.2 * x * y * y - 0.6 * y * y * y;
}

// The integral of the cubic over a triangle: Strang & Fix's 4-point rule, exact for degree 3
// (centroid -27/48, the points (0.6, 0.2, 0.2) and permutations 25/48).
Real triangle_integral(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Real area = 0.5 * std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  Real sum = -27.0 / 48 * cubic((a + b + c) / 3);
  for (const Vec3& p : {Vec3(0.6 * a + 0.2 * b + 0.2 * c), Vec3(0.2 * a + 0.6 * b + 0.2 * c),
                        Vec3(0.2 * a + 0.2 * b + 0.6 * c)})
    sum += 25.0 / 48 * cubic(p);
  return area * sum;
}

// n x n squares of [0, 1]^2, each split into two triangles (diagonals alternating).
Mesh triangle_mesh(int n) {
  MeshBuilder b(2);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) b.add_node(Vec3(Real(i) / n, Real(j) / n, 0));
  auto node = [n](int i, int j) { return Index(j) * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Index p = node(i, j), q = node(i + 1, j), r = node(i + 1, j + 1), s = node(i, j + 1);
      if ((i + j) % 2 == 0) {
        b.add_cell(CellShape::Triangle, {p, q, r});
        b.add_cell(CellShape::Triangle, {p, r, s});
      } else {
        b.add_cell(CellShape::Triangle, {p, q, s});
        b.add_cell(CellShape::Triangle, {q, r, s});
      }
    }
  for (int k = 0; k < n; ++k) {
    b.add_boundary_face({node(k, 0), node(k + 1, 0)}, "bottom");
    b.add_boundary_face({node(k, n), node(k + 1, n)}, "top");
    b.add_boundary_face({node(0, k), node(0, k + 1)}, "left");
    b.add_boundary_face({node(n, k), node(n, k + 1)}, "right");
  }
  return b.build("triangles");
}

// Parallelograms: the structured n x n square sheared (an affine map).
Mesh parallelogram_mesh(int n) {
  BoxSpec spec;
  spec.upper = Vec3(1, 1, 0);
  spec.n[0] = n;
  spec.n[1] = n;
  return make_structured_mesh(spec,
                              [](const Vec3& x) { return Vec3(x.x() + 0.3 * x.y(), x.y(), 0); });
}

struct RuleErrors {
  Real fraction_sum = 0, mean = 0, corner = 0;  // max |error| over the cells
  std::size_t points = 0;                       // per cell (all cells alike)
};

RuleErrors rule_errors(const Mesh& mesh) {
  PlateSection s;
  s.E = 200e9;
  s.nu = 0.3;
  s.rho = 7854;
  s.thickness = 0.05;
  std::vector<PlateBoundary> bcs(mesh.patches().size());
  for (PlateBoundary& bc : bcs) {
    bc.kind = PlateBoundary::Kind::Displacement;
    bc.value = [](const Vec3& x, Real) { return Vec3(cubic(x), 0, 0); };
  }
  const PlateOperator plate(mesh, s, bcs, [](const Vec3&, Real) { return 0.0; });
  std::vector<Real> y(3 * mesh.n_cells(), 0.0);
  for (Index c = 0; c < mesh.n_cells(); ++c) y[3 * c] = cubic(mesh.cell_centroid(c));

  RuleErrors e;
  const std::vector<GapElement> elements = plate_gap_elements(mesh, plate);
  for (const GapElement& el : elements) {
    const Index c = el.dof / 3;
    const auto nodes = mesh.cell_nodes(c);
    std::vector<Vec3> x;
    for (Index k : nodes) x.push_back(mesh.nodes()[k]);
    const Real exact = (x.size() == 3 ? triangle_integral(x[0], x[1], x[2])
                                      : triangle_integral(x[0], x[1], x[2]) +
                                            triangle_integral(x[0], x[2], x[3])) /
                       mesh.cell_volume(c);
    Real fractions = 0, mean = 0;
    for (const GapPoint& q : el.points) {
      fractions += q.area_fraction;
      mean += q.area_fraction * gap_displacement(q, y);
    }
    e.points = el.points.size();
    e.fraction_sum = std::max(e.fraction_sum, std::abs(fractions - 1));
    e.mean = std::max(e.mean, std::abs(mean - exact));
    for (const Vec3& corner : x) {
      Real nearest = 1e300;
      for (const GapPoint& q : el.points)
        nearest = std::min(nearest, std::abs(gap_displacement(q, y) - cubic(corner)));
      e.corner = std::max(e.corner, nearest);
    }
  }
  return e;
}

}  // namespace

TEST(PlateGapPoints, TrianglesAndParallelogramsIntegrateACubicExactly) {
  for (const bool triangles : {true, false}) {
    const Mesh mesh = triangles ? triangle_mesh(6) : parallelogram_mesh(6);
    const RuleErrors e = rule_errors(mesh);
    std::printf(
        "%s: %zu points per cell; max |sum a_q - 1| %.1e, |mean - exact| %.1e, "
        "corner not a point by %.1e\n",
        triangles ? "triangles" : "parallelograms", e.points, e.fraction_sum, e.mean, e.corner);
    EXPECT_EQ(e.points, triangles ? 7u : 9u);
    EXPECT_LT(e.fraction_sum, 1e-14);
    EXPECT_LT(e.mean, 1e-10);
    EXPECT_LT(e.corner, 1e-10);
  }
}

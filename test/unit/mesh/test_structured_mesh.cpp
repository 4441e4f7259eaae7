// Tests of the structured generators (graded rectangles of quads, graded boxes of hexahedra).
//
// Asserted, for a graded rectangle and a graded box: the total volume is exact (also under a
// volume-preserving shear map, which makes the cells non-orthogonal); the cell and face counts;
// every boundary face belongs to the patch of its side, with the outward unit normal of that
// side and its centroid on the side; the patch areas; the grading (last/first cell size along
// each axis equals the requested ratio); every cell is closed (its outward area vectors sum to
// zero, the discrete divergence theorem the FV balance relies on); graded_points itself; and
// the geometry checks: a mirrored node map (inverted cells) and a map that collapses the
// nodes onto a line (zero volume) both raise MeshError, as do bad counts and gradings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/structured_mesh.hpp"

namespace rfmems {
namespace {

Real total_volume(const Mesh& mesh) {
  Real v = 0;
  for (Index c = 0; c < mesh.n_cells(); ++c) v += mesh.cell_volume(c);
  return v;
}

const Patch& patch(const Mesh& mesh, const std::string& name) {
  const int p = mesh.find_patch(name);
  if (p < 0) throw std::runtime_error("no patch " + name);
  return mesh.patches()[p];
}

// Outward unit normal, axis and coordinate of each side of the box spec.
struct Side {
  Vec3 normal;
  int axis;
  Real coordinate;
};

std::map<std::string, Side> sides(const BoxSpec& s) {
  std::map<std::string, Side> m{{"left", {Vec3(-1, 0, 0), 0, s.lower.x()}},
                                {"right", {Vec3(1, 0, 0), 0, s.upper.x()}},
                                {"bottom", {Vec3(0, -1, 0), 1, s.lower.y()}},
                                {"top", {Vec3(0, 1, 0), 1, s.upper.y()}}};
  if (s.dim == 3) {
    m["back"] = {Vec3(0, 0, -1), 2, s.lower.z()};
    m["front"] = {Vec3(0, 0, 1), 2, s.upper.z()};
  }
  return m;
}

// Sum of the outward area vectors of each cell; returns the largest relative to the cell's
// total face area.
Real worst_closure(const Mesh& mesh) {
  Real worst = 0;
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    Vec3 sum = Vec3::Zero();
    Real scale = 0;
    for (Index f : mesh.cell_faces(c)) {
      const Vec3& S = mesh.face_area(f);
      sum += mesh.face_owner(f) == c ? S : Vec3(-S);
      scale += S.norm();
    }
    worst = std::max(worst, sum.norm() / scale);
  }
  return worst;
}

// Sizes of the boundary faces of `name` along axis `axis`, ordered by their centroid on it
// (the faces of one row/column of cells when the other axes have one cell).
std::vector<Real> face_sizes_along(const Mesh& mesh, const std::string& name, int axis) {
  const Patch& p = patch(mesh, name);
  std::vector<std::pair<Real, Real>> faces;
  for (Index f = p.first_face; f < p.first_face + p.n_faces; ++f) {
    Real lo = 1e300, hi = -1e300;
    for (Index n : mesh.face_nodes(f)) {
      lo = std::min(lo, mesh.nodes()[n][axis]);
      hi = std::max(hi, mesh.nodes()[n][axis]);
    }
    faces.emplace_back(mesh.face_centroid(f)[axis], hi - lo);
  }
  std::sort(faces.begin(), faces.end());
  std::vector<Real> sizes;
  for (auto& [x, s] : faces) sizes.push_back(s);
  return sizes;
}

void check_boundary(const Mesh& mesh, const BoxSpec& spec) {
  const Vec3 extent = spec.upper - spec.lower;
  for (const auto& [name, side] : sides(spec)) {
    const Patch& p = patch(mesh, name);
    // Faces on this side: the product of the cell counts along the other axes.
    Index expected = 1;
    for (int d = 0; d < spec.dim; ++d)
      if (d != side.axis) expected *= spec.n[d];
    EXPECT_EQ(p.n_faces, expected) << name;
    Real area = 0;
    for (Index f = p.first_face; f < p.first_face + p.n_faces; ++f) {
      ASSERT_TRUE(mesh.is_boundary(f));
      EXPECT_EQ(mesh.face_neighbour(f), -1);
      const Vec3& S = mesh.face_area(f);
      EXPECT_NEAR((S / S.norm() - side.normal).norm(), 0.0, 1e-12) << name << " face " << f;
      EXPECT_NEAR(mesh.face_centroid(f)[side.axis], side.coordinate, 1e-12)
          << name << " face " << f;
      area += S.norm();
    }
    // Side area (2D: length times unit depth).
    Real exact = 1;
    for (int d = 0; d < spec.dim; ++d)
      if (d != side.axis) exact *= extent[d];
    EXPECT_NEAR(area, exact, 1e-12 * exact) << name;
  }
  // Every boundary face is on one of the sides: nothing falls into a default patch.
  Index boundary_faces = 0;
  for (const Patch& p : mesh.patches()) boundary_faces += p.n_faces;
  EXPECT_EQ(boundary_faces, mesh.n_faces() - mesh.n_interior_faces());
  EXPECT_EQ(mesh.patches().size(), sides(spec).size());
}

BoxSpec graded_rectangle() {
  BoxSpec s;
  s.dim = 2;
  s.lower = Vec3(-1.0, 0.5, 0);
  s.upper = Vec3(2.0, 1.5, 0);
  s.n[0] = 12;
  s.n[1] = 5;
  s.grading[0] = 4.0;
  s.grading[1] = 0.25;
  return s;
}

BoxSpec graded_box() {
  BoxSpec s;
  s.dim = 3;
  s.lower = Vec3(0, -0.5, 1.0);
  s.upper = Vec3(2.0, 0.5, 1.3);
  s.n[0] = 6;
  s.n[1] = 4;
  s.n[2] = 3;
  s.grading[0] = 3.0;
  s.grading[1] = 1.0;
  s.grading[2] = 0.5;
  return s;
}

}  // namespace

TEST(GradedPoints, EndpointsAndRatio) {
  const std::vector<Real> x = graded_points(1.0, 3.0, 7, 5.0);
  ASSERT_EQ(x.size(), 8u);
  EXPECT_EQ(x.front(), 1.0);
  EXPECT_EQ(x.back(), 3.0);
  EXPECT_NEAR((x[7] - x[6]) / (x[1] - x[0]), 5.0, 1e-12);
  // Geometric: every consecutive ratio is the same, 5^(1/6).
  for (int i = 1; i < 7; ++i)
    EXPECT_NEAR((x[i + 1] - x[i]) / (x[i] - x[i - 1]), std::pow(5.0, 1.0 / 6.0), 1e-12);
  // Uniform and single-cell cases.
  const std::vector<Real> u = graded_points(0.0, 1.0, 4, 1.0);
  for (int i = 0; i <= 4; ++i) EXPECT_NEAR(u[i], 0.25 * i, 1e-15);
  EXPECT_EQ(graded_points(0.0, 2.0, 1, 3.0), (std::vector<Real>{0.0, 2.0}));
  EXPECT_THROW(graded_points(0.0, 1.0, 0, 1.0), MeshError);
  EXPECT_THROW(graded_points(0.0, 1.0, 4, 0.0), MeshError);
  EXPECT_THROW(graded_points(0.0, 1.0, 4, -2.0), MeshError);
}

TEST(StructuredMesh, GradedRectangle) {
  const BoxSpec spec = graded_rectangle();
  const Mesh mesh = make_structured_mesh(spec);
  const int nx = spec.n[0], ny = spec.n[1];
  EXPECT_EQ(mesh.dim(), 2);
  EXPECT_EQ(mesh.n_cells(), nx * ny);
  EXPECT_EQ(mesh.n_nodes(), (nx + 1) * (ny + 1));
  EXPECT_EQ(mesh.n_interior_faces(), (nx - 1) * ny + nx * (ny - 1));
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    EXPECT_EQ(mesh.cell_shape(c), CellShape::Quad);
    EXPECT_GT(mesh.cell_volume(c), 0.0);
  }
  EXPECT_NEAR(total_volume(mesh), 3.0 * 1.0, 1e-12);
  check_boundary(mesh, spec);
  EXPECT_LT(worst_closure(mesh), 1e-14);

  // Grading: last/first sizes along x (bottom faces) and y (left faces).
  const std::vector<Real> sx = face_sizes_along(mesh, "bottom", 0),
                          sy = face_sizes_along(mesh, "left", 1);
  ASSERT_EQ(sx.size(), static_cast<std::size_t>(nx));
  ASSERT_EQ(sy.size(), static_cast<std::size_t>(ny));
  EXPECT_NEAR(sx.back() / sx.front(), 4.0, 1e-12);
  EXPECT_NEAR(sy.back() / sy.front(), 0.25, 1e-12);
  // A top face has the size of the bottom face below it (the grading is per axis).
  EXPECT_EQ(face_sizes_along(mesh, "top", 0), sx);
}

TEST(StructuredMesh, GradedBox) {
  const BoxSpec spec = graded_box();
  const Mesh mesh = make_structured_mesh(spec);
  const int nx = spec.n[0], ny = spec.n[1], nz = spec.n[2];
  EXPECT_EQ(mesh.dim(), 3);
  EXPECT_EQ(mesh.n_cells(), nx * ny * nz);
  EXPECT_EQ(mesh.n_nodes(), (nx + 1) * (ny + 1) * (nz + 1));
  EXPECT_EQ(mesh.n_interior_faces(), (nx - 1) * ny * nz + nx * (ny - 1) * nz + nx * ny * (nz - 1));
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    EXPECT_EQ(mesh.cell_shape(c), CellShape::Hexa);
    EXPECT_EQ(mesh.cell_faces(c).size(), 6u);
  }
  EXPECT_NEAR(total_volume(mesh), 2.0 * 1.0 * 0.3, 1e-12);
  check_boundary(mesh, spec);
  EXPECT_LT(worst_closure(mesh), 1e-14);

  // Sizes along x, y, z from the faces of one side each. A side holds several rows of faces
  // with the same size sequence; ordered by position, the first and last are end cells.
  auto ratio = [&](const std::string& side, int axis) {
    std::vector<Real> s = face_sizes_along(mesh, side, axis);
    return s.back() / s.front();
  };
  EXPECT_NEAR(ratio("bottom", 0), 3.0, 1e-12);
  EXPECT_NEAR(ratio("left", 1), 1.0, 1e-12);
  EXPECT_NEAR(ratio("left", 2), 0.5, 1e-12);
}

TEST(StructuredMesh, ShearedCellsKeepVolumeAndClosure) {
  // x' = x + 0.4 y (+ 0.2 z) has unit Jacobian: the cells become parallelograms/parallelepipeds
  // with non-orthogonal faces, yet the volume is unchanged.
  for (const BoxSpec& spec : {graded_rectangle(), graded_box()}) {
    const Mesh plain = make_structured_mesh(spec);
    const Mesh sheared = make_structured_mesh(
        spec, [](const Vec3& x) { return Vec3(x.x() + 0.4 * x.y() + 0.2 * x.z(), x.y(), x.z()); });
    EXPECT_NEAR(total_volume(sheared), total_volume(plain), 1e-12);
    for (Index c = 0; c < plain.n_cells(); ++c)
      EXPECT_NEAR(sheared.cell_volume(c), plain.cell_volume(c), 1e-12 * plain.cell_volume(c));
    EXPECT_LT(worst_closure(sheared), 1e-14);
  }
}

TEST(StructuredMesh, InvertedMapRaisesMeshError) {
  // Mirroring x reverses the orientation of every cell: non-positive volumes.
  const NodeMap mirror = [](const Vec3& x) { return Vec3(-x.x(), x.y(), x.z()); };
  EXPECT_THROW(make_structured_mesh(graded_rectangle(), mirror), MeshError);
  EXPECT_THROW(make_structured_mesh(graded_box(), mirror), MeshError);
}

TEST(StructuredMesh, DegenerateMapRaisesMeshError) {
  // All nodes on the x axis: zero cell volumes (and zero-area faces).
  const NodeMap collapse = [](const Vec3& x) { return Vec3(x.x(), 0, 0); };
  EXPECT_THROW(make_structured_mesh(graded_rectangle(), collapse), MeshError);
  EXPECT_THROW(make_structured_mesh(graded_box(), collapse), MeshError);
}

TEST(StructuredMesh, BadSpecRaisesMeshError) {
  BoxSpec spec = graded_rectangle();
  spec.n[1] = 0;
  EXPECT_THROW(make_structured_mesh(spec), MeshError);
  spec = graded_box();
  spec.grading[2] = -1.0;
  EXPECT_THROW(make_structured_mesh(spec), MeshError);
}

}  // namespace rfmems

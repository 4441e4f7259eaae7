#include "ibm/immersed_surface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "core/error.hpp"

namespace rfmems {

namespace {

Real signed_area(const std::vector<Vec3>& v) {
  Real a = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3& p = v[i];
    const Vec3& q = v[(i + 1) % v.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

}  // namespace

ImmersedSurface::ImmersedSurface(std::vector<Vec3> vertices, std::vector<Index> source_face)
    : vertices_(std::move(vertices)), source_face_(std::move(source_face)) {
  if (vertices_.size() < 3)
    throw MeshError(
        fmt::format("immersed surface: {} vertices (a closed polygon needs 3)", vertices_.size()));
  if (!source_face_.empty() && source_face_.size() != vertices_.size())
    throw MeshError("immersed surface: source_face has not one entry per segment");
  for (Vec3& v : vertices_) v.z() = 0;
  const Real a = signed_area(vertices_);
  if (a == 0) throw MeshError("immersed surface: polygon of zero area");
  if (a < 0) {
    // Clockwise: reverse, keeping segment k's source face with its segment.
    // Segment k (v_k -> v_k+1) becomes segment n-2-k of the reversed list, the
    // last stays last.
    std::reverse(vertices_.begin(), vertices_.end());
    if (!source_face_.empty()) {
      std::vector<Index> s(source_face_.size());
      const std::size_t n = s.size();
      for (std::size_t k = 0; k < n; ++k) s[(2 * n - 2 - k) % n] = source_face_[k];
      source_face_ = std::move(s);
    }
  }
  for (Index k = 0; k < n_segments(); ++k)
    if (!(length(k) > 0))
      throw MeshError(fmt::format("immersed surface: segment {} has zero length", k));
}

ImmersedSurface ImmersedSurface::rectangle(const Vec3& lower, const Vec3& upper, int nx, int ny) {
  if (nx < 1 || ny < 1 || !(upper.x() > lower.x()) || !(upper.y() > lower.y()))
    throw MeshError("immersed surface: rectangle with no area or no segments");
  std::vector<Vec3> v;
  auto lerp = [](Real a, Real b, int i, int n) { return a + (b - a) * i / n; };
  for (int i = 0; i < nx; ++i) v.emplace_back(lerp(lower.x(), upper.x(), i, nx), lower.y(), 0);
  for (int j = 0; j < ny; ++j) v.emplace_back(upper.x(), lerp(lower.y(), upper.y(), j, ny), 0);
  for (int i = nx; i > 0; --i) v.emplace_back(lerp(lower.x(), upper.x(), i, nx), upper.y(), 0);
  for (int j = ny; j > 0; --j) v.emplace_back(lower.x(), lerp(lower.y(), upper.y(), j, ny), 0);
  return ImmersedSurface(std::move(v));
}

ImmersedSurface ImmersedSurface::circle(const Vec3& centre, Real radius, int n, Real phase) {
  if (n < 3 || !(radius > 0)) throw MeshError("immersed surface: circle with n < 3 or r <= 0");
  std::vector<Vec3> v;
  for (int i = 0; i < n; ++i) {
    const Real t = phase + 2 * std::numbers::pi * i / n;
    v.emplace_back(centre.x() + radius * std::cos(t), centre.y() + radius * std::sin(t), 0);
  }
  return ImmersedSurface(std::move(v));
}

ImmersedSurface ImmersedSurface::from_mesh_boundary(const Mesh& structure,
                                                    const std::vector<std::string>& patches) {
  if (structure.dim() != 2) throw MeshError("immersed surface: the structure mesh is not 2D");
  std::vector<int> wanted;
  for (const std::string& name : patches) {
    const int p = structure.find_patch(name);
    if (p < 0)
      throw MeshError(fmt::format("immersed surface: no patch '{}' on the structure", name));
    wanted.push_back(p);
  }
  // Boundary face f runs node a -> b counterclockwise around its owner (its
  // area vector, the tangent rotated clockwise, points out), so following a ->
  // b walks the body's outline counterclockwise.
  std::map<Index, Index> face_from_node;
  for (Index f = structure.n_interior_faces(); f < structure.n_faces(); ++f) {
    if (!wanted.empty() &&
        std::find(wanted.begin(), wanted.end(), structure.face_patch(f)) == wanted.end())
      continue;
    const Index a = structure.face_nodes(f)[0];
    if (!face_from_node.emplace(a, f).second)
      throw MeshError(fmt::format("immersed surface: two boundary faces start at node {}", a));
  }
  if (face_from_node.empty()) throw MeshError("immersed surface: no boundary faces selected");
  std::vector<Vec3> vertices;
  std::vector<Index> faces;
  const Index first = face_from_node.begin()->second;
  Index f = first;
  do {
    auto fn = structure.face_nodes(f);
    vertices.push_back(structure.nodes()[fn[0]]);
    faces.push_back(f);
    auto next = face_from_node.find(fn[1]);
    if (next == face_from_node.end())
      throw MeshError(fmt::format("immersed surface: the boundary is open at node {}", fn[1]));
    f = next->second;
  } while (f != first && faces.size() <= face_from_node.size());
  if (faces.size() != face_from_node.size())
    throw MeshError(
        fmt::format("immersed surface: the boundary faces form more than one loop "
                    "({} of {} faces in the first)",
                    faces.size(), face_from_node.size()));
  return ImmersedSurface(std::move(vertices), std::move(faces));
}

Vec3 ImmersedSurface::normal(Index k) const {
  const Vec3 t = end(k) - start(k);
  return Vec3(t.y(), -t.x(), 0).normalized();
}

Real ImmersedSurface::area() const { return signed_area(vertices_); }

Real ImmersedSurface::perimeter() const {
  Real p = 0;
  for (Index k = 0; k < n_segments(); ++k) p += length(k);
  return p;
}

Vec3 ImmersedSurface::lower() const {
  Vec3 l = vertices_.front();
  for (const Vec3& v : vertices_) l = l.cwiseMin(v);
  return l;
}

Vec3 ImmersedSurface::upper() const {
  Vec3 u = vertices_.front();
  for (const Vec3& v : vertices_) u = u.cwiseMax(v);
  return u;
}

bool ImmersedSurface::contains(const Vec3& x) const {
  bool inside = false;
  for (Index k = 0; k < n_segments(); ++k) {
    const Vec3& a = start(k);
    const Vec3& b = end(k);
    if ((a.y() > x.y()) != (b.y() > x.y())) {
      const Real xc = a.x() + (x.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (x.x() < xc) inside = !inside;
    }
  }
  return inside;
}

Real ImmersedSurface::distance(const Vec3& x, Vec3* nearest, Index* segment) const {
  Real best = std::numeric_limits<Real>::infinity();
  for (Index k = 0; k < n_segments(); ++k) {
    const Vec3& a = start(k);
    const Vec3 t = end(k) - a;
    const Real s = std::clamp((x - a).dot(t) / t.squaredNorm(), 0.0, 1.0);
    const Vec3 p = a + s * t;
    const Real d = (x - p).norm();
    if (d < best) {
      best = d;
      if (nearest) *nearest = p;
      if (segment) *segment = k;
    }
  }
  return best;
}

ImmersedSurface ImmersedSurface::translated(const Vec3& d) const {
  ImmersedSurface moved = *this;
  for (Vec3& v : moved.vertices_) v += Vec3(d.x(), d.y(), 0);
  return moved;
}

void ImmersedSurface::set_vertices(std::vector<Vec3> vertices) {
  if (vertices.size() != vertices_.size())
    throw MeshError("immersed surface: set_vertices changes the number of vertices");
  for (Vec3& v : vertices) v.z() = 0;
  if (!(signed_area(vertices) > 0))
    throw MeshError("immersed surface: the moved polygon is inverted or has no area");
  vertices_ = std::move(vertices);
}

}  // namespace rfmems

// The closed surface of an immersed body in 2D: a simple polygon whose segments
// are the structure's surface faces (thesis ch. 6, step 2: "a surface mesh
// is created from the solid"). Vertices run counterclockwise, so the outward
// normal of segment k (v_k -> v_k+1) is its tangent rotated clockwise, as for a
// Mesh boundary face.
//
// Each segment remembers the structure face it came from (`source_face`, -1 for
// a polygon made by hand), so loads transferred to the segments go back to the
// structure's faces and the structure's face velocities come to the segments in
// the same order.
//
// Used by the cell marking (which background cells it cuts), the interpolation
// (the segments' midpoints are the wall points of a stencil) and the force
// transfer.
#pragma once
#include <string>
#include <vector>

#include "core/types.hpp"
#include "mesh/mesh.hpp"

namespace rfmems {

class ImmersedSurface {
 public:
  // Counterclockwise or clockwise vertices of a simple polygon (reordered
  // counterclockwise), at least three, no repeated closing vertex. source_face:
  // per segment, or empty.
  explicit ImmersedSurface(std::vector<Vec3> vertices, std::vector<Index> source_face = {});

  // The rectangle [lower, upper], n[0] segments along x and n[1] along y on
  // each side.
  static ImmersedSurface rectangle(const Vec3& lower, const Vec3& upper, int nx = 1, int ny = 1);
  // A regular n-gon inscribed in the circle (centre, radius), first vertex at
  // angle `phase`.
  static ImmersedSurface circle(const Vec3& centre, Real radius, int n, Real phase = 0.0);
  // The boundary faces of a 2D structure mesh on the named patches (all patches
  // if empty), chained into one closed loop; source_face(k) is the mesh face of
  // segment k. Throws MeshError if the faces do not form exactly one closed
  // loop.
  static ImmersedSurface from_mesh_boundary(const Mesh& structure,
                                            const std::vector<std::string>& patches = {});

  Index n_segments() const { return static_cast<Index>(vertices_.size()); }
  const std::vector<Vec3>& vertices() const { return vertices_; }
  const Vec3& start(Index k) const { return vertices_[k]; }
  const Vec3& end(Index k) const { return vertices_[(k + 1) % vertices_.size()]; }
  Vec3 midpoint(Index k) const { return 0.5 * (start(k) + end(k)); }
  Real length(Index k) const { return (end(k) - start(k)).norm(); }
  // Unit outward normal of segment k.
  Vec3 normal(Index k) const;
  Index source_face(Index k) const { return source_face_.empty() ? -1 : source_face_[k]; }

  // Enclosed area (shoelace) and perimeter.
  Real area() const;
  Real perimeter() const;
  // Lower and upper corners of the bounding box.
  Vec3 lower() const;
  Vec3 upper() const;
  // Point strictly inside the polygon (crossing number; a point on the surface
  // is reported by distance(), not here).
  bool contains(const Vec3& x) const;
  // Distance from x to the surface, and the nearest point with the segment that
  // holds it.
  Real distance(const Vec3& x, Vec3* nearest = nullptr, Index* segment = nullptr) const;

  // The same surface moved: every vertex x -> x + d, or x -> x + d(x) for a
  // deformation.
  ImmersedSurface translated(const Vec3& d) const;
  void set_vertices(std::vector<Vec3> vertices);

 private:
  std::vector<Vec3> vertices_;
  std::vector<Index> source_face_;
};

}  // namespace rfmems

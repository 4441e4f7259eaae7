#include "ibm/force_transfer.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.hpp"

namespace rfmems {

ForceTransfer::ForceTransfer(const Mesh& mesh, const CellMarking& marking,
                             const ImmersedSurface& body)
    : n_segments_(body.n_segments()) {
  const Index n = body.n_segments();
  auto wrap = [n](Index i) { return ((i % n) + n) % n; };
  const Vec3 z(0, 0, 1);
  for (std::size_t k = 0; k < marking.ib_faces.size(); ++k) {
    const Index f = marking.ib_faces[k];
    const Vec3& x = mesh.face_centroid(f);
    Vec3 p;
    Index s = 0;
    body.distance(x, &p, &s);
    // The midpoints bracketing p: s and the neighbour on p's side of the midpoint of s.
    const Vec3 m = body.midpoint(s);
    const bool forward = (p - m).dot(body.end(s) - body.start(s)) >= 0;
    const Index t = wrap(forward ? s + 1 : s - 1);
    const Index third = wrap(forward ? s - 1 : s + 1);
    const Real span = 0.5 * (body.length(s) + body.length(t));
    const Real alpha = std::clamp((p - m).norm() / span, 0.0, 1.0);
    FaceMap map;
    map.segment = {s, t, third};
    map.weight = {1 - alpha, alpha, 0.0};
    Vec3 P = Vec3::Zero(), mean = Vec3::Zero();
    for (int j = 0; j < 3; ++j) {
      P += map.weight[j] * body.midpoint(map.segment[j]);
      mean += body.midpoint(map.segment[j]) / 3.0;
    }
    Real spread = 0;
    for (int j = 0; j < 3; ++j) spread += (body.midpoint(map.segment[j]) - mean).squaredNorm();
    if (!(spread > 0))
      throw MeshError(
          fmt::format("force transfer: segments {} {} {} share one midpoint", s, t, third));
    for (int j = 0; j < 3; ++j)
      map.couple[j] = z.cross(body.midpoint(map.segment[j]) - mean) / spread;
    map.z_cross_offset = z.cross(Vec3(x - P));
    maps_.push_back(map);
    centroids_.push_back(x);
    normals_.push_back(marking.ib_face_normal[k]);
    areas_.push_back(mesh.face_area(f).norm());
  }
}

std::vector<Vec3> ForceTransfer::to_surface(std::span<const Vec3> ib_face_forces) const {
  if (ib_face_forces.size() != maps_.size())
    throw std::invalid_argument("force transfer: not one force per IB face");
  std::vector<Vec3> out(n_segments_, Vec3::Zero());
  for (std::size_t k = 0; k < maps_.size(); ++k) {
    const FaceMap& m = maps_[k];
    const Vec3& F = ib_face_forces[k];
    const Real moment = F.dot(m.z_cross_offset);  // z . (a_k x F)
    for (int j = 0; j < 3; ++j) out[m.segment[j]] += m.weight[j] * F + m.couple[j] * moment;
  }
  return out;
}

std::vector<Vec3> ForceTransfer::to_ib_faces(std::span<const Vec3> segment_velocities) const {
  if (segment_velocities.size() != static_cast<std::size_t>(n_segments_))
    throw std::invalid_argument("force transfer: not one velocity per surface segment");
  std::vector<Vec3> out;
  out.reserve(maps_.size());
  for (const FaceMap& m : maps_) {
    Vec3 u = Vec3::Zero();
    Real spin = 0;
    for (int j = 0; j < 3; ++j) {
      u += m.weight[j] * segment_velocities[m.segment[j]];
      spin += m.couple[j].dot(segment_velocities[m.segment[j]]);
    }
    out.push_back(u + spin * m.z_cross_offset);
  }
  return out;
}

}  // namespace rfmems

// A structured rectangle of plate cells with every edge clamped: the plate creep tests' film
// and strip (test/unit/creep).
#pragma once
#include <vector>

#include "mesh/structured_mesh.hpp"
#include "physics/plate/plate_boundary.hpp"

namespace rfmems::test {

// length x width [m], nx x ny cells, corner at the origin.
inline Mesh rectangle(Real length, Real width, int nx, int ny) {
  BoxSpec spec;
  spec.upper = Vec3(length, width, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  return make_structured_mesh(spec);
}

inline std::vector<PlateBoundary> all_clamped(const Mesh& mesh) {
  std::vector<PlateBoundary> bcs(mesh.patches().size());
  for (auto& b : bcs) b.kind = PlateBoundary::Kind::Clamped;
  return bcs;
}

}  // namespace rfmems::test

// The quasi-1D kinetic test domain: a side x side square of nx x ny quads in the (x, y) plane
// (patches left, right, bottom, top; the tests make the sides specular and the flow depend on
// y only). One column leaves the second-order reconstruction without a stencil (first order);
// two give it one.
#pragma once
#include "fv/face_graph.hpp"
#include "mesh/structured_mesh.hpp"

namespace rfmems::test_support {

inline FaceGraph kinetic_slab(Real side, int nx, int ny) {
  BoxSpec spec;
  spec.upper = Vec3(side, side, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  return face_graph_of(make_structured_mesh(spec));
}

}  // namespace rfmems::test_support

// A plate on an irregular, non-orthogonal, graded quadrilateral mesh with every kind of edge
// (clamped, hard simply supported, free, loaded): the hard case of the plate creep system's
// Jacobian and Schur-complement tests (test/unit/creep).
#pragma once
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "mesh/structured_mesh.hpp"
#include "physics/plate/plate_scene.hpp"

namespace rfmems::test {

// nx x ny cells on [0, 2] x [0, 1.2], graded 1.6 in x, sheared by smooth sines and jittered by
// +-0.03 at random (seed).
inline Mesh distorted_mesh(int nx, int ny, unsigned seed) {
  auto rng = std::make_shared<std::mt19937>(seed);
  BoxSpec spec;
  spec.upper = Vec3(2.0, 1.2, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  spec.grading[0] = 1.6;
  return make_structured_mesh(spec, [rng](const Vec3& x) {
    std::uniform_real_distribution<double> jitter(-0.03, 0.03);
    Vec3 y = x;
    y.x() += 0.12 * std::sin(2.0 * x.y()) + jitter(*rng);
    y.y() += 0.08 * std::sin(3.0 * x.x()) + jitter(*rng);
    return y;
  });
}

// Left clamped, right hard simply supported, bottom free, top loaded (a force and moments
// varying along x).
inline std::vector<PlateBoundary> mixed_boundaries(const Mesh& mesh) {
  using Kind = PlateBoundary::Kind;
  std::vector<PlateBoundary> bcs(mesh.patches().size());
  for (std::size_t p = 0; p < bcs.size(); ++p) {
    const std::string& name = mesh.patches()[p].name;
    bcs[p].kind = name == "left"     ? Kind::Clamped
                  : name == "right"  ? Kind::SimplySupportedHard
                  : name == "bottom" ? Kind::Free
                                     : Kind::Load;
    if (bcs[p].kind == Kind::Load)
      bcs[p].value = [](const Vec3& x, Real) { return Vec3(-50.0 * x.x(), 3.0, -2.0); };
  }
  return bcs;
}

}  // namespace rfmems::test

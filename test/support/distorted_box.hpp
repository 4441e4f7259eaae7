// The node map of the elasticity Jacobian tests: a smooth non-affine shear plus random jitter,
// so faces are non-orthogonal and cells irregular (in 2D and 3D).
#pragma once
#include <cmath>
#include <memory>
#include <random>

#include "mesh/structured_mesh.hpp"

namespace rfmems::test {

// Moves every node by 0.15 sin(2y), 0.1 sin(3x) (and 0.1 sin(2x) in z off the z = 0 plane),
// plus jitter uniform in +-amplitude drawn from a generator seeded with `seed`.
inline NodeMap distortion(double amplitude, unsigned seed) {
  auto rng = std::make_shared<std::mt19937>(seed);
  return [=](const Vec3& x) {
    std::uniform_real_distribution<double> jitter(-amplitude, amplitude);
    Vec3 y = x;
    y.x() += 0.15 * std::sin(2.0 * x.y()) + jitter(*rng);
    y.y() += 0.1 * std::sin(3.0 * x.x()) + jitter(*rng);
    if (x.z() != 0) y.z() += 0.1 * std::sin(2.0 * x.x()) + jitter(*rng);
    return y;
  };
}

}  // namespace rfmems::test

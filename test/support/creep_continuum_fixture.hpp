// The continuum creep Jacobian tests' body (test/unit/creep): a graded box, sheared by smooth
// sines and jittered, with every kind of boundary (a prescribed non-zero displacement, a
// symmetry plane, a loaded side, free sides), in 2D or 3D; and a random state of its creep
// system.
#pragma once
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "mesh/structured_mesh.hpp"
#include "physics/creep/continuum_creep_system.hpp"
#include "physics/elasticity/elasticity_boundary.hpp"

namespace rfmems::test {

// nx x ny (x nz) cells on [0, 2] x [0, 1.2] (x [0, 0.8]), graded 1.6 in x, sheared and
// jittered by +-0.03 at random (seed).
inline Mesh creep_test_mesh(int dim, int nx, int ny, int nz, unsigned seed) {
  auto rng = std::make_shared<std::mt19937>(seed);
  BoxSpec spec;
  spec.dim = dim;
  spec.upper = Vec3(2.0, 1.2, dim == 3 ? 0.8 : 0.0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  spec.n[2] = nz;
  spec.grading[0] = 1.6;
  return make_structured_mesh(spec, [rng, dim](const Vec3& x) {
    std::uniform_real_distribution<double> jitter(-0.03, 0.03);
    Vec3 y = x;
    y.x() += 0.12 * std::sin(2.0 * x.y()) + jitter(*rng);
    y.y() += 0.08 * std::sin(3.0 * x.x()) + jitter(*rng);
    if (dim == 3) y.z() += 0.05 * std::sin(2.0 * x.x()) + 0.5 * jitter(*rng);
    return y;
  });
}

// left fixed (a non-zero displacement), right symmetry, bottom loaded, the rest free.
inline std::vector<ElasticityBoundary> creep_test_boundaries(const Mesh& mesh) {
  using Kind = ElasticityBoundary::Kind;
  std::vector<ElasticityBoundary> bcs(mesh.patches().size());
  for (std::size_t p = 0; p < bcs.size(); ++p) {
    const std::string& name = mesh.patches()[p].name;
    if (name == "left") {
      bcs[p].kind = Kind::Fixed;
      bcs[p].value = [](const Vec3& x, Real) { return Vec3(1e-4 * x.y(), -2e-4, 0); };
    } else if (name == "right") {
      bcs[p].kind = Kind::Symmetry;
    } else if (name == "bottom") {
      bcs[p].value = [](const Vec3& x, Real) { return Vec3(3e7 * x.x(), -5e7, 1e7); };
    }
  }
  return bcs;
}

struct ContinuumCreepState {
  std::vector<Real> y, yp, steps, scales;
};

// Displacements ~1e-3 m over ~1 m (strain ~1e-3, stress ~1e8 Pa), plastic strains ~1e-4 and
// eps_eff >= 0, with the finite-difference steps (1e-5 of each scale) and the column scales of
// test_support::check_jacobian.
inline ContinuumCreepState random_continuum_creep_state(const ContinuumCreepSystem& system,
                                                        unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  const Index n = system.size(), ns = system.structural_size();
  const int nq = system.n_components();
  ContinuumCreepState r{std::vector<Real>(n), std::vector<Real>(n), std::vector<Real>(n),
                        std::vector<Real>(n)};
  for (Index k = 0; k < n; ++k) {
    const Real scale = k < ns ? 1e-3 : 1e-4;
    r.y[k] = scale * u(rng);
    r.yp[k] = scale * u(rng);
    if (k >= ns && (k - ns) % nq == system.effective_component()) r.y[k] = std::abs(r.y[k]);
    r.steps[k] = 1e-5 * scale;
    r.scales[k] = scale;
  }
  return r;
}

}  // namespace rfmems::test

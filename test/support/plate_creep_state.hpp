// A random state of a plate creep system for its Jacobian checks (test/unit/creep): w ~ 1e-4 m,
// beta ~ 2e-3 (curvature ~ 1e-3 /m on the test plates, stresses ~ 1e8 Pa), plastic strains
// ~ 1e-4 and eps_eff >= 0, with the finite-difference steps (1e-5 of each scale) and the column
// scales of test_support::check_jacobian.
#pragma once
#include <cmath>
#include <random>
#include <vector>

#include "physics/creep/plate_creep_system.hpp"

namespace rfmems::test {

struct PlateCreepState {
  std::vector<Real> y, yp, steps, scales;
};

inline PlateCreepState random_plate_creep_state(const PlateCreepSystem& system, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  const Index n = system.size(), ns = system.structural_size();
  PlateCreepState r{std::vector<Real>(n), std::vector<Real>(n), std::vector<Real>(n),
                    std::vector<Real>(n)};
  for (Index k = 0; k < n; ++k) {
    const Real scale = k < ns ? (k % 3 == 0 ? 1e-4 : 2e-3) : 1e-4;
    r.y[k] = scale * u(rng);
    r.yp[k] = scale * u(rng);
    if (k >= ns && (k - ns) % system.per_point() == PlateCreepSystem::kEff)
      r.y[k] = std::abs(r.y[k]);
    r.steps[k] = 1e-5 * scale;
    r.scales[k] = scale;
  }
  return r;
}

}  // namespace rfmems::test

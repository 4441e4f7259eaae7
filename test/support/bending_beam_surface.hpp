// A cantilever-like beam's surface for the immersed electrostatics tests: the rest rectangle
// bent down as w(x) = d (x / L)^2 (x >= 0; the part inside the wall stays), and the coupled
// run's motion: d grows by 2 nm per step and 20 nm every fourth, so that most steps keep the
// marking and some re-mark.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "ibm/immersed_surface.hpp"

namespace rfmems::test {

inline ImmersedSurface bent_down(const ImmersedSurface& rest, Real d, Real L) {
  std::vector<Vec3> x = rest.vertices();
  for (Vec3& p : x) p.y() -= d * std::pow(std::max(p.x(), 0.0) / L, 2);
  ImmersedSurface beam = rest;
  beam.set_vertices(std::move(x));
  return beam;
}

// The tip deflection after `step` + 1 steps of the motion.
inline Real bending_deflection(int step) {
  Real d = 0;
  for (int s = 0; s <= step; ++s) d += (s % 4 == 3 ? 20e-9 : 2e-9);
  return d;
}

}  // namespace rfmems::test

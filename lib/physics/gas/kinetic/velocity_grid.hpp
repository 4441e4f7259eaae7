// Discrete velocity space of the kinetic (BGK / ESBGK) gas model: a uniform Cartesian grid of
// N1 x N2 x N3 ordinates c_k over [-E1, E1] x [-E2, E2] x [-E3, E3] (thesis ch. 5).
//
// Ordinates sit at the cell midpoints of the velocity grid, c = -E + (i + 1/2) dc with
// dc = 2E/N, and every weight is dc1 dc2 dc3 (m^3/s^3): the midpoint rule, which is spectrally
// accurate for the Gaussian-like distributions of a gas and never places an ordinate at c = 0
// when N is even (so c . S != 0 on axis-aligned faces). Integrals over velocity space are
// sum_k w_k g(c_k). Units are SI (m/s); the distribution f is a mass density in phase space
// (kg s^3 / m^6) so that rho = sum_k w_k f_k.
//
// Ordinate numbering: k = (i N2 + j) N3 + l for the (i, j, l)-th point along (x, y, z).
//
// Specular reflection about a wall with unit normal n maps c to c - 2 (c . n) n. On this grid
// the image of an ordinate is again an ordinate when n is along an axis (the grid is symmetric
// about 0), so the reflection map is exact and a specular wall conserves mass to round-off;
// for any other n the image is rounded to the nearest ordinate (clamped to the grid), which
// conserves mass only approximately (documented in docs/kinetic.md).
#pragma once
#include <array>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

struct VelocityGrid {
  std::array<int, 3> n{0, 0, 0};  // points per direction
  Vec3 extent = Vec3::Zero();     // half-width per direction, m/s
  Vec3 spacing = Vec3::Zero();    // dc per direction, m/s
  std::vector<Vec3> c;            // ordinates, m/s
  std::vector<Real> w;            // quadrature weights, m^3/s^3
  // Velocity scale of the equilibrium's polynomial basis, xi = c / reference_speed (the
  // largest half-width), so that the Newton unknowns of equilibrium.hpp are O(1)-conditioned.
  Real reference_speed = 1.0;

  Index size() const { return static_cast<Index>(c.size()); }
  Index index(int i, int j, int l) const { return (Index(i) * n[1] + j) * n[2] + l; }

  // Uniform grid; InputError unless every n >= 2 and extent > 0.
  static VelocityGrid uniform(int n1, int n2, int n3, Real extent);
  static VelocityGrid uniform(int n1, int n2, int n3, const Vec3& extent);

  // The ordinate nearest to v (components clamped to the grid).
  Index nearest_ordinate(const Vec3& v) const;
  // Ordinate index of the specular image of c_k about the unit normal n (exact for
  // axis-aligned n, nearest otherwise).
  Index specular_image(Index k, const Vec3& unit_normal) const;
  // specular_image for every ordinate.
  std::vector<Index> reflection_map(const Vec3& unit_normal) const;
  // True if unit_normal is along a coordinate axis (to 1e-12), i.e. the reflection is exact.
  static bool reflection_is_exact(const Vec3& unit_normal);
};

}  // namespace rfmems

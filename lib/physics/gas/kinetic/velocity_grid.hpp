// Discrete velocity space of the kinetic (BGK / ESBGK) gas model: the tensor product of one
// quadrature rule per direction (velocity_quadrature.hpp), N1 x N2 x N3 ordinates c_k with
// weights w_k (thesis ch. 5 uses the uniform rule in every direction).
//
// Direction d has nodes c_d,i = s x_d,i and weights s w_d,i (m/s) of its rule, s the velocity
// scale (the thermal speed sqrt(2 R T0) of the initial state for a case; 1 for uniform(), whose
// extents are in m/s); the ordinate (i, j, l) is (c_1,i, c_2,j, c_3,l) with weight
//     w_k = (w_1,i w_2,j) w_3,l   (m^3/s^3),
// so integrals over velocity space are sum_k w_k g(c_k). The distribution f is a mass density
// in phase space (kg s^3 / m^6) so that rho = sum_k w_k f_k. The uniform rule gives the
// midpoint grid over [-E1, E1] x [-E2, E2] x [-E3, E3] with every weight dc1 dc2 dc3: never an
// ordinate at c = 0 when N is even (so c . S != 0 on axis-aligned faces).
//
// Ordinate numbering: k = (i N2 + j) N3 + l for the (i, j, l)-th point along (x, y, z).
//
// Specular reflection about a wall with unit normal n maps c to c - 2 (c . n) n. Every rule is
// mirror-symmetric about 0, so for n along an axis the image of an ordinate is again an
// ordinate, the reflection map is exact and a specular wall conserves mass to round-off; for
// any other n the image is rounded to the nearest ordinate (per direction, clamped to the
// grid), which conserves mass only approximately (documented in docs/kinetic.md).
#pragma once
#include <array>
#include <vector>

#include "core/types.hpp"
#include "physics/gas/kinetic/velocity_quadrature.hpp"

namespace rfmems {

struct VelocityGrid {
  std::array<int, 3> n{0, 0, 0};  // points per direction
  std::array<VelocityRule, 3> rule{VelocityRule::Uniform, VelocityRule::Uniform,
                                   VelocityRule::Uniform};
  // Half-width per direction, m/s: E s of a truncated rule (uniform, sinh_stretched),
  // +infinity for the Gauss-Hermite rules (the whole line).
  Vec3 extent = Vec3::Zero();
  std::array<std::vector<Real>, 3> axis;         // nodes per direction (ascending), m/s
  std::array<std::vector<Real>, 3> axis_weight;  // their weights, m/s
  std::vector<Vec3> c;                           // ordinates, m/s
  std::vector<Real> w;                           // quadrature weights, m^3/s^3
  // Velocity scale of the equilibrium's polynomial basis, xi = c / reference_speed (the
  // largest half-width of a truncated rule, else the largest node), so that the Newton
  // unknowns of equilibrium.hpp are O(1)-conditioned.
  Real reference_speed = 1.0;

  Index size() const { return static_cast<Index>(c.size()); }
  Index index(int i, int j, int l) const { return (Index(i) * n[1] + j) * n[2] + l; }

  // The product of the rules `rule` with n points each, extents (of the truncated rules) in
  // units of `scale`, sinh stretch a, velocities c = scale x. InputError as velocity_axis.
  static VelocityGrid product(const std::array<VelocityRule, 3>& rule, const std::array<int, 3>& n,
                              const Vec3& extent, Real stretch, Real scale);
  // Uniform grid, extents in m/s; InputError unless every n >= 2 and extent > 0.
  static VelocityGrid uniform(int n1, int n2, int n3, Real extent);
  static VelocityGrid uniform(int n1, int n2, int n3, const Vec3& extent);

  // The ordinate nearest to v (per direction, clamped to the grid).
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

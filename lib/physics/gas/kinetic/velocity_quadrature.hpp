// One-dimensional quadrature rules for one direction of the discrete velocity grid
// (velocity_grid.hpp builds the 3D grid as their tensor product).
//
// A rule approximates int g(x) dx over the real line by sum_i w_i g(x_i), with x = c / v0 the
// velocity in units of the thermal speed v0 = sqrt(2 R T0) of the initial state, for g the
// distribution of a gas near T0, i.e. g(x) = p(x) exp(-x^2) with p smooth (or smooth on each
// side of x = 0: a diffuse wall sends different half-Maxwellians in and out, so the
// distribution next to a wall jumps at zero wall-normal velocity).
//
//   uniform             midpoints of N equal cells over [-E, E]: w = 2E/N. Spectral for smooth g
//                       that vanish at +-E; second order in the spacing across the jump at 0
//                       (N even puts the jump on a cell edge).
//   gauss_hermite       Gauss quadrature for the weight exp(-x^2) on the whole line (nodes: the
//                       roots of the Hermite polynomial H_N), w_i = lambda_i exp(x_i^2) with
//                       lambda_i the Gauss weights: exact for g = p exp(-x^2), p of degree
//                       <= 2N - 1. No extent. N = 2 puts both nodes at +-v0/sqrt(2), which
//                       hold a variance of at most v0^2/2 = R T0: no discrete equilibrium of a
//                       warmer gas; N points reach a variance x_max^2 v0^2 (N = 3: 3 T0).
//   half_range_hermite  Gauss quadrature for exp(-x^2) on [0, inf) with N/2 nodes, mirrored onto
//                       (-inf, 0] (N even): exact for g = p exp(-x^2) with p of degree
//                       <= N - 1 on each half separately, so the jump at 0 costs nothing; the
//                       half-range moments of a wall's Maxwellian are exact. Nodes cluster
//                       towards 0. No extent.
//   sinh_stretched      midpoints of N equal cells in s over [-1, 1] mapped by
//                       x = E sinh(a s) / sinh(a) (a = stretch), w = E a cosh(a s) / sinh(a) ds:
//                       the uniform rule with its points concentrated near 0 by a factor
//                       sinh(a) / a, still second order across the jump.
//
// Gauss rules by Golub-Welsch: the nodes are the eigenvalues of the symmetric Jacobi matrix of
// the weight's three-term recurrence (Eigen's SelfAdjointEigenSolver); the weights by the
// Christoffel formula lambda_i = 1 / sum_k p_k(x_i)^2 (p_k orthonormal), evaluated as
// lambda_i exp(x_i^2) = 1 / sum_k (p_k(x_i) exp(-x_i^2 / 2))^2 so that the outer weights keep
// their relative accuracy. Hermite: alpha_k = 0, beta_k = k / 2. Half-range: the recurrence of
// exp(-x^2) on [0, inf) is not known in closed form; it comes from the discretised Stieltjes
// procedure on a composite Gauss-Legendre rule over [0, L] (40 panels of 20 points, L beyond
// which exp(-x^2) x^(2M) is below round-off), accurate to round-off for the sizes allowed.
//
// Every rule is symmetric about 0 (x_{N-1-i} = -x_i, equal weights), so a specular reflection
// about an axis maps ordinates onto ordinates.
#pragma once
#include <string>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

enum class VelocityRule { Uniform, GaussHermite, HalfRangeHermite, SinhStretched };

// "uniform", "gauss_hermite", "half_range_hermite", "sinh_stretched".
const std::vector<std::string>& velocity_rule_names();
VelocityRule velocity_rule_from_name(const std::string& name);
const char* velocity_rule_name(VelocityRule rule);
// True if the rule covers only [-E, E] (uniform, sinh_stretched).
bool velocity_rule_is_truncated(VelocityRule rule);

// Nodes (ascending) and weights of a rule for int g(x) dx, x dimensionless.
struct VelocityAxis {
  std::vector<Real> x;
  std::vector<Real> w;
};

// The rule with n points; extent E and stretch a are used by the truncated rules only.
// InputError for n < 2, an odd n with half_range_hermite, n > 200, or E, a <= 0.
VelocityAxis velocity_axis(VelocityRule rule, int n, Real extent, Real stretch);

VelocityAxis uniform_axis(int n, Real extent);
VelocityAxis gauss_hermite_axis(int n);
VelocityAxis half_range_hermite_axis(int n);
VelocityAxis sinh_stretched_axis(int n, Real extent, Real stretch);

}  // namespace rfmems

// The exponential-polynomial equilibrium family and its moments on a tensor-product velocity
// grid, in O(N) work with few exponentials: what the discrete equilibrium's Newton
// (equilibrium.hpp) and COMET's d f_eq / dU (comet/equilibrium_moment_derivative.hpp) spend
// their time on.
//
// On a product grid (velocity_grid.hpp) the scaled ordinates are xi_k = (x_i, y_j, z_l),
// k = (i N2 + j) N3 + l, with weights w_k = wx_i wy_j wz_l. The exponent of f_k = exp(a .
// phi(xi_k)) (ESBGK basis phi = (1, x, y, z, x^2, y^2, z^2, xy, xz, yz); BGK's |xi|^2 is x^2 + y^2
// + z^2) splits as
//     A(i, j) + B(i, l) + C(j, l),
//     A = a0 + a1 x + a2 y + a4 x^2 + a5 y^2 + a7 xy,  B = a3 z + a6 z^2 + a8 xz,  C = a9 yz,
// so f_k = e^A(i,j) e^B(i,l) e^C(j,l): N1 N2 + N1 N3 + N2 N3 exponentials (300 for 10^3)
// instead of N, and two multiplications per ordinate.
//
// Moments sum_k w_k g_k x^p y^q z^r (p + q + r <= D) are nested sums: over l first (D + 1
// multiply-adds per ordinate against the weighted powers wz_l z_l^r), then over j and i on the
// partial sums with wy_j y_j^q and wx_i x_i^p.
// The Newton residual G = sum w phi f needs D = 2 (3 per ordinate instead of the 10 of a
// matrix-vector product), its Jacobian J = sum w phi phi^T f needs D = 4 (5 per ordinate
// instead of ~100), and a combination f_k phi_k^T Y (the derivative's N x K block) is a
// polynomial in z per (i, j): 2 multiply-adds per ordinate and column.
//
// valid() is false for a grid that is not such a product (ordinates set by hand); callers
// then use the dense basis-matrix products.
#pragma once
#include <array>
#include <vector>

#include "core/types.hpp"
#include "physics/gas/kinetic/velocity_grid.hpp"

namespace rfmems {

class EquilibriumTensorKernel {
 public:
  // Up to degree 4: mu[(p * 5 + q) * 5 + r] = sum_k w_k g_k x^p y^q z^r.
  using MonomialMoments = std::array<Real, 125>;

  EquilibriumTensorKernel() = default;
  explicit EquilibriumTensorKernel(const VelocityGrid& grid);

  bool valid() const { return valid_; }
  Index size() const { return n_; }
  // sum_k w_k g_k.
  Real weighted_sum(const Real* g) const;

  // f_k = exp(a . phi(xi_k)), a of size 5 (BGK) or 10 (ESBGK), scaled basis.
  void exponential(const Real* a, int n_coefficients, Real* f) const;

  // sum_k w_k g_k x^p y^q z^r for p + q + r <= D (D = 2 or 4; other entries
  // untouched).
  template <int D>
  void monomial_moments(const Real* g, MonomialMoments& mu) const;

  // The moments of macroscopic_state.hpp's moments() (scaled velocities): rho = sum w g,
  // u = sum w g xi / rho, and the central ones about u, P = sum w g C C^T and
  // q = sum w g |C|^2 C / 2 with C = xi - u (the nested sums on shifted axes: no cancellation).
  void central_moments(const Real* g, Real& rho, Vec3& u, Mat3& P, Vec3& q) const;

  // G = sum_k w_k g_k phi_k and, if J is given, J = sum_k w_k g_k phi_k phi_k^T (M
  // = 5 or 10).
  template <int M>
  void basis_moments(const Real* g, Eigen::Matrix<Real, M, 1>& G,
                     Eigen::Matrix<Real, M, M>* J) const;

  // H = sum_k w_k g_k phi5_k phi_k^T with phi5 the 5-function basis (1, xi, |xi|^2), phi the
  // M-function one (M = 5 or 10).
  template <int M>
  void conserved_product_moments(const Real* g, Eigen::Matrix<Real, 5, M>& H) const;

  // out[K k + j] = g_k phi_k^T Y(:, j) (row-major N x K), M = 5 or 10.
  template <int M, int K>
  void basis_combination(const Real* g, const Eigen::Matrix<Real, M, K>& Y, Real* out) const;

 private:
  bool valid_ = false;
  Index n_ = 0;
  int n1_ = 0, n2_ = 0, n3_ = 0;
  std::vector<Real> wx_, wy_, wz_;                         // the axes' weights
  std::vector<Real> x_, y_, z_;                            // scaled axes
  std::array<std::vector<Real>, 5> xp_, yp_, zp_;          // their weighted powers 0..4
  mutable std::vector<Real> ea_, eb_, ec_;                 // exponential tables (scratch)
  mutable std::array<std::vector<Real>, 5> xs_, ys_, zs_;  // shifted axes' powers (scratch)

  template <int D>
  void nested_moments(const Real* g, const std::array<std::vector<Real>, 5>& xp,
                      const std::array<std::vector<Real>, 5>& yp,
                      const std::array<std::vector<Real>, 5>& zp, MonomialMoments& mu) const;
};

}  // namespace rfmems

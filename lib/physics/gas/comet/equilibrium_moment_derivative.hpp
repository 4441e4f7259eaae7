// Derivative of the discrete-conservative equilibrium (kinetic/equilibrium.hpp) with respect to
// the cell's conserved moments, the B block of COMET's arrowhead when the point solve couples
// the ordinates to all five conserved moments instead of to u, v, w only.
//
// Conserved moments in the scaled velocity xi = c / s (s = grid.reference_speed):
//     U = sum_k w_k psi_k f_k,   psi = (1, xi_x, xi_y, xi_z, |xi|^2),
// i.e. mass, momentum and twice the energy (over s, s^2). The equilibrium is
// f_eq,k = exp(a . phi_k) with the moments G(a) = sum_k w_k phi_k f_eq,k equal to targets m(U):
//     BGK   phi = psi,                          m = U
//     ESBGK phi = (1, xi, xi xi (6 entries)),   m = (rho, rho u, Q) with the second moment
//           Q = m m^T / rho + p I + A,  p = (U_4 - |m|^2 / rho) / 3,  A traceless
//           (A = (1 - 1/Pr) times the traceless pressure tensor: Holway's Lambda, tr = 3 R T).
// Differentiating G(a(U)) = m(U):  da/dU = J^-1 dm/dU,  J = sum_k w_k phi_k phi_k^T f_eq,k, and
//     d f_eq,k / dU = f_eq,k phi_k^T J^-1 dm/dU.
// For ESBGK the anisotropic part A is held fixed (lagged): it relaxes, it is not conserved,
// so the point solve stays exact for the five conservation laws and approximate only in the
// stress relaxation, which the next visit corrects. The exponential family is the same in any
// basis of span{phi}, so this needs only f_eq and the grid (not the coefficients' scaling),
// and U(f_eq) = U(f) by discrete conservation, so dm/dU is evaluated from f_eq too.
#pragma once
#include <span>

#include "physics/gas/kinetic/equilibrium_tensor_kernel.hpp"
#include "physics/gas/kinetic/kinetic_gas.hpp"
#include "physics/gas/kinetic/velocity_grid.hpp"

namespace rfmems {

// psi_k = (1, xi, |xi|^2) of ordinate k.
inline Eigen::Matrix<Real, 5, 1> conserved_basis(const VelocityGrid& grid, Index k) {
  const Vec3 xi = grid.c[k] / grid.reference_speed;
  Eigen::Matrix<Real, 5, 1> psi;
  psi << 1.0, xi[0], xi[1], xi[2], xi.squaredNorm();
  return psi;
}

// U = sum_k w_k psi_k f_k.
Eigen::Matrix<Real, 5, 1> conserved_moments(const VelocityGrid& grid, std::span<const Real> f);

// The derivative for one grid and model (COMET evaluates it once per cell visit). On a
// tensor-product grid J and the moments come from nested sums and the N x 5 block from
// polynomials in z per (x, y) (equilibrium_tensor_kernel.hpp): ~20 operations per ordinate;
// otherwise two dense products with the basis matrix (~160).
class EquilibriumMomentDerivative {
 public:
  EquilibriumMomentDerivative(CollisionModel model, const VelocityGrid& grid);
  // df_dU[5 k + j] = scale * d f_eq,k / dU_j (scale: COMET's -V nu, folded in for free).
  void evaluate(std::span<const Real> f_eq, std::span<Real> df_dU, Real scale = 1.0);

  // The compact form: d f_eq,k / dU = f_eq,k phi_k^T Y with Y = J^-1 dm/dU (P x 5, P = 5 BGK
  // or 10 ESBGK), from the moments G = sum w phi f_eq and the Gram matrix
  // J = sum w phi phi^T f_eq of f_eq (the equilibrium's tensor Newton stores both with the
  // coefficients). RecoverableError if J is not positive definite.
  template <int P>
  static Eigen::Matrix<Real, P, 5> basis_coefficients(const Eigen::Matrix<Real, P, 1>& G,
                                                      const Eigen::Matrix<Real, P, P>& J);
  // The grid's tensor-product kernel (valid() false if the grid is not one).
  const EquilibriumTensorKernel& kernel() const { return kernel_; }

 private:
  template <int P>
  void evaluate_tensor(std::span<const Real> f_eq, std::span<Real> df_dU, Real scale);

  CollisionModel model_;
  EquilibriumTensorKernel kernel_;
  Eigen::MatrixXd phi_;       // N x P basis of the equilibrium's exponent (P = 5 or 10)
  Eigen::VectorXd w_;         // weights
  Eigen::MatrixXd weighted_;  // scratch N x P
};

// df_dU[5 k + j] = d f_eq,k / dU_j for the model's discrete equilibrium with values f_eq
// (convenience: builds an EquilibriumMomentDerivative).
void equilibrium_conserved_derivative(CollisionModel model, const VelocityGrid& grid,
                                      std::span<const Real> f_eq, std::span<Real> df_dU);

}  // namespace rfmems

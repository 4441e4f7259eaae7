// The discrete-conservative equilibrium of the BGK and ESBGK collision operators
// (Mieussens 2000, J. Comput. Phys. 162; Mathiaud & Mieussens 2016 for the ES model; thesis
// eqs. 5.10-5.28).
//
// The collision term nu (f_eq - f) conserves mass, momentum and energy only if the DISCRETE
// moments of f_eq equal those of f. A Maxwellian sampled on the grid does not (its discrete
// moments differ by the quadrature error), so f_eq is sought in exponential-polynomial form
//     f_eq,k = exp(a . phi(xi_k)),    xi = c / reference_speed,
//     BGK:   phi = (1, xi_x, xi_y, xi_z, |xi|^2)                                  5 coefficients
//     ESBGK: phi = (1, xi_x, xi_y, xi_z, xi_x^2, xi_y^2, xi_z^2, xi_x xi_y, xi_x xi_z, xi_y xi_z)
//                                                                                10 coefficients
// with a the root of G(a) = sum_k w_k phi_k exp(a . phi_k) - m = 0, m the target moments:
//     BGK:   m = (rho, rho u, rho (|u|^2 + 3 R T)) / scaled      (= the discrete moments of f)
//     ESBGK: m = (rho, rho u, rho (u u^T + Lambda)_{xx,yy,zz,xy,xz,yz})
//            Lambda = (1/Pr) R T I + (1 - 1/Pr) Theta (Holway), tr Lambda = 3 R T so energy is
//            conserved as well,
// velocities scaled by reference_speed. Newton's method with the Jacobian
// dG/da = sum_k w_k phi_k phi_k^T f_eq,k (symmetric positive definite) converges
// quadratically from the continuous Maxwellian / Gaussian coefficients, or from the previous
// coefficients of the cell (a warm start), until |G| reaches round-off.
//
// COMET's arrowhead needs d f_eq / d u at fixed rho and temperature (covariance): the
// derivative of the DISCRETE equilibrium, da/du = (dG/da)^-1 dm/du, df_k/du = f_k phi_k . da/du.
#pragma once
#include <array>
#include <span>

#include "core/types.hpp"
#include "physics/gas/kinetic/kinetic_gas.hpp"
#include "physics/gas/kinetic/macroscopic_state.hpp"
#include "physics/gas/kinetic/velocity_grid.hpp"

namespace rfmems {

// What the equilibrium reproduces: density, velocity and velocity covariance (m^2/s^2).
// BGK: covariance R T I (only its trace is used); ESBGK: Holway's Lambda.
struct EquilibriumTarget {
  Real rho = 0;
  Vec3 u = Vec3::Zero();
  Mat3 covariance = Mat3::Zero();
};

// The target of the gas's collision model for a cell in state m.
EquilibriumTarget equilibrium_target(const MacroState& m, const KineticGas& gas);
// A Maxwellian target (rho, u, R T I).
EquilibriumTarget maxwellian_target(Real rho, const Vec3& u, Real T, const KineticGas& gas);

inline int n_equilibrium_coefficients(CollisionModel model) {
  return model == CollisionModel::Bgk ? 5 : 10;
}

struct EquilibriumCoefficients {
  std::array<Real, 10> a{};  // BGK uses a[0..4]
  int size = 0;              // 5 (BGK), 10 (ESBGK), 0 = not yet computed
  bool valid() const { return size > 0; }
  // The last Newton Jacobian dG/da (size x size, column-major): on a tensor-product grid J at
  // a (see moments below); otherwise reused as the iteration matrix of the next warm-started
  // solve while it contracts (chord steps; refreshed when not).
  std::array<Real, 100> jacobian{};
  bool has_jacobian = false;
  // Tensor-product grids: the moments sum w phi f_eq of these coefficients, with `jacobian`
  // evaluated at them too, so that the next warm start takes its first Newton step without
  // an evaluation. Valid while moments_at == a.
  std::array<Real, 10> moments{};
  std::array<Real, 10> moments_at{};
  bool has_moments = false;
};

// The coefficients of the continuous Maxwellian (BGK) / Gaussian (ESBGK) with the target's
// rho, u, covariance: Newton's starting point.
EquilibriumCoefficients continuous_coefficients(const EquilibriumTarget& target,
                                                CollisionModel model, const VelocityGrid& grid);

struct EquilibriumSolveInfo {
  int iterations = 0;
  Real residual = 0;            // max |G| / rho at exit
  bool values_written = false;  // the f_eq overload: f_eq was (re)written
};

// Newton for the discrete-conservative coefficients. Warm-starts from `coefficients` if it is
// valid and of the model's size, else from continuous_coefficients (and falls back to that
// start if the warm start fails). SolverError if Newton does not converge.
EquilibriumSolveInfo solve_equilibrium(const EquilibriumTarget& target, CollisionModel model,
                                       const VelocityGrid& grid,
                                       EquilibriumCoefficients& coefficients);
// The same, and f_eq,k = exp(a . phi(xi_k)) of the result without a separate evaluation.
// f_eq must hold the values of `coefficients` on entry if those are valid (as a cache of the
// last solve's output does): when the coefficients do not change it is left as it is
// (info.values_written says which).
EquilibriumSolveInfo solve_equilibrium(const EquilibriumTarget& target, CollisionModel model,
                                       const VelocityGrid& grid,
                                       EquilibriumCoefficients& coefficients, std::span<Real> f_eq);
// The same from the continuous start.
EquilibriumCoefficients equilibrium(const EquilibriumTarget& target, CollisionModel model,
                                    const VelocityGrid& grid);

// f_eq,k = exp(a . phi(xi_k)) for every ordinate.
void evaluate_equilibrium(const EquilibriumCoefficients& coefficients, const VelocityGrid& grid,
                          std::span<Real> f_eq);

// d f_eq,k / d u_j (SI, row-major: df_du[3 k + j]) at fixed rho and covariance, of the discrete
// equilibrium with these (converged) coefficients; f_eq its values.
void equilibrium_velocity_derivative(const EquilibriumCoefficients& coefficients,
                                     const EquilibriumTarget& target, const VelocityGrid& grid,
                                     std::span<const Real> f_eq, std::span<Real> df_du);

// moments() (macroscopic_state.hpp) of one cell, by the grid's tensor-product kernel when it
// has one (equilibrium_tensor_kernel.hpp: 6 operations per ordinate instead of ~25; the same
// central sums).
MacroState cell_moments(std::span<const Real> f_cell, const VelocityGrid& grid,
                        const KineticGas& gas);

// The continuous Maxwellian rho / (2 pi R T)^(3/2) exp(-|c - u|^2 / (2 R T)) sampled on the
// grid (not discrete-conservative; boundary data and initial states).
void sample_maxwellian(Real rho, const Vec3& u, Real T, const KineticGas& gas,
                       const VelocityGrid& grid, std::span<Real> f);

}  // namespace rfmems

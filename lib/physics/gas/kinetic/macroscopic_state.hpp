// Macroscopic state of one cell from its discrete distribution (thesis eqs. 5.2-5.6), with the
// velocity-space integrals replaced by the grid's quadrature sum_k w_k (.):
//   rho          = sum w f
//   u            = sum w c f / rho
//   Theta_ij     = sum w C_i C_j f / rho,    C = c - u       (covariance, m^2/s^2)
//   T            = tr(Theta) / (3 R),   p = rho R T
//   pressure     P_ij = rho Theta_ij        (kinetic pressure tensor, Pa; tr P / 3 = p)
//   stress       tau_ij = -(P_ij - p delta_ij)  (viscous Cauchy stress, Pa: in plane Couette
//                flow tau_xy = mu du/dy > 0 for a faster top wall)
//   heat_flux    q_i = 1/2 sum w C_i |C|^2 f  (W/m^2)
// These are the moments the discrete-conservative equilibrium (equilibrium.hpp) reproduces.
#pragma once
#include <span>

#include "core/types.hpp"
#include "physics/gas/kinetic/kinetic_gas.hpp"
#include "physics/gas/kinetic/velocity_grid.hpp"

namespace rfmems {

struct MacroState {
  Real rho = 0;
  Vec3 u = Vec3::Zero();
  Real T = 0, p = 0;
  Mat3 stress = Mat3::Zero();  // viscous Cauchy stress -(P - p I)
  Vec3 heat_flux = Vec3::Zero();
  Mat3 pressure_tensor = Mat3::Zero();  // P = rho Theta
};

MacroState moments(std::span<const Real> f_cell, const VelocityGrid& grid, const KineticGas& gas);

}  // namespace rfmems

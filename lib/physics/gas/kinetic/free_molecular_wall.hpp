// Free-molecular momentum exchange between a diffuse wall and a gas at rest: the collisionless
// limit (Kn -> infinity) against which the kinetic gas is checked at large Kn (gas
// damping across regimes, docs/gas_damping.md).
//
// The gas arriving at the wall is the ambient Maxwellian M (rho, T, at rest); the wall (at
// the gas temperature T) moves at velocity U and re-emits every molecule it receives as a
// half-Maxwellian at (U, T) with the density that makes the wall impermeable in its own
// frame. Per unit area, with s = U_n / sqrt(2 R T) the speed ratio of a wall moving INTO the
// gas (U_n = -U . m, m the wall's normal pointing out of the gas):
//   incident flux   N = rho sqrt(R T / 2 pi) [exp(-s^2) + sqrt(pi) s (1 + erf s)]
//   incident normal momentum  P_i = rho R T [s exp(-s^2) / sqrt(pi) + (1/2 + s^2)(1 + erf s)]
//   re-emitted normal momentum P_r = N sqrt(pi R T / 2)     (half-Maxwellian at T)
// (moments of the shifted half-range Maxwellian; Bird 1994, free-molecular flow), so the
// normal stress
// is P_i + P_r = p [1 + (4 + pi) / (2 sqrt(pi)) s + O(s^2)]: a face advancing into the gas at
// U_n feels the excess  dp = p U_n (4 + pi) / (2 sqrt(2 pi R T)),  a receding face the
// deficit. A wall sliding tangentially at U_t re-emits the incident flux with its tangential
// velocity: shear  tau = rho sqrt(R T / 2 pi) U_t = p U_t / sqrt(2 pi R T)  (exact at U_n = 0).
// The traction on the wall is  m (P_i + P_r + rho U_n^2) - tau: the momentum flux through
// the fixed face the wall occupies (as KineticOperator::wall_force), which exceeds the
// wall-frame stress P_i + P_r by rho_face U_n^2 (even in U; rho_face = rho + O(s)).
//
// The same exchange on a discrete velocity grid (the half-range sums the kinetic solver
// takes): the incident half c . m > 0 carries the SAMPLED ambient Maxwellian, the re-emitted
// half c . m < 0 the sampled Maxwellian at (U, T) scaled so that sum_k w_k (c_k - U) . m f_k
// = 0, and the momentum flux is sum_k w_k c_k (c_k . m) f_k through the fixed face (as
// KineticOperator::wall_force; it differs from the wall-frame flux by rho U^2, even in U).
// Sampled Maxwellians, not the solver's discrete equilibria: an independent reference whose
// midpoint sums converge spectrally in the interior and at second order across the kink of
// the half-range integrands at c . m = 0.
#pragma once
#include "core/types.hpp"
#include "physics/gas/kinetic/velocity_grid.hpp"

namespace rfmems {

// Traction (force per unit area, Pa) on a diffuse wall with unit normal m (out of the gas)
// moving at U in the ambient gas (rho, T, at rest) of specific gas constant R: the closed
// form above: normal part exact for a purely normal motion up to O(rho U_n^2 s), shear exact
// for a purely tangential one; to first order in U for a combined motion.
Vec3 free_molecular_wall_traction(Real rho, Real T, Real R, const Vec3& wall_velocity,
                                  const Vec3& unit_normal);

// The same on the discrete velocity grid (momentum flux through the fixed face per unit area).
Vec3 discrete_free_molecular_wall_traction(const VelocityGrid& grid, Real rho, Real T, Real R,
                                           const Vec3& wall_velocity, const Vec3& unit_normal);

// Damping coefficients per unit area, d traction / d U at U = 0 (Pa s/m), continuous:
// normal (4 + pi) p / (2 sqrt(2 pi R T)), tangential p / sqrt(2 pi R T).
struct FreeMolecularDamping {
  Real normal = 0;
  Real tangential = 0;
};
FreeMolecularDamping free_molecular_damping(Real rho, Real T, Real R);

}  // namespace rfmems

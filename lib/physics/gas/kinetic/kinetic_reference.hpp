// The reference state of a kinetic run and its walls' answers in the normalisation of the
// linearised-kinetic literature (Sharipov & Seleznev, J. Phys. Chem. Ref. Data 27 (1998) 657;
// Sharipov, Rarefied Gas Dynamics, Wiley 2016), so that a run compares with their tables as
// printed:
//   p0 = rho0 R T0, T0, rho0       the initial state's (kinetic_case.hpp `initial:`)
//   mu0 = mu(T0),  v0 = sqrt(2 R T0)   (the most probable speed)
//   H = initial.reference_length   (the gap between the walls of a channel; default: the
//                                   mesh's largest extent)
//   delta = p0 H / (mu0 v0)        the rarefaction parameter
//   Kn = sqrt(pi) / (2 delta)      = lambda / H with Bird's lambda = (mu0 / p0) sqrt(pi R T0 / 2)
//                                   (kinetic_gas.hpp): the Kn of `initial.knudsen`
//   U  = the relative wall speed, max |u_i - u_j| over the diffuse walls (0: none moves)
//   dT = the wall temperature difference, max T_w - min T_w over the diffuse walls
// Per diffuse wall, of area A (m^2; m per unit depth in 2D, so that the per-depth force and
// heat flow of a plane run divide to Pa and W/m^2), traction t = F / A of the gas on it:
//   shear_stress tau = -t . e, e the unit tangential part of the wall's velocity relative to
//       the mean of the diffuse walls' velocities: the drag against the wall's motion relative
//       to the others; in plane Couette flow tau = -p_xy on both walls.
//   normalised_shear P = tau v0 / (p0 U)   (defined when U > 0 and the wall moves
//       tangentially relative to the others; free-molecular limit 1 / sqrt(pi), continuum
//       1 / delta)
//   heat_flux q = the heat flow from the gas into the wall / A (W/m^2; positive into the
//       colder wall; a moving wall's includes the work of its shear)
//   normalised_heat_flux q* = q / (p0 v0 dT / T0)   (defined when dT > 0; free-molecular limit
//       1 / sqrt(pi), continuum 5 / (4 Pr delta), Pr = 1 for BGK)
// A channel driven by a body force a (kinetic_operator.hpp) between periodic patches:
//   pressure_gradient xi = (H / p0) dp/dx of the equivalent pressure-driven flow,
//       dp/dx = -rho0 |a|:  xi = -rho0 |a| H / p0 = -2 |a| H / v0^2
//   normalised_flow_rate G = -(2 / (xi H v0)) int u dy over the gap, int u dy = (m / rho0) (H / A)
//       from the mass flow m through the periodic patch the force drives the gas out of, of
//       area A (H per unit depth in 2D): the linear regime's (continuum delta / 6; grows as
//       log(1 / delta) towards the free-molecular limit).
#pragma once
#include <optional>
#include <string>

#include "core/types.hpp"

namespace rfmems {

struct KineticScene;

struct KineticReference {
  Real pressure = 0;                // p0 [Pa]
  Real temperature = 0;             // T0 [K]
  Real density = 0;                 // rho0 [kg/m^3]
  Real viscosity = 0;               // mu0 [Pa s]
  Real thermal_speed = 0;           // v0 [m/s]
  Real reference_length = 0;        // H [m]
  Real rarefaction_parameter = 0;   // delta
  Real knudsen = 0;                 // sqrt(pi) / (2 delta)
  Real wall_speed = 0;              // U [m/s] (0: no wall moves relative to another)
  Real temperature_difference = 0;  // dT [K] (0: every diffuse wall at one temperature)
  Real body_force = 0;              // |a| [m/s^2]
  Real pressure_gradient = 0;       // xi (0: no body force)
};

// G from the mass flow m (kg/s, per unit depth in 2D) through the outflow periodic patch of
// area A.
Real normalised_flow_rate(const KineticReference& reference, Real mass_flow, Real area);

// One sentence defining Kn, for the printed and JSON reports.
inline constexpr const char* kKnudsenDefinition =
    "Kn = sqrt(pi) / (2 delta) = (mu0 / p0) sqrt(pi R T0 / 2) / H";

// The reference state of the scene (its initial state, reference length and diffuse walls).
KineticReference kinetic_reference(const KineticScene& scene);

struct WallAnswer {
  Real area = 0;                             // A
  std::optional<Real> shear_stress;          // tau [Pa]
  std::optional<Real> normalised_shear;      // P
  Real heat_flux = 0;                        // q [W/m^2]
  std::optional<Real> normalised_heat_flux;  // q*
};

// The answers above on the patch `name` from the gas's force F and heat flow Q on it (as
// KineticOperator::wall_force / wall_heat_flow) and its area (KineticOperator::patch_area).
// The normalised values only on a diffuse wall and where U (dT) defines them.
WallAnswer wall_answer(const KineticScene& scene, const KineticReference& reference,
                       const std::string& name, const Vec3& force, Real heat_flow, Real area,
                       const Vec3& area_vector);

}  // namespace rfmems

// Gas properties of the kinetic model: specific gas constant, power-law viscosity, Prandtl
// number, and the collision model (BGK or Holway's ellipsoidal-statistical ESBGK).
//
//   mu(T)  = mu_ref (T / T_ref)^omega                       (thesis eq. 5.30, Bird's law)
//   BGK:   Q(f) = nu (f_M - f),   nu = p / mu              (gives mu; Pr = 1)
//   ESBGK: Q(f) = nu (f_G - f),   nu = Pr p / mu           (Holway 1966; Andries et al. 2000)
//          f_G the Gaussian with the fluid's rho, u and covariance
//          Lambda = (1/Pr) R T I + (1 - 1/Pr) Theta,  rho Theta = int (c-u)(c-u) f dc,
//          which relaxes the shear stress at nu / Pr = p / mu and the heat flux at
//          nu = Pr p / mu, so that Pr = mu c_p / kappa (2/3 for a monatomic gas).
//   Mean free path (Bird's viscosity-based definition, the one behind the slip laws):
//          lambda = (mu / p) sqrt(pi R T / 2),   Kn = lambda / L.
// All SI: R in J/(kg K), mu in Pa s, T in K, p in Pa.
#pragma once
#include <string>

#include "core/types.hpp"

namespace rfmems {

enum class CollisionModel { Bgk, Esbgk };

// "bgk" / "esbgk"; InputError otherwise.
CollisionModel collision_model_from_name(const std::string& name);
const char* collision_model_name(CollisionModel model);

struct KineticGas {
  Real R = 208.13;           // specific gas constant, J/(kg K) (argon: 8.314462618 / 0.039948)
  Real mu_ref = 2.117e-5;    // viscosity at T_ref, Pa s
  Real T_ref = 273.15;       // K
  Real omega = 0.81;         // viscosity exponent
  Real prandtl = 2.0 / 3.0;  // used by ESBGK
  CollisionModel model = CollisionModel::Esbgk;

  // Argon as in the thesis (ch. 5, after Bird): mu_ref = 2.117e-5 Pa s at 273.15 K,
  // omega = 0.81.
  static KineticGas argon(CollisionModel model = CollisionModel::Esbgk);

  Real viscosity(Real T) const;
  Real pressure(Real rho, Real T) const { return rho * R * T; }
  // nu of Q(f) = nu (f_eq - f): p / mu for BGK, Pr p / mu for ESBGK.
  Real collision_frequency(Real rho, Real T) const;
  // Bird's mean free path (mu / p) sqrt(pi R T / 2).
  Real mean_free_path(Real rho, Real T) const;
  Real knudsen(Real rho, Real T, Real length) const { return mean_free_path(rho, T) / length; }
  // The density that gives Knudsen number kn over length at temperature T.
  Real density_for_knudsen(Real kn, Real T, Real length) const;
  // Most probable speed sqrt(2 R T) (the velocity scale of the non-dimensional form).
  Real thermal_speed(Real T) const;
  // Checks the constants (InputError naming the first bad one).
  void validate() const;
};

}  // namespace rfmems

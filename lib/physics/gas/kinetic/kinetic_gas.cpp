#include "physics/gas/kinetic/kinetic_gas.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace rfmems {

CollisionModel collision_model_from_name(const std::string& name) {
  if (name == "bgk") return CollisionModel::Bgk;
  if (name == "esbgk") return CollisionModel::Esbgk;
  throw InputError("unknown collision model '" + name + "' (expected bgk or esbgk)");
}

const char* collision_model_name(CollisionModel model) {
  return model == CollisionModel::Bgk ? "bgk" : "esbgk";
}

KineticGas KineticGas::argon(CollisionModel model) {
  KineticGas gas;
  gas.model = model;
  return gas;
}

Real KineticGas::viscosity(Real T) const { return mu_ref * std::pow(T / T_ref, omega); }

Real KineticGas::collision_frequency(Real rho, Real T) const {
  const Real nu_bgk = pressure(rho, T) / viscosity(T);
  return model == CollisionModel::Esbgk ? prandtl * nu_bgk : nu_bgk;
}

Real KineticGas::mean_free_path(Real rho, Real T) const {
  return viscosity(T) / pressure(rho, T) * std::sqrt(std::numbers::pi * R * T / 2);
}

Real KineticGas::density_for_knudsen(Real kn, Real T, Real length) const {
  // lambda is proportional to 1 / rho at fixed T.
  return mean_free_path(1.0, T) / (kn * length);
}

Real KineticGas::thermal_speed(Real T) const { return std::sqrt(2 * R * T); }

void KineticGas::validate() const {
  if (!(R > 0)) throw InputError("kinetic gas: R must be > 0");
  if (!(mu_ref > 0)) throw InputError("kinetic gas: mu_ref must be > 0");
  if (!(T_ref > 0)) throw InputError("kinetic gas: T_ref must be > 0");
  if (!(omega >= 0 && omega <= 2)) throw InputError("kinetic gas: omega must be in [0, 2]");
  // ESBGK's covariance (1/Pr) R T I + (1 - 1/Pr) Theta is positive definite for every f
  // only when Pr >= 2/3 (Andries et al. 2000).
  if (!(prandtl >= 2.0 / 3.0 * (1 - 1e-12) && prandtl <= 10))
    throw InputError("kinetic gas: Prandtl number must be in [2/3, 10]");
}

}  // namespace rfmems

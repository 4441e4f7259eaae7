// A prestressed film that creeps flat (test/unit/creep): its plate section and the closed form
// of its equibiaxial relaxation, which the plate, von Karman plate and continuum creep systems
// each reproduce.
#pragma once
#include <cmath>

#include "materials/creep_law.hpp"
#include "physics/plate/plate_operator.hpp"

namespace rfmems::test {

// A film of polysilicon-like stiffness under the equibiaxial residual stress sigma0.
inline PlateSection relaxing_film(Real thickness, Real sigma0) {
  PlateSection s;
  s.E = 160e9;
  s.nu = 0.28;
  s.rho = 2330;
  s.thickness = thickness;
  s.residual_stress = Mat3::Zero();
  s.residual_stress(0, 0) = s.residual_stress(1, 1) = sigma0;
  return s;
}

// Equibiaxial plane stress relaxing by creep (B = 0): sigma_eff = sigma, the flow rule gives
// eps_p,xx' = eps_p,yy' = eps_eff'/2 and sigma = sigma0 - E/(1-nu) eps_p,xx, so
//   d sigma/dt = -E/(2 (1-nu)) A (sigma/sigma_y)^m,
//   m = 1: sigma = sigma0 exp(-E A t / (2 (1-nu) sigma_y)),
//   m > 1: sigma^(1-m) = sigma0^(1-m) + (m-1) E A t / (2 (1-nu) sigma_y^m).
inline Real equibiaxial_relaxation(const CreepLaw& law, Real E, Real nu, Real sigma0, Real t) {
  const Real rate = E * law.A / (2 * (1 - nu));
  if (law.m == 1) return sigma0 * std::exp(-rate * t / law.sigma_y0);
  return std::pow(
      std::pow(sigma0, 1 - law.m) + (law.m - 1) * rate * t / std::pow(law.sigma_y0, law.m),
      1 / (1 - law.m));
}

}  // namespace rfmems::test

// Cross-section of a homogeneous isotropic Mindlin-Reissner plate of thickness h.
//   bending stiffness      D = E h^3 / (12 (1 - nu^2))
//   transverse shear       k G h,  G = E / (2 (1 + nu)),  k = 5/6 (Reissner) unless set
//   inertia per unit area  rho h (translation), rho h^3 / 12 (rotation of the normal)
//   membrane force         N0 = h sigma0 of an in-plane residual stress sigma0 (2 x 2 used)
#pragma once
#include "core/types.hpp"

namespace rfmems {

struct PlateSection {
  Real E = 0;          // Young's modulus [Pa]
  Real nu = 0;         // Poisson's ratio
  Real rho = 0;        // density [kg/m^3]
  Real thickness = 0;  // h [m]
  Real shear_factor = 5.0 / 6.0;
  Mat3 residual_stress = Mat3::Zero();  // sigma0 [Pa], tension positive

  Real G() const { return E / (2 * (1 + nu)); }
  Real bending_stiffness() const {
    return E * thickness * thickness * thickness / (12 * (1 - nu * nu));
  }
  Real shear_stiffness() const { return shear_factor * G() * thickness; }
  Real mass_per_area() const { return rho * thickness; }
  Real rotary_inertia() const { return rho * thickness * thickness * thickness / 12; }
  Mat3 membrane_force() const { return thickness * residual_stress; }
};

}  // namespace rfmems

// Isotropic linear elasticity (Hooke's law): sigma = lambda tr(eps) I + 2 mu eps.
// Plane stress uses the reduced lambda* = 2 lambda mu / (lambda + 2 mu) so that the in-plane
// relations match sigma_zz = 0; plane strain keeps lambda (eps_zz = 0).
#pragma once
#include "core/types.hpp"

namespace rfmems {

enum class Hypothesis { PlaneStrain, PlaneStress, ThreeD };

struct LinearElastic {
  Real E = 0;    // Young's modulus [Pa]
  Real nu = 0;   // Poisson's ratio
  Real rho = 0;  // density [kg/m^3]
  Hypothesis hypothesis = Hypothesis::ThreeD;
  // The stress sigma0 the body holds at rest [Pa] (physics/structure/residual_stress.hpp); it
  // is not part of stress(G), which is the stress of the deformation.
  Mat3 residual_stress = Mat3::Zero();

  Real mu() const { return E / (2 * (1 + nu)); }
  Real lambda_3d() const { return E * nu / ((1 + nu) * (1 - 2 * nu)); }
  // The lambda that enters the in-plane (or 3D) stress.
  Real lambda() const {
    Real l = lambda_3d(), m = mu();
    return hypothesis == Hypothesis::PlaneStress ? 2 * l * m / (l + 2 * m) : l;
  }
  // Cauchy stress from a displacement gradient G (G_ij = du_i/dx_j).
  Mat3 stress(const Mat3& G) const {
    Mat3 eps = 0.5 * (G + G.transpose());
    Mat3 s = lambda() * eps.trace() * Mat3::Identity() + 2 * mu() * eps;
    if (hypothesis == Hypothesis::PlaneStress) s(2, 2) = 0;
    if (hypothesis == Hypothesis::PlaneStrain) s(2, 2) = lambda_3d() * eps.trace();
    return s;
  }
};

}  // namespace rfmems

#include "physics/gas/kinetic/free_molecular_wall.hpp"

#include <cmath>
#include <numbers>

namespace rfmems {

namespace {

constexpr Real kPi = std::numbers::pi;

// Maxwellian of density rho, velocity u, temperature T (gas constant R) at c.
Real maxwellian(Real rho, const Vec3& u, Real T, Real R, const Vec3& c) {
  const Real two_rt = 2 * R * T;
  return rho / std::pow(kPi * two_rt, 1.5) * std::exp(-(c - u).squaredNorm() / two_rt);
}

}  // namespace

Vec3 free_molecular_wall_traction(Real rho, Real T, Real R, const Vec3& wall_velocity,
                                  const Vec3& unit_normal) {
  const Vec3& m = unit_normal;
  const Real u_into = -wall_velocity.dot(m);  // speed of the wall into the gas
  const Vec3 u_t = wall_velocity + u_into * m;
  const Real s = u_into / std::sqrt(2 * R * T);
  const Real e = std::exp(-s * s), one_erf = 1 + std::erf(s);
  const Real flux = rho * std::sqrt(R * T / (2 * kPi)) * (e + std::sqrt(kPi) * s * one_erf);
  const Real p_incident = rho * R * T * (s * e / std::sqrt(kPi) + (0.5 + s * s) * one_erf);
  const Real p_emitted = flux * std::sqrt(kPi * R * T / 2);
  const Real shear = rho * std::sqrt(R * T / (2 * kPi));  // per unit tangential velocity
  // Through the fixed face (as the solver's wall force): the wall-frame normal stress plus
  // rho_face u_n^2 (sum (c_n - u_n) f = 0), rho_face = rho + O(s).
  return (p_incident + p_emitted + rho * u_into * u_into) * m - shear * u_t;
}

Vec3 discrete_free_molecular_wall_traction(const VelocityGrid& grid, Real rho, Real T, Real R,
                                           const Vec3& wall_velocity, const Vec3& unit_normal) {
  const Vec3& m = unit_normal;
  // Incident half (c . m > 0, towards the wall): the ambient Maxwellian; re-emitted half:
  // n_w M(U, T) with n_w from sum w (c - U) . m f = 0.
  Vec3 incident_momentum = Vec3::Zero(), emitted_momentum = Vec3::Zero();
  Real incident_flux = 0, emitted_flux = 0;  // sum w (c - U) . m f, emitted per unit n_w
  for (Index k = 0; k < grid.size(); ++k) {
    const Vec3& c = grid.c[k];
    const Real cn = c.dot(m);
    const Real rel = (c - wall_velocity).dot(m);
    if (cn > 0) {
      const Real f = maxwellian(rho, Vec3::Zero(), T, R, c);
      incident_momentum += grid.w[k] * cn * f * c;
      incident_flux += grid.w[k] * rel * f;
    } else {
      const Real f = maxwellian(1, wall_velocity, T, R, c);
      emitted_momentum += grid.w[k] * cn * f * c;
      emitted_flux += grid.w[k] * rel * f;
    }
  }
  const Real n_w = -incident_flux / emitted_flux;
  return incident_momentum + n_w * emitted_momentum;
}

FreeMolecularDamping free_molecular_damping(Real rho, Real T, Real R) {
  const Real p = rho * R * T, root = std::sqrt(2 * kPi * R * T);
  return {(4 + kPi) * p / (2 * root), p / root};
}

}  // namespace rfmems

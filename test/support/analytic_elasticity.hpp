// Closed-form plane elasticity solutions used as references.
#pragma once
#include <cmath>

#include "core/types.hpp"

namespace rfmems::test_support {

// Timoshenko & Goodier (1970, sec. 21) cantilever, plane stress: x in [0, L], y in [-D/2, D/2],
// end x = L loaded by the parabolic shear traction of resultant P (per unit depth), end x = 0
// held at the exact displacement. Tip deflection u_y(L, 0) = P L^3/(3EI) + (4+5 nu) P D^2 L/(24EI)
// (Euler-Bernoulli plus shear deformation).
struct TimoshenkoCantilever {
  double L, D, E, nu, P;
  double I() const { return D * D * D / 12.0; }
  Vec3 displacement(const Vec3& x) const {
    double X = x.x(), Y = x.y(), c = P / (6 * E * I());
    return Vec3(-c * Y * ((6 * L - 3 * X) * X + (2 + nu) * (Y * Y - D * D / 4)),
                c * (3 * nu * Y * Y * (L - X) + (4 + 5 * nu) * D * D * X / 4 + (3 * L - X) * X * X),
                0.0);
  }
  // sigma_xx, sigma_yy, sigma_xy
  Vec3 stress(const Vec3& x) const {
    return Vec3(-P * (L - x.x()) * x.y() / I(), 0.0, P / (2 * I()) * (D * D / 4 - x.y() * x.y()));
  }
  double tip_deflection() const { return displacement(Vec3(L, 0, 0)).y(); }
};

// Kirsch (1898): infinite plate with a hole of radius a under remote tension T along x.
// Plane strain (kappa = 3 - 4 nu).
struct KirschHole {
  double a, T, E, nu;
  double mu() const { return E / (2 * (1 + nu)); }
  double kappa() const { return 3 - 4 * nu; }
  // sigma_xx, sigma_yy, sigma_xy
  Vec3 stress(const Vec3& x) const {
    double r = std::hypot(x.x(), x.y()), th = std::atan2(x.y(), x.x());
    double a2 = a * a / (r * r), a4 = a2 * a2;
    return Vec3(
        T * (1 - a2 * (1.5 * std::cos(2 * th) + std::cos(4 * th)) + 1.5 * a4 * std::cos(4 * th)),
        T * (-a2 * (0.5 * std::cos(2 * th) - std::cos(4 * th)) - 1.5 * a4 * std::cos(4 * th)),
        T * (-a2 * (0.5 * std::sin(2 * th) + std::sin(4 * th)) + 1.5 * a4 * std::sin(4 * th)));
  }
  Vec3 displacement(const Vec3& x) const {
    double r = std::hypot(x.x(), x.y()), th = std::atan2(x.y(), x.x());
    double k = kappa(), c = a * T / (8 * mu());
    return Vec3(c * (r / a * (k + 1) * std::cos(th) +
                     2 * a / r * ((1 + k) * std::cos(th) + std::cos(3 * th)) -
                     2 * std::pow(a / r, 3) * std::cos(3 * th)),
                c * (r / a * (k - 3) * std::sin(th) +
                     2 * a / r * ((1 - k) * std::sin(th) + std::sin(3 * th)) -
                     2 * std::pow(a / r, 3) * std::sin(3 * th)),
                0.0);
  }
  // Traction sigma n on a face with outward normal n.
  Vec3 traction(const Vec3& x, const Vec3& n) const {
    Vec3 s = stress(x);
    return Vec3(s[0] * n.x() + s[2] * n.y(), s[2] * n.x() + s[1] * n.y(), 0.0);
  }
};

// Observed order from errors on meshes refined by `ratio`.
inline double observed_order(double coarse, double fine, double ratio = 2.0) {
  return std::log(coarse / fine) / std::log(ratio);
}

}  // namespace rfmems::test_support

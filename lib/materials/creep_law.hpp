// Secondary (steady-state) creep with strain hardening (thesis ch. 4, eqs. 4.1-4.3; the
// equations were lost in the text extraction and are re-derived here in their standard form):
//
//   effective creep rate    eps_dot_eff = A (sigma_eff / sigma_y)^m               (4.2)
//   strain hardening        sigma_y     = sigma_y0 (1 + B eps_eff)^n              (4.3)
//   von Mises stress        sigma_eff   = sqrt(3/2 s:s),  s = sigma - tr(sigma)/3 I
//   flow rule (Prandtl-Reuss, volume preserving)
//                           eps_dot_p   = eps_dot_eff (3/2) s / sigma_eff
//
// so that sqrt(2/3 eps_dot_p:eps_dot_p) = eps_dot_eff and, under uniaxial stress sigma,
// eps_dot_p,xx = eps_dot_eff. m selects the mechanism: 1 diffusion (Coble), 2 grain-boundary
// sliding, > 3 dislocation power law.
//
// Uniaxial closed form (constant stress, a = A (sigma/sigma_y0)^m, k = m n): the ODE
// d eps/dt = a (1 + B eps)^(-k) is separable, (1 + B eps)^(k+1) = 1 + (k+1) B a t, so
//   eps(t) = ((1 + (k+1) B a t)^(1/(k+1)) - 1) / B      (eps = a t when B = 0).
//
// Derivatives for analytic Jacobians (tensors as symmetric Mat3; a direction d_sigma is a
// symmetric stress increment): with lambda = (3/2) A sigma_y^-m sigma_eff^(m-1),
//   d eps_dot_p = lambda dev(d_sigma) + d_lambda s,
//   d_lambda    = (3/2) A sigma_y^-m (m-1) sigma_eff^(m-2) d_sigma_eff,
//   d_sigma_eff = (3/2) s:d_sigma / sigma_eff,
//   d eps_dot_eff = m eps_dot_eff d_sigma_eff / sigma_eff,
// and both rates scale as sigma_y^-m, so d/d eps_eff = -m rate sigma_y' / sigma_y. At
// sigma_eff = 0 (a neutral fibre) the rate and its stress derivative are taken as 0 (m > 1
// makes them vanish; m = 1 would have a direction-dependent limit).
//
// A negative eps_eff (an integrator's round-off below zero) hardens as eps_eff = 0.
#pragma once
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/types.hpp"

namespace rfmems {

struct CreepRate {
  Mat3 strain_rate = Mat3::Zero();  // eps_dot_p (symmetric, traceless)
  Real effective_rate = 0;          // eps_dot_eff
};

struct CreepLaw {
  Real A = 0;         // rate constant [1/s]
  Real B = 0;         // hardening coefficient [-]
  Real m = 1;         // stress exponent
  Real n = 0;         // hardening exponent
  Real sigma_y0 = 0;  // initial yield stress [Pa]

  void validate() const {
    if (!(A >= 0) || !(B >= 0) || !(m >= 1) || !(n >= 0) || !(sigma_y0 > 0))
      throw InputError(fmt::format(
          "creep law: need A >= 0, B >= 0, m >= 1, n >= 0, sigma_y0 > 0 (A = {}, B = {}, m = {}, "
          "n = {}, sigma_y0 = {})",
          A, B, m, n, sigma_y0));
  }

  Real yield_stress(Real eps_eff) const {
    return sigma_y0 * std::pow(1 + B * std::max(eps_eff, 0.0), n);
  }
  Real yield_stress_derivative(Real eps_eff) const {
    if (eps_eff < 0) return 0;
    return sigma_y0 * n * B * std::pow(1 + B * eps_eff, n - 1);
  }

  static Mat3 deviator(const Mat3& sigma) { return sigma - sigma.trace() / 3 * Mat3::Identity(); }
  static Real effective_stress(const Mat3& sigma) {
    const Mat3 s = deviator(sigma);
    return std::sqrt(1.5 * (s.array() * s.array()).sum());
  }

  Real effective_rate(Real sigma_eff, Real eps_eff) const {
    return A * std::pow(sigma_eff / yield_stress(eps_eff), m);
  }

  CreepRate rate(const Mat3& sigma, Real eps_eff) const {
    CreepRate r;
    const Real se = effective_stress(sigma);
    if (se == 0) return r;
    r.effective_rate = effective_rate(se, eps_eff);
    r.strain_rate = (1.5 * r.effective_rate / se) * deviator(sigma);
    return r;
  }

  // Directional derivative of the rates with respect to the stress, along d_sigma.
  CreepRate rate_stress_derivative(const Mat3& sigma, Real eps_eff, const Mat3& d_sigma) const {
    CreepRate d;
    const Real se = effective_stress(sigma);
    if (se == 0) return d;
    const Mat3 s = deviator(sigma);
    const Real rate = effective_rate(se, eps_eff);
    const Real d_se = 1.5 * (s.array() * d_sigma.array()).sum() / se;
    const Real lambda = 1.5 * rate / se;
    const Real d_lambda = lambda * (m - 1) * d_se / se;
    d.strain_rate = lambda * deviator(d_sigma) + d_lambda * s;
    d.effective_rate = m * rate * d_se / se;
    return d;
  }

  // Derivative of the rates with respect to eps_eff (hardening).
  CreepRate rate_hardening_derivative(const Mat3& sigma, Real eps_eff) const {
    CreepRate d = rate(sigma, eps_eff);
    const Real factor = -m * yield_stress_derivative(eps_eff) / yield_stress(eps_eff);
    d.strain_rate *= factor;
    d.effective_rate *= factor;
    return d;
  }

  // Creep strain at time t under a constant uniaxial stress sigma from eps = 0 (closed form).
  Real uniaxial_strain(Real sigma, Real t) const {
    const Real a = A * std::pow(std::abs(sigma) / sigma_y0, m);
    if (B == 0) return a * t;
    const Real k = m * n;
    return (std::pow(1 + (k + 1) * B * a * t, 1 / (k + 1)) - 1) / B;
  }
};

}  // namespace rfmems

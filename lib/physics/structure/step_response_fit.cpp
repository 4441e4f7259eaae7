#include "physics/structure/step_response_fit.hpp"

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

namespace rfmems {

namespace {

// sin(a) / a and sinh(a) / a, exact to round-off also for small a.
Real sinc(Real a) { return std::abs(a) < 1e-4 ? 1 - a * a / 6 : std::sin(a) / a; }
Real sinhc(Real a) { return std::abs(a) < 1e-4 ? 1 + a * a / 6 : std::sinh(a) / a; }

// The residuals (x(t_i) - x_i) / scale in q = (x_s / scale, ln zeta, ln(w / omega_ref)), the
// logarithms keeping zeta and w positive.
struct Misfit {
  using Scalar = double;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;

  std::span<const Real> t, x;
  Real scale = 1, omega_ref = 1;

  int inputs() const { return 3; }
  int values() const { return static_cast<int>(t.size()); }
  Real static_deflection(const InputType& q) const { return q[0] * scale; }
  static Real zeta(const InputType& q) { return std::exp(q[1]); }
  Real omega(const InputType& q) const { return omega_ref * std::exp(q[2]); }

  int operator()(const InputType& q, ValueType& r) const {
    const Real xs = static_deflection(q), z = zeta(q), w = omega(q);
    for (std::size_t i = 0; i < t.size(); ++i)
      r[static_cast<Eigen::Index>(i)] =
          (xs + (x[0] - xs) * step_response_shape(t[i] - t[0], z, w) - x[i]) / scale;
    return 0;
  }
};

// The time at which x first gets half-way from x_0 to xs (linear between samples).
Real half_rise_time(std::span<const Real> t, std::span<const Real> x, Real xs) {
  const Real half = 0.5 * (xs - x[0]);
  for (std::size_t i = 1; i < t.size(); ++i) {
    const Real a = (x[i - 1] - x[0]) / half, b = (x[i] - x[0]) / half;
    if (b >= 1) return t[i - 1] - t[0] + (t[i] - t[i - 1]) * (b > a ? (1 - a) / (b - a) : 1.0);
  }
  return 0;
}

// omega t at phi's first half-way point (phi = 1/2), for the damping ratio zeta.
Real half_rise_phase(Real zeta) {
  const Real dtau = 1e-3;
  Real tau = 0;
  while (step_response_shape(tau, zeta, 1.0) > 0.5 && tau < 1e3) tau += dtau;
  return tau;
}

}  // namespace

Real step_response_shape(Real t, Real zeta, Real omega) {
  const Real wt = omega * t;
  const Real d = 1 - zeta * zeta;
  if (d >= 0) {  // under- and critically damped
    const Real a = std::sqrt(d) * wt;
    return std::exp(-zeta * wt) * (std::cos(a) + zeta * wt * sinc(a));
  }
  const Real s = std::sqrt(-d), a = s * wt;
  if (a < 1) return std::exp(-zeta * wt) * (std::cosh(a) + zeta * wt * sinhc(a));
  // The two exponentials apart: exp(-zeta wt) cosh(a) overflows for a long overdamped creep.
  return 0.5 * ((1 + zeta / s) * std::exp(-(zeta - s) * wt) +
                (1 - zeta / s) * std::exp(-(zeta + s) * wt));
}

StepResponseFit fit_step_response(std::span<const Real> t, std::span<const Real> x, Real guess_zeta,
                                  Real guess_omega) {
  StepResponseFit out;
  const std::size_t n = t.size();
  if (n < 8 || x.size() != n) return out;
  // The settled value's guess: the mean of the second half.
  Real xs0 = 0;
  for (std::size_t i = n / 2; i < n; ++i) xs0 += x[i];
  xs0 /= static_cast<Real>(n - n / 2);
  const Real scale = std::abs(xs0 - x[0]);
  if (!(scale > 0)) return out;
  const Real t_half = half_rise_time(t, x, xs0);
  if (!(t_half > 0)) return out;

  Misfit misfit;
  misfit.t = t;
  misfit.x = x;
  misfit.scale = scale;
  misfit.omega_ref = half_rise_phase(1.0) / t_half;
  std::vector<Eigen::Vector3d> starts;
  auto start = [&](Real zeta, Real omega) {
    starts.emplace_back(xs0 / scale, std::log(zeta), std::log(omega / misfit.omega_ref));
  };
  for (const Real zeta : {0.001, 0.01, 0.05, 0.2, 0.5, 0.8, 1.2, 2.0, 4.0})
    for (const Real factor : {0.8, 1.0, 1.25}) start(zeta, factor * half_rise_phase(zeta) / t_half);
  if (guess_zeta > 0 && guess_omega > 0) start(guess_zeta, guess_omega);

  Real best = std::numeric_limits<Real>::infinity();
  Eigen::VectorXd best_q;
  Eigen::VectorXd r(static_cast<Eigen::Index>(n));
  for (const Eigen::Vector3d& s : starts) {
    Eigen::NumericalDiff<Misfit> diff(misfit);
    Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Misfit>> lm(diff);
    lm.parameters.maxfev = 2000;
    Eigen::VectorXd q = s;
    lm.minimize(q);
    misfit(q, r);
    const Real ss = r.squaredNorm();
    if (std::isfinite(ss) && ss < best) {
      best = ss;
      best_q = q;
    }
  }
  if (!std::isfinite(best)) return out;
  out.fitted = true;
  out.damping_ratio = Misfit::zeta(best_q);
  const Real w = misfit.omega(best_q);
  out.natural_frequency = w / (2 * M_PI);
  out.damped_frequency = out.damping_ratio < 1
                             ? out.natural_frequency * std::sqrt(1 - std::pow(out.damping_ratio, 2))
                             : 0.0;
  out.static_deflection = misfit.static_deflection(best_q);
  out.residual =
      std::sqrt(best / static_cast<Real>(n)) * scale / std::abs(out.static_deflection - x[0]);
  return out;
}

}  // namespace rfmems

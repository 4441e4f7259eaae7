#include "physics/structure/free_response.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "physics/structure/step_response_fit.hpp"

namespace rfmems {

LogDecrement log_decrement(std::span<const Real> t, std::span<const Real> x) {
  // Extrema (time, value) by a parabola through each local extreme sample and its neighbours.
  std::vector<std::pair<Real, Real>> extrema;
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    const Real a = x[i - 1], b = x[i], c = x[i + 1];
    if (!((b > a && b >= c) || (b < a && b <= c))) continue;
    const Real curvature = a - 2 * b + c;
    const Real dt = t[i + 1] - t[i];
    const Real shift = curvature != 0 ? 0.5 * (a - c) / curvature : 0.0;  // in samples
    extrema.emplace_back(t[i] + shift * dt, b - 0.25 * (a - c) * shift);
  }
  LogDecrement r;
  if (extrema.size() < 3) return r;
  // ln s_k = ln s_0 - k delta / 2: least-squares slope.
  std::vector<Real> k, ln_s;
  for (std::size_t i = 0; i + 1 < extrema.size(); ++i) {
    k.push_back(static_cast<Real>(i));
    ln_s.push_back(std::log(std::abs(extrema[i + 1].second - extrema[i].second)));
  }
  const Real n = static_cast<Real>(k.size());
  Real sk = 0, sl = 0, skk = 0, skl = 0;
  for (std::size_t i = 0; i < k.size(); ++i) {
    sk += k[i];
    sl += ln_s[i];
    skk += k[i] * k[i];
    skl += k[i] * ln_s[i];
  }
  const Real slope = (n * skl - sk * sl) / (n * skk - sk * sk);
  const Real delta = -2 * slope;
  r.damping_ratio = delta / std::sqrt(4 * M_PI * M_PI + delta * delta);
  r.frequency = 0.5 * (extrema.size() - 1) / (extrema.back().first - extrema.front().first);
  r.swings = static_cast<int>(k.size());
  return r;
}

FreeResponse free_response(std::span<const Real> t, std::span<const Real> x) {
  FreeResponse r;
  r.log_decrement = log_decrement(t, x);
  const LogDecrement& ld = r.log_decrement;
  const Real zeta_ld = std::min(ld.damping_ratio, 0.99);
  const StepResponseFit fit = fit_step_response(
      t, x, ld.swings > 0 ? zeta_ld : 0.0,
      ld.swings > 0 ? 2 * M_PI * ld.frequency / std::sqrt(1 - zeta_ld * zeta_ld) : 0.0);
  r.fitted = fit.fitted;
  r.fit_damping_ratio = r.damping_ratio = fit.damping_ratio;
  r.fit_frequency = r.frequency = fit.damped_frequency;
  r.natural_frequency = fit.natural_frequency;
  r.residual = fit.residual;
  r.from_log_decrement = fit.fitted && ld.swings >= 4 && fit.damped_frequency > 0 &&
                         std::abs(ld.frequency / fit.damped_frequency - 1) <= 0.02;
  if (r.from_log_decrement) {
    r.damping_ratio = ld.damping_ratio;
    r.frequency = ld.frequency;
    r.natural_frequency = ld.frequency / std::sqrt(1 - zeta_ld * zeta_ld);
  }
  return r;
}

}  // namespace rfmems

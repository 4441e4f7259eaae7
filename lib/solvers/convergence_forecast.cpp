#include "solvers/convergence_forecast.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rfmems {

std::optional<IterationForecast> ConvergenceForecast::of(std::span<const Real> ratios,
                                                         Real tolerance) {
  const std::size_t n = ratios.size();
  if (n < static_cast<std::size_t>(kMinIterations)) return std::nullopt;
  const Real now = ratios[n - 1];
  if (!(now > 0) || !std::isfinite(now)) return std::nullopt;
  IterationForecast f;
  f.rate = std::numeric_limits<Real>::infinity();
  for (const std::size_t m : {3 * n / 4, n / 2}) {
    const Real then = ratios[m - 1];
    if (!(then > 0) || !std::isfinite(then)) return std::nullopt;
    f.rate = std::min(f.rate, std::pow(now / then, 1.0 / Real(n - m)));
  }
  if (now <= tolerance)
    f.remaining = 0;
  else if (f.rate >= 1)
    f.remaining = std::numeric_limits<Real>::infinity();
  else
    f.remaining = std::log(tolerance / now) / std::log(f.rate);
  return f;
}

std::string ConvergenceForecast::hopeless(std::span<const Real> ratios, Real tolerance,
                                          int max_iterations, const char* solver) {
  const std::optional<IterationForecast> f = of(ratios, tolerance);
  const Real done = Real(ratios.size());
  if (!f || done + f->remaining <= Real(max_iterations)) return {};
  if (!std::isfinite(f->remaining))
    return fmt::format(
        "{} stopped after {} of its {} iterations: no progress over the last {} (residual "
        "ratio {:.3e}, tolerance {:.1e})",
        solver, ratios.size(), max_iterations, ratios.size() - ratios.size() / 2, ratios.back(),
        tolerance);
  return fmt::format(
      "{} stopped after {} of its {} iterations: at its contraction rate of {:.6f} per "
      "iteration, the residual ratio {:.3e} reaches the tolerance {:.1e} only after about "
      "{:.3g} more",
      solver, ratios.size(), max_iterations, f->rate, ratios.back(), tolerance, f->remaining);
}

}  // namespace rfmems

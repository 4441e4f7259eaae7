// A forecast of a linearly converging iteration (source iteration, multigrid cycles) from its
// residual history, so that a solve that cannot reach its tolerance within its iteration cap
// says so early instead of at the cap.
//
// A linearly converging iteration has r_n ~ C rho^n. From the residual ratios r_1..r_n the
// contraction rate is estimated over the end of the history,
//   rho = (r_n / r_m)^(1 / (n - m)),  the smaller of m = 3 n / 4 and m = n / 2,
// and the iterations still needed to reach the tolerance are
//   k = log(tol / r_n) / log(rho)      (infinite when rho >= 1: no progress).
// The early iterations are left out: their fast modes decay quickly and would make rho look
// better than the iteration's asymptotic rate. Of the two windows the faster rate is taken, so
// that a few noisy iterations (a multigrid cycle that gains nothing) do not read as a stall.
// For source iteration the rate only worsens as the fast modes die out (it tends to 1 as
// Kn -> 0), so the forecast errs on the side of optimism: one beyond the cap is a failure
// that the remaining iterations would only confirm.
#pragma once
#include <optional>
#include <span>
#include <string>

#include "core/types.hpp"

namespace rfmems {

struct IterationForecast {
  Real rate = 1;       // contraction per iteration at the end of the history
  Real remaining = 0;  // iterations still needed to reach the tolerance (inf: none suffices)
};

// The forecast from the ratios after each iteration, or nothing before kMinIterations (too
// little history to tell a slow mode from a transient).
class ConvergenceForecast {
 public:
  static constexpr int kMinIterations = 40;

  static std::optional<IterationForecast> of(std::span<const Real> ratios, Real tolerance);

  // Why the iteration should stop now: its forecast needs more iterations than max_iterations
  // allows in total. Empty while the forecast fits, or before there is enough history.
  // `solver` names it in the sentence ("sequential solver", "COMET").
  static std::string hopeless(std::span<const Real> ratios, Real tolerance, int max_iterations,
                              const char* solver);
};

}  // namespace rfmems

#include "io/iteration_progress.hpp"

#include <utility>

#include "io/progress.hpp"
#include "solvers/convergence_forecast.hpp"

namespace rfmems {

IterationProgress::IterationProgress(bool quiet, Real tolerance, std::string program,
                                     std::string remedy, std::FILE* out)
    : quiet_(quiet),
      tolerance_(tolerance),
      program_(std::move(program)),
      remedy_(std::move(remedy)),
      out_(out) {}

bool IterationProgress::operator()(int iteration, Real ratio) {
  if (quiet_) return true;
  ratios_.push_back(ratio);
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  if (elapsed - last_print_ <= kInterval) return true;
  last_print_ = elapsed;
  const auto forecast = ConvergenceForecast::of(ratios_, tolerance_);
  if (!forecast) {
    std::fprintf(out_, "iteration %d: residual ratio %.3e (%.0f s)\n", iteration, ratio, elapsed);
    return true;
  }
  const double left = forecast->remaining * elapsed / iteration;
  std::fprintf(out_,
               "iteration %d: residual ratio %.3e, %.5f per iteration, ~%.2g more to %.0e (~%s) "
               "(%.0f s)\n",
               iteration, ratio, forecast->rate, forecast->remaining, tolerance_,
               format_duration(left).c_str(), elapsed);
  if (!warned_ && left > kSlowSeconds) {
    warned_ = true;
    std::fprintf(out_, "%s: warning: at this rate the solve needs ~%s more%s%s\n", program_.c_str(),
                 format_duration(left).c_str(), remedy_.empty() ? "" : "; ", remedy_.c_str());
  }
  return true;
}

}  // namespace rfmems

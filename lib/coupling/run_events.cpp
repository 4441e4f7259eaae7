#include "coupling/run_events.hpp"

#include <algorithm>

namespace rfmems {

RunEvents::RunEvents(const DynamicOptions& options, Real turning_after)
    : options_(options),
      turning_(options.turning_retreat, turning_after),
      ends_(early_ends(options)),
      stop_time_(options.end_time) {}

void RunEvents::roots(Real min_gap, Real x, Real v, std::span<Real> g) const {
  g[0] = min_gap - options_.contact_gap;
  turning_.roots(x, v, g.subspan(1, TurningBack::kRoots));
  g[kRoots - 1] = options_.release_gap > 0 ? min_gap - options_.release_gap : 1.0;
}

bool RunEvents::at_root(Real t, Real x, const std::vector<int>& found, DynamicRun& run) {
  if (found[0] < 0) {
    ++run.touch_downs;
    if (!run.pulled_in) {
      run.pulled_in = true;
      run.pull_in_time = t;
      if (options_.stop_at_contact) return true;
      if (options_.stop_after_contact >= 0)
        stop_time_ = std::min(options_.end_time, t + options_.stop_after_contact);
    }
  }
  if (found[kRoots - 1] > 0) {
    run.released = true;
    run.release_time = t;
    return true;
  }
  if (turning_.at_root(t, x, found[1], found[2]) && !run.pulled_in) {
    run.turning_time = turning_.turning_time();
    return options_.stop_at_turning;
  }
  return false;
}

}  // namespace rfmems

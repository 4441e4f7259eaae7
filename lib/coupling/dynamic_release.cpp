#include "coupling/dynamic_release.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "core/error.hpp"

namespace rfmems {

ReleaseApproach approach_contact(SwitchSystem& system, Index control, const DynamicOptions& base,
                                 const ReleaseOptions& release) {
  if (!system.actuation().contact().enabled())
    throw std::logic_error("approach_contact: the actuation has no contact penalty");
  DynamicOptions o = base;
  o.stop_at_turning = false;
  o.stop_at_contact = false;
  o.release_gap = 0;
  if (release.drop_time >= 0) {
    o.end_time = release.drop_time;
    o.stop_after_contact = -1;
  } else {
    o.stop_after_contact = release.delay;
  }
  const Real v = release.voltage;
  ReleaseApproach a;
  a.run = run_dynamic(
      system, control, [v](Real) { return v; }, o);
  if (!a.run.pulled_in)
    throw SolverError(
        fmt::format("release: a step to {:.4g} V does not touch down by {:g} s", v, o.end_time));
  a.drop = a.run.final_state;
  return a;
}

DynamicRun run_hold(SwitchSystem& system, Index control, const DynamicState& drop,
                    Real hold_voltage, const DynamicOptions& base, const ReleaseOptions& release) {
  DynamicOptions o = base;
  o.stop_at_turning = false;
  o.stop_at_contact = false;
  o.stop_after_contact = -1;
  o.end_time = drop.t + release.window;
  o.release_gap = o.contact_gap + release.lift;
  return run_dynamic(
      system, control, [hold_voltage](Real) { return hold_voltage; }, o, &drop);
}

DynamicPullOut find_dynamic_pull_out(SwitchSystem& system, Index control, const DynamicState& drop,
                                     Real low, Real high, Real tolerance,
                                     const DynamicOptions& base, const ReleaseOptions& release) {
  DynamicOptions quiet = base;
  quiet.output_interval = 0;
  DynamicPullOut result;
  auto run_at = [&](Real v) {
    DynamicRun run = run_hold(system, control, drop, v, quiet, release);
    ++result.runs;
    result.steps += run.stats.steps;
    result.residual_evals += run.stats.residual_evals;
    return run;
  };
  DynamicRun at_low = run_at(low);
  if (!at_low.released)
    throw SolverError(
        fmt::format("dynamic pull-out: a hold at {:.4g} V does not release within "
                    "{:g} s (lower the bracket or lengthen the window)",
                    low, release.window));
  if (run_at(high).released)
    throw SolverError(
        fmt::format("dynamic pull-out: a hold at {:.4g} V releases (raise the bracket)", high));
  while (high - low > tolerance) {
    const Real mid = 0.5 * (low + high);
    DynamicRun run = run_at(mid);
    if (run.released) {
      low = mid;
      at_low = std::move(run);
    } else {
      high = mid;
    }
  }
  result.voltage = high;
  result.released = low;
  result.release_time = at_low.release_time - drop.t;
  return result;
}

}  // namespace rfmems

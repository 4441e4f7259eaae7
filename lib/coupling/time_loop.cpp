#include "coupling/time_loop.hpp"

#include <algorithm>

#include "coupling/run_events.hpp"

namespace rfmems {

DynamicRun run_time_loop(IdaIntegrator& ida, const DynamicOptions& options,
                         const TimeLoopScheme& scheme) {
  RunEvents events(options, scheme.turning_after);
  ida.set_roots(RunEvents::kRoots,
                [&](Real, std::span<const Real> yy, std::span<const Real> yyp, std::span<Real> g) {
                  const RunWatch w = scheme.watch(yy, yyp);
                  events.roots(w.min_gap, w.control, w.velocity, g);
                });
  auto step = [&](Real t_stop) { return scheme.step ? scheme.step(t_stop) : ida.step(t_stop); };
  // IDA's normal mode takes the same internal steps as its one-step mode without stopping
  // after each: enough where nothing looks at every step.
  const bool every_step = scheme.exchange || events.step_rules_armed();

  const Real t0 = ida.time();
  const Real interval =
      options.output_interval > 0 ? options.output_interval : options.end_time - t0;
  DynamicRun run;
  run.history.push_back(scheme.sample(t0, ida.y()));
  Real next_output = std::min(options.end_time, t0 + interval);
  // The samples at the output times the last step passed before t, from IDA's interpolation.
  std::vector<Real> y_out, yp_out;
  auto sample_passed = [&](Real t) {
    while (options.output_interval > 0 && next_output < t) {
      ida.state_at(next_output, y_out, yp_out);
      run.history.push_back(scheme.sample(next_output, y_out));
      next_output = std::min(options.end_time, next_output + interval);
    }
  };
  while (true) {
    const Real stop_time = events.stop_time();
    const IdaIntegrator::Status status =
        every_step ? step(stop_time) : ida.advance(std::min(next_output, stop_time));
    const Real t = ida.time();
    const RunWatch w = scheme.watch(ida.y(), ida.yp());
    run.extreme_control = std::min(run.extreme_control, w.control);
    bool last = (status == IdaIntegrator::Status::Reached && t >= stop_time * (1 - 1e-12)) ||
                (status == IdaIntegrator::Status::Root &&
                 events.at_root(t, w.control, ida.roots_found(), run));
    if (scheme.exchange) scheme.exchange(t, last, run);
    sample_passed(t);
    if (!last && events.step_rules_armed()) {
      const RunForces f = scheme.forces(t, ida.y());
      last = events.at_step(t, f.voltage, w.control, w.velocity, f.gas, f.electrostatic, run);
    }
    const bool at_output = options.output_interval > 0 && next_output <= t;
    if (last || at_output) run.history.push_back(scheme.sample(t, ida.y()));
    if (last) break;
    if (at_output) next_output = std::min(options.end_time, next_output + interval);
  }
  run.final_time = ida.time();
  run.final_state = {ida.time(), std::vector<Real>(ida.y().begin(), ida.y().end()),
                     std::vector<Real>(ida.yp().begin(), ida.yp().end())};
  run.stats = ida.stats();
  return run;
}

}  // namespace rfmems

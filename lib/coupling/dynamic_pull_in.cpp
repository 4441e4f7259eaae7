#include "coupling/dynamic_pull_in.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "coupling/time_loop.hpp"

namespace rfmems {

bool EarlyEnds::at_step(Real t, Real voltage, Real x, Real v, Real gas_force,
                        Real electrostatic_force, DynamicRun& run) {
  if (run.pulled_in) return false;
  if (settle.at_step(t, x, v, gas_force, electrostatic_force, voltage)) {
    run.settled = true;
    return true;
  }
  if (past.at_step(voltage, x, v)) {
    run.pulled_in = run.past_fold = true;
    return true;
  }
  return false;
}

EarlyEnds early_ends(bool stop_at_turning, Real settle_tolerance, const FoldBranch& fold,
                     bool stop_past_fold, Real past_fold_margin) {
  EarlyEnds ends;
  ends.settle = {stop_at_turning ? settle_tolerance : 0.0, fold.control, fold.voltage};
  if (stop_at_turning && stop_past_fold) ends.past = {fold, past_fold_margin};
  return ends;
}

EarlyEnds early_ends(const DynamicOptions& options) {
  return early_ends(options.stop_at_turning, options.settle_tolerance, options.fold,
                    options.stop_past_fold, options.past_fold_margin);
}

DynamicRun run_dynamic(SwitchSystem& system, Index control, std::function<Real(Real)> voltage,
                       const DynamicOptions& options, const DynamicState* start) {
  system.actuation().set_voltage_squared([voltage](Real t) {
    const Real v = voltage(t);
    return v * v;
  });
  std::vector<Real> y, yp;
  Real t0 = 0;
  if (start) {
    t0 = start->t;
    y = start->y;
    yp = start->yp;
  } else {
    system.initial_state(0.0, y, yp);
  }
  IdaIntegrator ida(system, with_state_tolerances(options.ida, system, options.tolerances));
  ida.initialize(t0, y, yp);
  const Real span = options.end_time - t0;
  const Real first_output =
      t0 + (options.output_interval > 0 ? std::min(options.output_interval, span) : span);
  try {
    ida.correct_initial_conditions(first_output);
  } catch (const SolverError&) {
    // From a stored state IDACalcIC's line search can stall on a state that is consistent to
    // round-off already (a stiff contact at rest); IDA's first steps then absorb what is left.
    if (!start) throw;
    ida.reinitialize(t0, y, yp);
  }
  // One system: nothing to exchange between steps.
  TimeLoopScheme scheme;
  scheme.watch = [&](std::span<const Real> yy, std::span<const Real> yyp) {
    return RunWatch{system.min_gap(yy), system.displacement(yy, control),
                    system.velocity(yy, yyp, control)};
  };
  scheme.forces = [&](Real t, std::span<const Real> state) {
    return RunForces{voltage(t), system.electrostatic_force(t, state), system.gas_force(state)};
  };
  scheme.sample = [&](Real t, std::span<const Real> state) {
    return DynamicSample{t,
                         system.displacement(state, control),
                         system.min_gap(state),
                         system.electrostatic_force(t, state),
                         system.gas_force(state),
                         system.contact_force(t, state),
                         voltage(t)};
  };
  return run_time_loop(ida, options, scheme);
}

FreeResponse free_response(const std::vector<DynamicSample>& history) {
  std::vector<Real> t, x;
  for (const DynamicSample& s : history) {
    t.push_back(s.t);
    x.push_back(s.control);
  }
  return free_response(t, x);
}

std::function<Real(Real)> VoltageWaveform::at(Real amplitude) const {
  const VoltageWaveform w = *this;
  return [w, amplitude](Real t) {
    const Real rise = w.rise_time > 0 ? std::clamp(t / w.rise_time, 0.0, 1.0) : 1.0;
    const bool held = w.kind == Kind::Pulse && t >= w.release_time;
    return amplitude * (held ? w.hold_fraction : (w.kind == Kind::Step ? 1.0 : rise));
  };
}

DynamicOptions with_tolerances_scaled(DynamicOptions options, Real factor) {
  options.ida = with_tolerances_scaled(options.ida, factor);
  options.tolerances.displacement *= factor;
  options.tolerances.pressure *= factor;
  options.tolerances.quasi_static *= factor;
  return options;
}

DynamicPullIn find_dynamic_pull_in(SwitchSystem& system, Index control, Real low, Real high,
                                   Real tolerance, const DynamicOptions& options,
                                   const VoltageWaveform& waveform) {
  DynamicOptions quiet = options;
  quiet.output_interval = 0;
  // A pulse's drop can release a structure that was past the unstable equilibrium of its step.
  quiet.stop_past_fold = options.stop_past_fold && waveform.kind != VoltageWaveform::Kind::Pulse;
  DynamicOptions to_contact = quiet;
  to_contact.stop_past_fold = false;
  return find_dynamic_pull_in(
      [&](Real v) { return run_dynamic(system, control, waveform.at(v), quiet); }, low, high,
      tolerance, options.end_time,
      [&](Real v) { return run_dynamic(system, control, waveform.at(v), to_contact); });
}

DynamicPullIn find_dynamic_pull_in(const PullInRunner& runner, Real low, Real high, Real tolerance,
                                   Real end_time, const PullInRunner& to_contact) {
  DynamicPullIn result;
  auto run_at = [&](Real v, const PullInRunner& by = {}) {
    DynamicRun run = (by ? by : runner)(v);
    ++result.runs;
    result.settled_runs += run.settled;
    result.past_fold_runs += run.past_fold;
    result.steps += run.stats.steps;
    result.residual_evals += run.stats.residual_evals;
    return run;
  };
  if (run_at(low).pulled_in)
    throw SolverError(
        fmt::format("dynamic pull-in: {:.4g} V already pulls in (lower the bracket)", low));
  DynamicRun at_high = run_at(high);
  if (!at_high.pulled_in)
    throw SolverError(
        fmt::format("dynamic pull-in: {:.4g} V does not pull in within {:g} s "
                    "(raise the bracket or the end time)",
                    high, end_time));
  while (high - low > tolerance) {
    const Real mid = 0.5 * (low + high);
    DynamicRun run = run_at(mid);
    if (run.pulled_in) {
      high = mid;
      at_high = std::move(run);
    } else {
      low = mid;
    }
  }
  result.upper_past_fold = at_high.past_fold;
  if (at_high.past_fold && to_contact) {
    // The upper end's touch-down time: its step again, to contact or end_time. Turning back or
    // settling instead would say the rule's margin is too small for this structure.
    at_high = run_at(high, to_contact);
    if (at_high.turning_time > 0 || at_high.settled)
      throw SolverError(fmt::format(
          "dynamic pull-in: {:.4g} V passed the unstable equilibrium but then {} (raise "
          "pull_in.dynamic.past_fold_margin)",
          high, at_high.settled ? "settled" : "turned back"));
  }
  result.pull_in_time = at_high.pull_in_time;
  result.voltage = high;
  result.lower = low;
  return result;
}

}  // namespace rfmems

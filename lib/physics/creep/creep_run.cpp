// The creep run: segments between output times, lifetime events, checkpoints (see the header).
#include "physics/creep/creep_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.hpp"
#include "physics/creep/explicit_creep_integrator.hpp"
#include "solvers/ida_integrator.hpp"

namespace rfmems {

namespace {

using Clock = std::chrono::steady_clock;
using End = CreepRunResult::End;

std::string output_key(std::size_t k) { return fmt::format("outputs/{:06d}", k); }

// The checkpoint of a run at the end of a segment.
Checkpoint make_checkpoint(const CreepRunSettings& settings, const CreepRunResult& r,
                           std::size_t next_output, double wall_time) {
  Checkpoint cp;
  cp.time = r.final_time;
  cp.state = r.state;
  cp.state_dot = r.state_dot;
  cp.settings_hash = settings.settings_hash;
  cp.numbers["next_output"] = static_cast<double>(next_output);
  cp.numbers["steps"] = static_cast<double>(r.steps);
  cp.numbers["last_step"] = r.last_step;
  cp.numbers["wall_time_s"] = wall_time;
  cp.numbers["n_outputs"] = static_cast<double>(r.outputs.size());
  cp.arrays["series/time"] = r.series_times;
  std::vector<double> flat;
  for (const auto& row : r.series) flat.insert(flat.end(), row.begin(), row.end());
  cp.arrays["series/values"] = std::move(flat);
  for (std::size_t k = 0; k < r.outputs.size(); ++k) {
    cp.arrays[output_key(k) + "/time"] = {r.outputs[k].time};
    for (const auto& [name, values] : r.outputs[k].fields)
      cp.arrays[output_key(k) + "/fields/" + name] = values;
  }
  return cp;
}

// Restores what make_checkpoint stored; returns the next output index.
std::size_t restore(const Checkpoint& cp, const std::string& file, std::size_t n_columns,
                    CreepRunResult& r) {
  auto fail = [&](const std::string& what) {
    throw InputError(fmt::format("{}: checkpoint is inconsistent: {}", file, what));
  };
  auto number = [&](const std::string& name) {
    const auto it = cp.numbers.find(name);
    if (it == cp.numbers.end()) fail("no number '" + name + "'");
    return it->second;
  };
  auto array = [&](const std::string& name) -> const std::vector<double>& {
    const auto it = cp.arrays.find(name);
    if (it == cp.arrays.end()) fail("no array '" + name + "'");
    return it->second;
  };
  r.final_time = cp.time;
  r.state = cp.state;
  r.state_dot = cp.state_dot;
  r.steps = static_cast<long>(number("steps"));
  r.last_step = number("last_step");
  r.series_times = array("series/time");
  const std::vector<double>& flat = array("series/values");
  if (flat.size() != r.series_times.size() * n_columns) fail("series size");
  for (std::size_t i = 0; i < r.series_times.size(); ++i)
    r.series.emplace_back(flat.begin() + static_cast<long>(i * n_columns),
                          flat.begin() + static_cast<long>((i + 1) * n_columns));
  const auto n_outputs = static_cast<std::size_t>(number("n_outputs"));
  const std::string fields_prefix = "/fields/";
  for (std::size_t k = 0; k < n_outputs; ++k) {
    CreepOutput out;
    const std::vector<double>& time = array(output_key(k) + "/time");
    if (time.size() != 1) fail("output time");
    out.time = time[0];
    const std::string prefix = output_key(k) + fields_prefix;
    for (auto it = cp.arrays.lower_bound(prefix);
         it != cp.arrays.end() && it->first.compare(0, prefix.size(), prefix) == 0; ++it)
      out.fields[it->first.substr(prefix.size())] = it->second;
    r.outputs.push_back(std::move(out));
  }
  return static_cast<std::size_t>(number("next_output"));
}

// Records the series row and the output fields at (t, state).
void record(const CreepRunModel& model, CreepSystem& system, Real t, std::span<const Real> state,
            CreepRunResult& r) {
  r.series_times.push_back(t);
  r.series.push_back(model.sample(system, t, state));
  CreepOutput out;
  out.time = t;
  if (model.output_fields) out.fields = model.output_fields(system, t, state);
  r.outputs.push_back(std::move(out));
}

struct SegmentEnd {
  bool event = false;
  End kind = End::EndTime;
};

// One segment with IDA: a fresh integrator from (t, y, y') to t_next, or to an event.
SegmentEnd implicit_segment(const CreepRunModel& model, const CreepRunSettings& s,
                            CreepSystem& system, Real t_next, CreepRunResult& r) {
  IdaOptions options;
  options.rtol = s.rtol;
  options.atol = s.atol;
  // Start where the previous segment's steps had grown to (IDA cuts it if the error test
  // fails): saves most of the restart's ramp-up from a tiny first step.
  options.initial_step = s.segment_initial_step_from_previous ? r.last_step : 0;
  options.linear_solver = s.krylov && system.has_preconditioner()
                              ? IdaOptions::LinearSolver::Spgmr
                              : IdaOptions::LinearSolver::Direct;
  IdaIntegrator ida(system, options);
  std::vector<int> root_kind;  // which End each root is
  if (s.gap_threshold_event) root_kind.push_back(static_cast<int>(End::GapThreshold));
  if (s.collapse_event) root_kind.push_back(static_cast<int>(End::Collapse));
  if (!root_kind.empty()) {
    ida.set_roots(
        static_cast<int>(root_kind.size()),
        [&](Real t, std::span<const Real> y, std::span<const Real> yp, std::span<Real> g) {
          int k = 0;
          const Real gap = model.min_gap(y);
          if (s.gap_threshold_event) g[k++] = gap - s.gap_threshold;
          if (s.collapse_event) g[k++] = gap + s.collapse_fraction * t * model.min_gap_rate(y, yp);
        });
  }
  ida.initialize(r.final_time, r.state, r.state_dot);
  SegmentEnd end;
  try {
    const auto status = ida.advance(t_next);
    if (status == IdaIntegrator::Status::Root) {
      const std::vector<int> found = ida.roots_found();
      for (std::size_t k = 0; k < found.size(); ++k)
        if (found[k] != 0) {
          end.event = true;
          end.kind = static_cast<End>(root_kind[k]);
          break;
        }
    }
  } catch (const SolverError& e) {
    if (!model.min_gap) throw;
    // No equilibrium past here: the creep-induced pull-in overtook the collapse root.
    end.event = true;
    end.kind = End::EquilibriumLost;
    r.message = e.what();
  }
  r.steps += ida.stats().steps;
  r.last_step = ida.stats().last_step;
  r.final_time = ida.time();
  r.state.assign(ida.y().begin(), ida.y().end());
  r.state_dot.assign(ida.yp().begin(), ida.yp().end());
  return end;
}

// One segment of explicit Euler steps of dt (the last shortened to land on t_next), with the
// lifetime events checked after every step and located by linear interpolation.
SegmentEnd explicit_segment(const CreepRunModel& model, const CreepRunSettings& s,
                            CreepSystem& system, Real t_next, CreepRunResult& r) {
  const Real dt = s.explicit_dt;
  ExplicitCreepIntegrator euler(system, dt);
  euler.initialize(r.final_time, r.state);
  const Index ns = system.structural_size();
  auto derivatives = [&](std::span<const Real> state) {
    std::vector<Real> d(state.size(), 0.0);  // q' = g; the structure's rate is not needed
    system.creep_rates(euler.time(), state, std::span<Real>(d).subspan(ns));
    return d;
  };
  std::vector<Real> previous(r.state);
  Real t_prev = r.final_time;
  Real gap_prev = model.min_gap ? model.min_gap(previous) : 0;
  Real collapse_prev = std::numeric_limits<Real>::quiet_NaN();
  SegmentEnd end;
  while (euler.time() < t_next) {
    const Real target = (t_next - euler.time() <= dt * (1 + 1e-9)) ? t_next : euler.time() + dt;
    try {
      euler.advance(target);
    } catch (const SolverError& e) {
      if (!model.min_gap) throw;
      end = {true, End::EquilibriumLost};
      r.message = e.what();
      break;
    } catch (const RecoverableError& e) {  // a gap closed inside the equilibrium solve
      if (!model.min_gap) throw;
      end = {true, End::EquilibriumLost};
      r.message = e.what();
      break;
    }
    ++r.steps;
    const Real t = euler.time();
    std::span<const Real> state = euler.state();
    if (model.min_gap) {
      const Real gap = model.min_gap(state);
      // Event functions at the end of the step, and their values at its start.
      struct Candidate {
        bool active;
        Real before, after;
        End kind;
      };
      const Real rate = (gap - gap_prev) / (t - t_prev);
      const Real collapse = gap + s.collapse_fraction * t * rate;
      const Candidate candidates[2] = {
          {s.gap_threshold_event, gap_prev - s.gap_threshold, gap - s.gap_threshold,
           End::GapThreshold},
          {s.collapse_event && !std::isnan(collapse_prev), collapse_prev, collapse, End::Collapse}};
      Real theta_first = 2;
      for (const Candidate& c : candidates)
        if (c.active && c.after <= 0 && c.before > 0) {
          const Real theta = c.before / (c.before - c.after);
          if (theta < theta_first) theta_first = theta, end.kind = c.kind;
        }
      if (s.collapse_event && std::isnan(collapse_prev) && collapse <= 0)
        theta_first = 1, end.kind = End::Collapse;  // first step: no bracket to interpolate
      if (theta_first <= 1) {
        end.event = true;
        r.final_time = t_prev + theta_first * (t - t_prev);
        r.state.resize(state.size());
        for (std::size_t k = 0; k < state.size(); ++k)
          r.state[k] = previous[k] + theta_first * (state[k] - previous[k]);
        r.state_dot = derivatives(r.state);
        return end;
      }
      gap_prev = gap;
      collapse_prev = collapse;
    }
    previous.assign(state.begin(), state.end());
    t_prev = t;
  }
  r.final_time = t_prev;
  r.state = previous;
  r.state_dot = derivatives(r.state);
  return end;
}

}  // namespace

std::string to_string(CreepRunResult::End end) {
  switch (end) {
    case End::EndTime:
      return "end_time";
    case End::GapThreshold:
      return "gap_threshold";
    case End::Collapse:
      return "collapse";
    case End::EquilibriumLost:
      return "equilibrium_lost";
  }
  return "unknown";
}

void CreepRunSettings::validate() const {
  if (output_times.empty()) throw InputError("creep run: no output times");
  Real previous = 0;
  for (Real t : output_times) {
    if (!(t > previous))
      throw InputError(fmt::format(
          "creep run: output times must be > 0 and increasing ({} after {})", t, previous));
    previous = t;
  }
  if (integration == Integration::Explicit && !(explicit_dt > 0))
    throw InputError(fmt::format("creep run: explicit time step must be > 0, got {}", explicit_dt));
  if (!(rtol > 0) || !(atol > 0))
    throw InputError(fmt::format("creep run: rtol and atol must be > 0 ({}, {})", rtol, atol));
  if (collapse_event && !(collapse_fraction > 0 && collapse_fraction < 1))
    throw InputError(
        fmt::format("creep run: collapse fraction must be in (0, 1), got {}", collapse_fraction));
  if (checkpoint_every_steps < 0 || checkpoint_every_seconds < 0)
    throw InputError("creep run: checkpoint intervals must be >= 0");
}

CreepRunResult run_creep(const CreepRunModel& model, const CreepRunSettings& s,
                         const Checkpoint* restart, const std::string& checkpoint_file) {
  s.validate();
  if ((s.gap_threshold_event || s.collapse_event) && !model.min_gap)
    throw InputError("creep run: lifetime events need a gap (actuation.gap)");
  if (s.collapse_event && !model.min_gap_rate)
    throw InputError("creep run: the collapse event needs the gap rate");
  const auto start = Clock::now();
  double wall_before = 0;  // wall time of the run before its restart
  auto wall = [&] {
    return wall_before + std::chrono::duration<double>(Clock::now() - start).count();
  };

  CreepRunResult r;
  std::size_t next = 0;  // index of the next output time
  if (restart != nullptr) {
    if (restart->settings_hash != s.settings_hash)
      throw InputError(fmt::format(
          "{}: checkpoint was written for other settings (hash {}, this case {}); restart with "
          "the case and options it was written for",
          checkpoint_file, restart->settings_hash, s.settings_hash));
    next = restore(*restart, checkpoint_file, model.series_columns.size(), r);
    wall_before = restart->numbers.count("wall_time_s") ? restart->numbers.at("wall_time_s") : 0;
    if (next == 0 || next > s.output_times.size() || r.final_time != s.output_times[next - 1])
      throw InputError(fmt::format("{}: checkpoint time {} is not an output time of this case",
                                   checkpoint_file, r.final_time));
    r.restarted = true;
    r.restart_time = r.final_time;
  } else {
    std::unique_ptr<CreepSystem> system = model.make_system();
    system->initial_state(0, r.state, r.state_dot);
    r.final_time = 0;
    record(model, *system, 0, r.state, r);
    if (model.min_gap && s.gap_threshold_event && model.min_gap(r.state) <= s.gap_threshold) {
      r.end = End::GapThreshold;  // closed elastically: no life at all
      r.lifetime = 0;
      return r;
    }
  }

  long steps_at_checkpoint = r.steps;
  double wall_at_checkpoint = wall();
  for (; next < s.output_times.size(); ++next) {
    const Real t_next = s.output_times[next];
    std::unique_ptr<CreepSystem> system = model.make_system();
    const SegmentEnd end = s.integration == CreepRunSettings::Integration::Implicit
                               ? implicit_segment(model, s, *system, t_next, r)
                               : explicit_segment(model, s, *system, t_next, r);
    ++r.segments;
    record(model, *system, r.final_time, r.state, r);
    if (model.on_segment) model.on_segment(r.final_time, r.last_step, r.steps);
    if (end.event) {
      r.end = end.kind;
      r.lifetime = r.final_time;
      return r;
    }
    const bool last = next + 1 == s.output_times.size();
    const bool due = (s.checkpoint_every_steps > 0 &&
                      r.steps - steps_at_checkpoint >= s.checkpoint_every_steps) ||
                     (s.checkpoint_every_seconds > 0 &&
                      wall() - wall_at_checkpoint >= s.checkpoint_every_seconds);
    if (!s.checkpoint_path.empty() && due && !last) {
      write_checkpoint(s.checkpoint_path, make_checkpoint(s, r, next + 1, wall()));
      ++r.checkpoints_written;
      steps_at_checkpoint = r.steps;
      wall_at_checkpoint = wall();
    }
  }
  return r;
}

}  // namespace rfmems

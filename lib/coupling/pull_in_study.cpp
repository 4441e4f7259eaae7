#include "coupling/pull_in_study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <functional>

#include "core/error.hpp"
#include "coupling/coupling_settings.hpp"
#include "coupling/laplace_pull_in.hpp"
#include "coupling/pull_in_results.hpp"
#include "physics/elasticity/elasticity_scene.hpp"

namespace rfmems {

PullInSettings read_pull_in_settings(const CaseNode& root, const SwitchScene& scene) {
  PullInSettings s;
  const CaseNode node = root.child("pull_in");
  const std::string mode = node.get_choice("mode", {"quasi_static", "dynamic", "transient"});
  s.dynamic = mode == "dynamic";
  s.transient = mode == "transient";
  s.coupling = read_coupling_options(root, scene, s.transient);
  const CaseNode qs = node.child_or_empty("quasi_static");
  s.quasi_static.n_points = static_cast<int>(qs.get_int("points", 40, Range::closed(4, 100000)));
  s.quasi_static.max_fraction = qs.get_real("max_fraction", 0.9, Range{0.0, 1.0, true, true});
  s.quasi_static.voltage_tolerance =
      qs.get_quantity("voltage_tolerance", Dimension::Voltage, 0.01, Range::positive());
  // IDA settings of every transient run (read here: the transient mode returns early).
  const CaseNode solver = root.child_or_empty("solver");
  s.run.ida.rtol = solver.get_real("rtol", 1e-3, Range::open(0.0, 1.0));
  // error_weights: scalar (atol on every unknown) or per_kind (coupling/state_tolerances.hpp:
  // atol on the displacements, velocity_frequency scales the velocities' atol,
  // docs/BENCHMARKS.md sec. 6e).
  const bool per_kind =
      solver.get_choice("error_weights", {"scalar", "per_kind"}, "scalar") == "per_kind";
  s.run.ida.atol = solver.get_quantity(
      "atol", Dimension::Length, (per_kind ? s.run.ida.rtol : 1e-4) * scene.gap, Range::positive());
  s.run.ida.max_order = static_cast<int>(solver.get_int("max_order", 2, Range::closed(1, 5)));
  s.run.ida.max_steps = 10000000;
  // IDA refreshes the Jacobian when c_j = alpha/h has moved by this fraction since the last
  // one (IDASetDeltaCjLSetup); 0 keeps IDA's 0.25 (docs/BENCHMARKS.md sec. 54).
  s.run.ida.jacobian_cj_change =
      solver.get_real("jacobian_refresh", 0.0, Range::closed(0.0, 1.0));
  if (per_kind) {
    s.run.tolerances = per_kind_tolerances(
        scene, s.run.ida.atol,
        2 * M_PI *
            solver.get_quantity("velocity_frequency", Dimension::Frequency, Range::positive()));
  } else {
    solver.require(!solver.has("velocity_frequency"), "velocity_frequency",
                   "only with error_weights: per_kind");
  }
  if (s.transient || node.has("transient")) {
    const CaseNode tr = node.child("transient");
    s.transient_voltage = tr.get_quantity("voltage", Dimension::Voltage, Range::positive());
    DynamicOptions& o = s.transient_run;
    o.end_time = tr.get_quantity("end_time", Dimension::Time, Range::positive());
    o.output_interval =
        tr.get_quantity("output_interval", Dimension::Time, o.end_time / 500, Range::positive());
    if (scene.contact.enabled()) {
      tr.require(!tr.has("contact_gap"), "contact_gap",
                 "with actuation.contact the touch-down is at actuation.contact.gap");
      o.contact_gap = scene.contact.gap;
    } else {
      o.contact_gap = tr.get_quantity("contact_gap", Dimension::Length, 0.02 * scene.gap,
                                      Range{0.0, scene.gap, false, true});
    }
    o.stop_at_turning = false;  // the whole history, to end_time or touch-down
    o.stop_at_contact = true;
    o.ida = s.run.ida;
    o.tolerances = s.run.tolerances;
  }
  // The dynamic settings are checked even when the mode does not use them (a case switched
  // between modes with --set keeps both sections valid).
  if (!s.dynamic && !node.has("dynamic")) return s;
  const CaseNode dyn = node.child("dynamic");
  s.run.end_time = dyn.get_quantity("end_time", Dimension::Time, Range::positive());
  if (scene.contact.enabled()) {
    dyn.require(!dyn.has("contact_gap"), "contact_gap",
                "with actuation.contact the touch-down is at actuation.contact.gap");
    s.run.contact_gap = scene.contact.gap;
  } else {
    s.run.contact_gap = dyn.get_quantity("contact_gap", Dimension::Length, 0.02 * scene.gap,
                                         Range{0.0, scene.gap, false, true});
  }
  s.run.output_interval = dyn.get_quantity("output_interval", Dimension::Time,
                                           s.run.end_time / 500, Range::positive());
  if (dyn.has("bracket")) {
    const std::vector<Real> b = dyn.get_quantities("bracket", Dimension::Voltage);
    dyn.require(b.size() == 2 && 0 <= b[0] && b[0] < b[1], "bracket",
                "expected [low, high] with 0 <= low < high");
    s.bracket_low = b[0];
    s.bracket_high = b[1];
  }
  s.tolerance = dyn.get_quantity("tolerance", Dimension::Voltage, 0.5, Range::positive());
  // A run that turns back (the control retreated from its extreme by turning_retreat of the
  // excursion, coupling/turning_back.hpp) has not pulled in. false: every bisection run goes
  // to touch-down or end_time.
  s.run.stop_at_turning = dyn.get_bool("stop_at_turning", true);
  s.run.turning_retreat =
      dyn.get_real("turning_retreat", kTurningRetreat, Range::open(0.0, 1.0));
  // With stop_at_turning, a run that has come to rest at a stable static equilibrium (velocity,
  // acceleration and film force below this fraction of their scales, on the quasi-static stable
  // branch; coupling/settled_at_rest.hpp) has not pulled in either. 0: off.
  s.run.settle_tolerance =
      dyn.get_real("settle_tolerance", kSettleTolerance, Range{0.0, 1.0, false, true});
  // With stop_at_turning, a run beyond the unstable equilibrium of its voltage by this fraction
  // of the fold's deflection, moving towards the electrode, has pulled in
  // (coupling/past_unstable_equilibrium.hpp).
  s.run.past_fold_margin =
      dyn.get_real("past_fold_margin", kPastFoldMargin, Range::closed(0.0, 1.0));
  if (dyn.has("voltages")) s.voltages = dyn.get_quantities("voltages", Dimension::Voltage);
  s.small_signal = dyn.get_real("small_signal", 0.3, Range{0.0, 0.9, false, false});
  s.time_check = dyn.get_real("time_check", 0.1, Range{0.0, 1.0, false, true});
  const bool laplace = scene.electrostatics == ElectrostaticsModel::Laplace;
  dyn.require(laplace || !dyn.has("laplace_coupling"), "laplace_coupling",
              "only with actuation.electrostatics: laplace");
  s.laplace_coupling =
      dyn.get_choice("laplace_coupling", {"staggered", "implicit"}, "staggered") == "implicit"
          ? LaplaceCoupling::Implicit
          : LaplaceCoupling::Staggered;
  if (dyn.has("waveform")) {
    const CaseNode w = dyn.child("waveform");
    const std::string type = w.get_choice("type", {"step", "ramp", "pulse"});
    s.waveform.kind = type == "step"   ? VoltageWaveform::Kind::Step
                      : type == "ramp" ? VoltageWaveform::Kind::Ramp
                                       : VoltageWaveform::Kind::Pulse;
    s.waveform.rise_time = w.get_quantity("rise_time", Dimension::Time,
                                          type == "ramp" ? -1.0 : 0.0, Range::non_negative());
    w.require(type != "ramp" || s.waveform.rise_time > 0, "rise_time", "a ramp needs rise_time > 0");
    w.require(!laplace || type == "step", "type",
              "the Laplace dynamic switch takes a step voltage only");
    if (type == "pulse") {
      s.waveform.release_time = w.get_quantity("release_time", Dimension::Time, Range::positive());
      s.waveform.hold_fraction = w.get_real("hold", 0.0, Range::closed(0.0, 1.0));
    }
  }

  if (node.has("release")) {
    const CaseNode r = node.child("release");
    if (!scene.contact.enabled())
      node.fail("release", "a release needs the contact model (actuation.contact)");
    s.release = true;
    ReleaseOptions& o = s.release_options;
    s.hold_voltage = r.get_quantity("hold_voltage", Dimension::Voltage, Range::non_negative());
    o.voltage = r.get_quantity("voltage", Dimension::Voltage, 0.0, Range::positive());
    r.require(!(r.has("delay") && r.has("time")), "time", "give either delay or time");
    o.delay = r.get_quantity("delay", Dimension::Time, 2e-6, Range::non_negative());
    o.drop_time = r.get_quantity("time", Dimension::Time, -1.0, Range::positive());
    o.window = r.get_quantity("window", Dimension::Time, 20e-6, Range::positive());
    o.lift = r.get_quantity("lift", Dimension::Length, 0.05 * scene.gap,
                            Range::open(0.0, scene.gap - scene.contact.gap));
    s.release_tolerance = r.get_quantity("tolerance", Dimension::Voltage, 0.5, Range::non_negative());
    if (r.has("bracket")) {
      const std::vector<Real> b = r.get_quantities("bracket", Dimension::Voltage);
      r.require(b.size() == 2 && 0 <= b[0] && b[0] < b[1], "bracket",
                "expected [low, high] with 0 <= low < high");
      s.release_bracket_low = b[0];
      s.release_bracket_high = b[1];
    }
    r.require(o.voltage == 0 || s.hold_voltage < o.voltage, "hold_voltage",
              "the hold must be below the voltage that pulls in");
  }

  return s;
}

namespace {

QuasiStaticPullIn quasi_static(SwitchScene& scene, const PullInSettings& settings,
                               long& laplace_solves) {
  if (scene.electrostatics == ElectrostaticsModel::ParallelPlate)
    return trace_pull_in(*scene.actuation, scene.control, settings.quasi_static);
  auto* beam = dynamic_cast<ElasticityScene*>(scene.structure.get());
  if (!beam) throw InputError("laplace electrostatics need a plane beam");
  LaplacePullInOptions options;
  options.sampling = settings.quasi_static;
  options.gap_cells = scene.laplace_gap_cells;
  const LaplacePullIn r = trace_pull_in_laplace(*beam, scene.facing_patch, scene.gap,
                                                scene.electrode, scene.control, options);
  laplace_solves = r.coupling_iterations;
  return r.result;
}

// One run of the dynamic study at a voltage with the given options (the scene's integrator).
using DynamicRunner = std::function<DynamicRun(Real voltage, const DynamicOptions& options)>;

// The pull-in time's integration error: the bisection's upper end once more to contact at
// time_check x the tolerances of `bisection` (its rules, no past-fold end, no samples). Near
// the fold t_PI amplifies IDA's local errors 10-100x (docs/BENCHMARKS.md 6e and 56), so rtol
// alone does not say how good the reported time is.
void check_pull_in_time(const DynamicRunner& run, const DynamicOptions& bisection,
                        const PullInSettings& settings, PullInReport& report) {
  if (settings.time_check <= 0 || report.dynamic.pull_in_time <= 0) return;
  DynamicOptions tight = with_tolerances_scaled(bisection, settings.time_check);
  tight.output_interval = 0;
  tight.stop_past_fold = false;
  report.time_check = run(report.dynamic.voltage, tight);
  report.time_check_factor = settings.time_check;
}

// Mode transient: the step voltage from rest by the case's coupling scheme.
void run_transient(SwitchScene& scene, const PullInSettings& settings, PullInReport& report) {
  const Real v = settings.transient_voltage;
  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  if (settings.coupling.scheme == CouplingScheme::Monolithic) {
    const std::unique_ptr<SwitchSystem> system = scene.make_transient_system();
    report.transient = run_dynamic(
        *system, scene.control, [v](Real) { return v; }, settings.transient_run);
  } else {
    std::vector<Index> w_dof;  // the plate's w over film cell c (the plate's unknowns 3c..3c+2)
    for (Index c = 0; c < scene.film->size(); ++c) w_dof.push_back(3 * c);
    PartitionedRun r = run_partitioned(
        *scene.actuation, scene.structure->quasi_static_components(), *scene.film, std::move(w_dof),
        scene.control, [v](Real) { return v; }, settings.transient_run, settings.coupling);
    report.transient = std::move(r.run);
    report.coupling_iterations = r.coupling_iterations;
    report.macro_steps = r.macro_steps;
  }
  report.transient_cpu_s = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  report.transient_wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  report.coupling = settings.coupling;
  report.has_transient = true;
}

// A laplace scene's dynamic study: the plane beam under the Laplace field recomputed per IDA
// step (laplace_dynamic_switch.hpp), bisection, histories and the small-signal response.
void run_laplace_dynamic(SwitchScene& scene, const PullInSettings& settings, ResultWriter& writer,
                         PullInReport& report) {
  auto* beam = dynamic_cast<ElasticityScene*>(scene.structure.get());
  if (!beam) throw InputError("laplace electrostatics need a plane beam");
  LaplaceGapOptions gap_options;
  gap_options.gap_cells = scene.laplace_gap_cells;
  LaplaceDynamicSwitch sw(*beam->op, scene.facing_patch, scene.gap, scene.electrode,
                          scene.control, gap_options);
  const QuasiStaticPullIn& qs = report.quasi_static;
  const Real low = settings.bracket_high > 0 ? settings.bracket_low : 0.8 * qs.pull_in_voltage;
  const Real high = settings.bracket_high > 0 ? settings.bracket_high : 1.02 * qs.pull_in_voltage;
  DynamicOptions quiet = settings.run;
  quiet.output_interval = 0;
  quiet.fold = FoldBranch::of(qs);  // the settle and past-fold rules
  DynamicOptions to_contact = quiet;
  to_contact.stop_past_fold = false;
  report.dynamic = find_dynamic_pull_in(
      [&](Real v) { return sw.run(v, quiet, settings.laplace_coupling); }, low, high,
      settings.tolerance, settings.run.end_time,
      [&](Real v) { return sw.run(v, to_contact, settings.laplace_coupling); });
  report.has_dynamic = true;
  check_pull_in_time(
      [&](Real v, const DynamicOptions& o) { return sw.run(v, o, settings.laplace_coupling); },
      quiet, settings, report);
  report.waveform = "step";
  report.dynamic_coupling = laplace_coupling_name(settings.laplace_coupling);
  DynamicOptions whole = settings.run;
  whole.stop_at_turning = false;  // the whole history up to end_time (or touch-down)
  std::vector<Real> voltages = settings.voltages;
  if (voltages.empty()) voltages = {0.97 * report.dynamic.voltage, 1.03 * report.dynamic.voltage};
  for (std::size_t k = 0; k < voltages.size(); ++k) {
    DynamicRun run = sw.run(voltages[k], whole, settings.laplace_coupling);
    write_dynamic_history(writer, fmt::format("V{}", k), run);
    report.histories.emplace_back(voltages[k], std::move(run));
  }
  if (settings.small_signal > 0) {
    const Real v = settings.small_signal * qs.pull_in_voltage;
    const DynamicRun run = sw.run(v, whole, settings.laplace_coupling);
    write_dynamic_history(writer, "small_signal", run);
    report.small_signal_voltage = v;
    report.small_signal = free_response(run.history);
  }
  report.dynamic_laplace_solves = sw.times().field_solves;
}

}  // namespace

PullInReport run_pull_in_study(SwitchScene& scene, const PullInSettings& settings,
                               ResultWriter& writer) {
  PullInReport report;
  StructuralModel& model = *scene.structure;
  const Index n = model.structure().size();
  if (settings.transient) {
    run_transient(scene, settings, report);
    const DynamicState& end = report.transient.final_state;
    if (end.y.size() >= static_cast<std::size_t>(n))
      model.write_fields(writer, 0, end.t, std::vector<Real>(end.y.begin(), end.y.begin() + n), {});
    write_dynamic_history(writer, "transient", report.transient);
    report.histories.emplace_back(settings.transient_voltage, report.transient);  // validity
    return report;
  }

  report.quasi_static = quasi_static(scene, settings, report.laplace_solves);
  const QuasiStaticPullIn& qs = report.quasi_static;
  std::vector<Real> fold(qs.fold_state.begin(), qs.fold_state.begin() + n);
  model.write_fields(writer, 0, 0.0, fold, {});
  write_pull_in_curve(writer, qs);
  if (!settings.dynamic) return report;

  if (scene.electrostatics == ElectrostaticsModel::Laplace) {
    run_laplace_dynamic(scene, settings, writer, report);
    return report;
  }
  const std::unique_ptr<SwitchSystem> transient = scene.make_transient_system();
  SwitchSystem& system = *transient;
  const Real low = settings.bracket_high > 0 ? settings.bracket_low : 0.8 * qs.pull_in_voltage;
  const Real high = settings.bracket_high > 0 ? settings.bracket_high : 1.02 * qs.pull_in_voltage;
  DynamicOptions bisection = settings.run;
  bisection.fold = FoldBranch::of(qs);  // the settle and past-fold rules
  report.dynamic = find_dynamic_pull_in(system, scene.control, low, high, settings.tolerance,
                                        bisection, settings.waveform);
  report.has_dynamic = true;
  check_pull_in_time(
      [&](Real v, const DynamicOptions& o) {
        return run_dynamic(system, scene.control, settings.waveform.at(v), o);
      },
      bisection, settings, report);
  static const char* names[] = {"step", "ramp", "pulse"};
  report.waveform = names[static_cast<int>(settings.waveform.kind)];
  std::vector<Real> voltages = settings.voltages;
  if (voltages.empty()) voltages = {0.97 * report.dynamic.voltage, 1.03 * report.dynamic.voltage};
  for (std::size_t k = 0; k < voltages.size(); ++k) {
    const Real v = voltages[k];
    DynamicRun run = run_dynamic(system, scene.control, settings.waveform.at(v), [&] {
      DynamicOptions o = settings.run;
      o.stop_at_turning = false;  // the whole history up to end_time (or touch-down)
      o.stop_at_contact = !scene.contact.enabled();  // with contact: resting on the dielectric
      return o;
    }());
    write_dynamic_history(writer, fmt::format("V{}", k), run);
    report.histories.emplace_back(v, std::move(run));
  }
  if (settings.small_signal > 0) {
    const Real v = settings.small_signal * qs.pull_in_voltage;
    DynamicOptions o = settings.run;
    o.stop_at_turning = false;
    const DynamicRun run = run_dynamic(system, scene.control, [v](Real) { return v; }, o);
    write_dynamic_history(writer, "small_signal", run);
    report.small_signal_voltage = v;
    report.small_signal = free_response(run.history);
  }
  if (settings.release) {
    ReleaseOptions r = settings.release_options;
    if (r.voltage == 0) r.voltage = 1.03 * report.dynamic.voltage;
    if (settings.hold_voltage >= r.voltage)
      throw InputError(fmt::format("pull_in.release.hold_voltage = {:.4g} V must be below the "
                                   "voltage that pulls in ({:.4g} V)",
                                   settings.hold_voltage, r.voltage));
    report.release_voltage = r.voltage;
    report.hold_voltage = settings.hold_voltage;
    report.approach = approach_contact(system, scene.control, settings.run, r);
    // The quasi-static pull-out: the contact equilibrium from the pulled-in state down.
    PullOutOptions po;
    po.start_voltage = r.voltage;
    po.voltage_tolerance = settings.quasi_static.voltage_tolerance;
    report.pull_out = trace_pull_out(*scene.actuation, scene.control, report.approach.drop.y, po);
    report.has_pull_out = true;
    std::vector<Real> v;
    std::vector<std::vector<double>> branch;
    for (auto it = report.pull_out.branch.rbegin(); it != report.pull_out.branch.rend(); ++it) {
      v.push_back(it->voltage);
      branch.push_back({it->control, it->min_gap, it->contact_fraction});
    }
    writer.write_time_series("pull_in", "contact_branch", v, branch,
                             {"control", "min_gap", "contact_fraction"}, "voltage");
    report.hold = run_hold(system, scene.control, report.approach.drop, settings.hold_voltage,
                           settings.run, r);
    DynamicRun both = report.approach.run;
    both.history.insert(both.history.end(), report.hold.history.begin(), report.hold.history.end());
    write_dynamic_history(writer, "release", both);
    report.has_release = true;
    if (settings.release_tolerance > 0) {
      // Default high end: the voltage that pulled in (holds: no drop). The dynamic pull-out
      // can be several times the quasi-static one (the plate switch from 180 V: 5-6x,
      // docs/BENCHMARKS.md section 28), so twice the static one is no bracket.
      const Real high =
          settings.release_bracket_high > 0 ? settings.release_bracket_high : r.voltage;
      report.dynamic_pull_out = find_dynamic_pull_out(
          system, scene.control, report.approach.drop, settings.release_bracket_low, high,
          settings.release_tolerance, settings.run, r);
      report.has_dynamic_pull_out = true;
    }
  }
  return report;
}

Json pull_in_summary(const SwitchScene& scene, const PullInReport& report) {
  Json j;
  const QuasiStaticPullIn& qs = report.quasi_static;
  j["electrostatics"] = scene.electrostatics == ElectrostaticsModel::Laplace ? "laplace" : "parallel_plate";
  j["gap"] = scene.gap;
  if (report.has_transient) {
    const DynamicRun& r = report.transient;
    const Real v = report.histories.empty() ? 0.0 : report.histories.front().first;
    j["transient"] = {{"voltage", v},
                      {"gas", scene.film ? "reynolds" : "none"},
                      {"final_time", r.final_time},
                      {"final_control", r.history.empty() ? 0.0 : r.history.back().control},
                      {"extreme_control", r.extreme_control},
                      {"pulled_in", r.pulled_in},
                      {"pull_in_time", r.pull_in_time},
                      {"samples", r.history.size()},
                      {"steps", r.stats.steps},
                      {"residual_evals", r.stats.residual_evals},
                      {"newton_iterations", r.stats.newton_iters},
                      {"wall_time_s", report.transient_wall_s},
                      {"cpu_time_s", report.transient_cpu_s}};
    return j;
  }
  j["quasi_static"] = {{"pull_in_voltage", qs.pull_in_voltage},
                       {"pull_in_displacement", qs.pull_in_displacement},
                       {"pull_in_fraction_of_gap", -qs.pull_in_displacement / scene.gap},
                       {"curve_points", qs.curve.size()},
                       {"solves", qs.solves},
                       {"newton_iterations", qs.newton_iterations}};
  if (report.laplace_solves > 0) j["quasi_static"]["laplace_solves"] = report.laplace_solves;
  if (report.has_pull_out) {
    const QuasiStaticPullOut& po = report.pull_out;
    j["contact"] = {{"gap", scene.contact.gap}, {"penetration", scene.contact.penetration}};
    j["quasi_static"]["pull_out_voltage"] = po.pull_out_voltage;
    j["quasi_static"]["pull_out"] = {{"voltage", po.pull_out_voltage},
                                     {"released_voltage", po.released_voltage},
                                     {"contact_fraction", po.branch.back().contact_fraction},
                                     {"branch_points", po.branch.size()},
                                     {"solves", po.solves},
                                     {"newton_iterations", po.newton_iterations}};
  }
  if (report.has_dynamic) {
    const DynamicPullIn& d = report.dynamic;
    // null: the upper end (past the unstable equilibrium) did not touch down by end_time.
    j["dynamic"] = {{"pull_in_voltage", d.voltage},
                    {"not_pulling_in", d.lower},
                    {"pull_in_time", d.pull_in_time > 0 ? Json(d.pull_in_time) : Json()},
                    {"upper_past_fold", d.upper_past_fold},
                    {"ratio_to_quasi_static", d.voltage / qs.pull_in_voltage},
                    {"runs", d.runs},
                    {"settled_runs", d.settled_runs},
                    {"past_fold_runs", d.past_fold_runs},
                    {"steps", d.steps},
                    {"residual_evals", d.residual_evals},
                    {"electrostatics",
                     report.dynamic_coupling.empty() ? "parallel_plate" : "laplace"},
                    {"gas", scene.film ? "reynolds" : "none"},
                    {"waveform", report.waveform}};
    Json histories = Json::array();
    for (const auto& [v, run] : report.histories)
      histories.push_back({{"voltage", v},
                           {"pulled_in", run.pulled_in},
                           {"pull_in_time", run.pull_in_time},
                           {"extreme_control", run.extreme_control},
                           {"steps", run.stats.steps}});
    j["dynamic"]["histories"] = histories;
    if (report.time_check_factor > 0)
      j["dynamic"]["pull_in_time_check"] =
          pull_in_time_check_json(report.time_check_factor, d.pull_in_time, report.time_check);
    if (!report.dynamic_coupling.empty()) {
      j["dynamic"]["laplace_coupling"] = report.dynamic_coupling;
      j["dynamic"]["laplace_solves"] = report.dynamic_laplace_solves;
    }
    if (report.has_release) {
      const DynamicRun& a = report.approach.run;
      const DynamicRun& h = report.hold;
      Json r = {{"voltage", report.release_voltage},
                {"hold_voltage", report.hold_voltage},
                {"pull_in_time", a.pull_in_time},
                {"drop_time", report.approach.drop.t},
                {"released", h.released},
                {"release_time", h.released ? h.release_time - report.approach.drop.t : 0.0},
                {"steps", a.stats.steps + h.stats.steps}};
      if (report.has_dynamic_pull_out) {
        const DynamicPullOut& d = report.dynamic_pull_out;
        r["pull_out_voltage"] = d.voltage;
        r["releasing"] = d.released;
        r["release_time_at_releasing"] = d.release_time;
        r["runs"] = d.runs;
        r["ratio_to_quasi_static"] = d.voltage / report.pull_out.pull_out_voltage;
      }
      j["dynamic"]["release"] = r;
    }
    if (report.small_signal_voltage > 0) {
      j["dynamic"]["small_signal"] = free_response_json(report.small_signal);
      j["dynamic"]["small_signal"]["voltage"] = report.small_signal_voltage;
    }
  }
  return j;
}

}  // namespace rfmems

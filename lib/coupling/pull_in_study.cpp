#include "coupling/pull_in_study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <ctime>
#include <functional>

#include "core/error.hpp"
#include "coupling/pull_in_results.hpp"
#include "io/case_schema_yaml.hpp"
#include "io/frequency_sweep.hpp"

namespace rfmems {

namespace {

// [low, high] of a bracket key, with 0 <= low < high.
std::pair<Real, Real> read_bracket(const CaseNode& node) {
  const std::vector<Real> b = node.get_quantities("bracket", Dimension::Voltage);
  node.require(b.size() == 2 && 0 <= b[0] && b[0] < b[1], "bracket",
               "expected [low, high] with 0 <= low < high");
  return {b[0], b[1]};
}

// A key the active mode requires, else read with a placeholder default (checked if present).
Real mode_quantity(const CaseNode& node, const std::string& key, Dimension d, bool required) {
  return required ? node.get_quantity(key, d, Range::positive())
                  : node.get_quantity(key, d, 1.0, Range::positive());
}

// solver: IDA's settings of every run.
void read_solver(const CaseNode& root, const SwitchScene& scene, DynamicOptions& o) {
  const CaseNode solver = root.child_or_empty("solver");
  o.ida.rtol = solver.get_real("rtol", 1e-3, Range::open(0.0, 1.0));
  // error_weights: scalar (atol on every unknown) or per_kind (coupling/state_tolerances.hpp:
  // atol on the displacements, velocity_frequency scales the velocities' atol).
  const bool per_kind =
      solver.get_choice("error_weights", {"scalar", "per_kind"}, "scalar") == "per_kind";
  solver.require(!per_kind || scene.field() != FieldModel::Immersed, "error_weights",
                 "the immersed field weights the velocities by its first bending period");
  o.ida.atol = solver.get_quantity("atol", Dimension::Length,
                                   (per_kind ? o.ida.rtol : 1e-4) * scene.gap, Range::positive());
  o.ida.max_order = static_cast<int>(solver.get_int("max_order", 2, Range::closed(1, 5)));
  o.ida.max_steps = 10000000;
  // IDA refreshes the Jacobian when c_j = alpha/h has moved by this fraction since the last
  // one (IDASetDeltaCjLSetup); 0 keeps IDA's 0.25.
  o.ida.jacobian_cj_change = solver.get_real("jacobian_refresh", 0.0, Range::closed(0.0, 1.0));
  // Fixed steps (the coupling schemes' splitting error at a given step): cut to 1e-4 of it
  // only after a failed Newton solve (the 1/g^2 touch-down).
  o.ida.fixed_step = solver.get_quantity("fixed_step", Dimension::Time, 0.0, Range::non_negative());
  o.ida.fixed_step_min = 1e-4 * o.ida.fixed_step;
  if (per_kind) {
    o.tolerances = per_kind_tolerances(
        scene, o.ida.atol,
        2 * M_PI *
            solver.get_quantity("velocity_frequency", Dimension::Frequency, Range::positive()));
  } else {
    solver.require(!solver.has("velocity_frequency"), "velocity_frequency",
                   "only with error_weights: per_kind");
  }
}

}  // namespace

PullInSettings read_pull_in_settings(const CaseNode& root, const SwitchScene& scene) {
  PullInSettings s;
  s.analysis = scene.choice.analysis;
  const CaseNode node = root.child("pull_in");
  // Every block is checked whatever the mode (a case toggled by --set stays valid); the
  // active mode's block and required keys must be there.
  auto block = [&](Analysis a) {
    return s.analysis == a ? node.child(analysis_name(a)) : node.child_or_empty(analysis_name(a));
  };
  DynamicOptions base;
  read_solver(root, scene, base);
  base.coupling = read_coupling_options(root, scene.choice);
  // The touch-down gap of every run.
  if (scene.contact().enabled()) {
    node.require(!node.has("contact_gap"), "contact_gap",
                 "with actuation.contact the touch-down is at actuation.contact.gap");
    base.contact_gap = scene.contact().gap;
  } else {
    base.contact_gap = node.get_quantity("contact_gap", Dimension::Length,
                                         std::max(0.02 * scene.gap, scene.resolvable_gap()),
                                         Range{0.0, scene.gap, false, true});
  }

  const CaseNode st = block(Analysis::Static);
  s.static_voltage =
      mode_quantity(st, "voltage", Dimension::Voltage, s.analysis == Analysis::Static);

  const CaseNode qs = block(Analysis::QuasiStatic);
  s.quasi_static.n_points = static_cast<int>(qs.get_int("points", 40, Range::closed(4, 100000)));
  s.quasi_static.max_fraction = qs.get_real("max_fraction", 0.9, Range{0.0, 1.0, true, false});
  s.quasi_static.voltage_tolerance =
      qs.get_quantity("voltage_tolerance", Dimension::Voltage, 0.01, Range::positive());
  s.quasi_static.newton_tolerance =
      qs.get_real("newton_tolerance", 0.0, Range{0.0, 1e-2, false, true});
  s.bias_modes = qs.get_int("modes", 0, Range::closed(0, 1000));
  if (s.bias_modes > 0) {
    qs.require(scene.field() == FieldModel::ParallelPlate, "modes",
               "the modes under bias need actuation.electrostatics parallel_plate");
    const Index most = max_shift_invert_modes(modal_mass(*scene.structure));
    qs.require(
        s.bias_modes <= most, "modes",
        fmt::format("the structure has {} modes to give (its unknowns with inertia less 2)", most));
  }

  const CaseNode tr = block(Analysis::Transient);
  const bool transient = s.analysis == Analysis::Transient;
  s.transient_voltage = mode_quantity(tr, "voltage", Dimension::Voltage, transient);
  DynamicOptions& t = s.transient_run;
  t = base;
  t.end_time = mode_quantity(tr, "end_time", Dimension::Time, transient);
  t.output_interval =
      tr.get_quantity("output_interval", Dimension::Time, t.end_time / 500, Range::positive());
  t.stop_at_turning = false;  // the whole history, to end_time or touch-down
  t.stop_at_contact = true;

  const CaseNode dyn = block(Analysis::Dynamic);
  const bool dynamic = s.analysis == Analysis::Dynamic;
  DynamicOptions& o = s.run;
  o = base;
  o.end_time = mode_quantity(dyn, "end_time", Dimension::Time, dynamic);
  o.output_interval =
      dyn.get_quantity("output_interval", Dimension::Time, o.end_time / 500, Range::positive());
  if (dyn.has("bracket")) std::tie(s.bracket_low, s.bracket_high) = read_bracket(dyn);
  // 0: kRelativeBisectionTolerance x the quasi-static V_PI (traced first).
  s.tolerance = dyn.get_quantity("tolerance", Dimension::Voltage, 0.0, Range::positive());
  // A run that turns back (the control retreated from its extreme by turning_retreat of the
  // excursion, coupling/turning_back.hpp) has not pulled in. false: every bisection run goes
  // to touch-down or end_time.
  o.stop_at_turning = dyn.get_bool("stop_at_turning", true);
  o.turning_retreat = dyn.get_real("turning_retreat", kTurningRetreat, Range::open(0.0, 1.0));
  // With stop_at_turning, a run that has come to rest at a stable static equilibrium (velocity,
  // acceleration and gas force below this fraction of their scales, on the quasi-static stable
  // branch; coupling/settled_at_rest.hpp) has not pulled in either. 0: off.
  o.settle_tolerance =
      dyn.get_real("settle_tolerance", kSettleTolerance, Range{0.0, 1.0, false, true});
  // With stop_at_turning, a run beyond the unstable equilibrium of its voltage by this fraction
  // of the fold's deflection, moving towards the electrode, has pulled in
  // (coupling/past_unstable_equilibrium.hpp).
  o.past_fold_margin = dyn.get_real("past_fold_margin", kPastFoldMargin, Range::closed(0.0, 1.0));
  if (dyn.has("voltages")) {
    s.voltages = dyn.get_quantities("voltages", Dimension::Voltage);
    s.histories = !s.voltages.empty();
  }
  s.small_signal = dyn.get_real("small_signal", 0.3, Range{0.0, 0.9, false, false});
  // The check costs one more coupled run at the tighter tolerance: with the kinetic gas one of
  // 10-40 min, so off there unless the case asks.
  s.time_check = dyn.get_real("time_check", scene.gas() == GasModel::Esbgk ? 0.0 : 0.1,
                              Range{0.0, 1.0, false, true});
  if (dyn.has("waveform")) {
    const CaseNode w = dyn.child("waveform");
    const std::string type = w.get_choice("type", {"step", "ramp", "pulse"});
    w.require(type == "step" || scene.field() == FieldModel::ParallelPlate, "type",
              "the " + field_name(scene.field()) + " field takes a step voltage only");
    w.require(type == "step" || scene.choice.scheme == CouplingScheme::Monolithic, "type",
              "a partitioned scheme takes a step voltage only (a ramp or pulse: coupling.scheme: "
              "monolithic)");
    s.waveform.kind = type == "step"   ? VoltageWaveform::Kind::Step
                      : type == "ramp" ? VoltageWaveform::Kind::Ramp
                                       : VoltageWaveform::Kind::Pulse;
    s.waveform.rise_time = w.get_quantity("rise_time", Dimension::Time, type == "ramp" ? -1.0 : 0.0,
                                          Range::non_negative());
    w.require(type != "ramp" || s.waveform.rise_time > 0, "rise_time",
              "a ramp needs rise_time > 0");
    if (type == "pulse") {
      s.waveform.release_time = w.get_quantity("release_time", Dimension::Time, Range::positive());
      s.waveform.hold_fraction = w.get_real("hold", 0.0, Range::closed(0.0, 1.0));
    }
  }

  const CaseNode harmonic = block(Analysis::Harmonic);
  const bool is_harmonic = s.analysis == Analysis::Harmonic;
  s.harmonic_bias = mode_quantity(harmonic, "bias", Dimension::Voltage, is_harmonic);
  if (is_harmonic || harmonic.has("frequencies") || harmonic.has("sweep"))
    s.harmonic_frequencies = read_frequency_sweep(harmonic);
  s.reject_bias = [harmonic](const std::string& what) { harmonic.fail("bias", what); };

  if (node.has("release")) {
    const CaseNode r = node.child("release");
    if (!scene.contact().enabled())
      node.fail("release", "a release needs the contact model (actuation.contact)");
    node.require(scene.choice.scheme == CouplingScheme::Monolithic, "release",
                 "the release runs the monolithic system (coupling.scheme: monolithic)");
    s.release = true;
    ReleaseOptions& ro = s.release_options;
    s.hold_voltage = r.get_quantity("hold_voltage", Dimension::Voltage, Range::non_negative());
    ro.voltage = r.get_quantity("voltage", Dimension::Voltage, 0.0, Range::positive());
    r.require(!(r.has("delay") && r.has("time")), "time", "give either delay or time");
    ro.delay = r.get_quantity("delay", Dimension::Time, 2e-6, Range::non_negative());
    ro.drop_time = r.get_quantity("time", Dimension::Time, -1.0, Range::positive());
    ro.window = r.get_quantity("window", Dimension::Time, 20e-6, Range::positive());
    ro.lift = r.get_quantity("lift", Dimension::Length, 0.05 * scene.gap,
                             Range::open(0.0, scene.gap - scene.contact().gap));
    s.release_tolerance =
        r.get_quantity("tolerance", Dimension::Voltage, 0.5, Range::non_negative());
    if (r.has("bracket")) std::tie(s.release_bracket_low, s.release_bracket_high) = read_bracket(r);
    r.require(ro.voltage == 0 || s.hold_voltage < ro.voltage, "hold_voltage",
              "the hold must be below the voltage that pulls in");
  }
  return s;
}

namespace {

// A run of the study on the progress stream (null: none): what it was, its voltage, how it
// ended, and the study's wall time so far.
class StudyProgress {
 public:
  explicit StudyProgress(std::FILE* out) : out_(out), start_(std::chrono::steady_clock::now()) {}
  void run(const std::string& what, Real voltage, const DynamicRun& r) const {
    if (!out_) return;
    std::string end = fmt::format("ran to {:.4g} us", 1e6 * r.final_time);
    if (r.pulled_in)
      end = r.past_fold ? "pulled in (past the unstable equilibrium)"
                        : fmt::format("pulled in at {:.4g} us", 1e6 * r.pull_in_time);
    else if (r.settled)
      end = "settled";
    else if (r.turning_time > 0)
      end += fmt::format(" (turned back at {:.4g} us)", 1e6 * r.turning_time);
    std::fprintf(out_, "rfmems-pullin: %s at %.4f V: %s, %ld steps (%.1f s)\n", what.c_str(),
                 voltage, end.c_str(), r.stats.steps,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
    std::fflush(out_);
  }

 private:
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_;
};

// The pull-in time's integration error: the bisection's upper end once more to contact at
// time_check x the tolerances of `bisection` (its rules, no past-fold end, no samples). Near
// the fold t_PI amplifies IDA's local errors 10-100x, so rtol alone does not say how good the
// reported time is.
void check_pull_in_time(CouplingManager& manager, const DynamicOptions& bisection,
                        const PullInSettings& settings, const StudyProgress& progress,
                        PullInReport& report) {
  if (settings.time_check <= 0 || report.dynamic.pull_in_time <= 0) return;
  DynamicOptions tight = with_tolerances_scaled(bisection, settings.time_check);
  tight.output_interval = 0;
  tight.stop_past_fold = false;
  report.time_check = manager.run(settings.waveform, report.dynamic.voltage, tight);
  report.time_check_factor = settings.time_check;
  progress.run("dynamic: the pull-in time's check", report.dynamic.voltage, report.time_check);
}

// The structure's unknowns of a state whose structure leads.
std::vector<Real> structure_part(const SwitchScene& scene, std::span<const Real> y) {
  const std::size_t n = static_cast<std::size_t>(scene.structure->structure().size());
  return std::vector<Real>(y.begin(),
                           y.begin() + static_cast<std::ptrdiff_t>(std::min(n, y.size())));
}

// The forces of a run are the structure's: a plate's whole (N), a plane beam's per depth (N/m).
std::string force_units(const SwitchScene& scene) {
  return scene.structure->kind() == "plate" ? "N" : "N/m";
}

void run_transient(SwitchScene& scene, CouplingManager& manager, const PullInSettings& settings,
                   ResultWriter& writer, PullInReport& report) {
  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  report.transient =
      manager.run(VoltageWaveform{}, settings.transient_voltage, settings.transient_run);
  report.transient_cpu_s = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  report.transient_wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  report.has_transient = true;
  const DynamicState& end = report.transient.final_state;
  if (!end.y.empty())
    scene.structure->write_fields(writer, 0, end.t, structure_part(scene, end.y), {});
  write_dynamic_history(writer, "transient", report.transient, force_units(scene));
  report.histories.emplace_back(settings.transient_voltage, report.transient);  // validity
}

// With contact: the step that pulls in, the drop to the hold voltage, the quasi-static pull-out
// on the contact branch and the dynamic pull-out by bisection on the hold.
void run_release(SwitchScene& scene, SwitchSystem& system, const PullInSettings& settings,
                 ResultWriter& writer, PullInReport& report) {
  ReleaseOptions r = settings.release_options;
  if (r.voltage == 0) r.voltage = 1.03 * report.dynamic.voltage;
  if (settings.hold_voltage >= r.voltage)
    throw InputError(
        fmt::format("pull_in.release.hold_voltage = {:.4g} V must be below the "
                    "voltage that pulls in ({:.4g} V)",
                    settings.hold_voltage, r.voltage));
  report.release_voltage = r.voltage;
  report.hold_voltage = settings.hold_voltage;
  report.approach = approach_contact(system, scene.control, settings.run, r);
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
  report.hold =
      run_hold(system, scene.control, report.approach.drop, settings.hold_voltage, settings.run, r);
  DynamicRun both = report.approach.run;
  both.history.insert(both.history.end(), report.hold.history.begin(), report.hold.history.end());
  write_dynamic_history(writer, "release", both, force_units(scene));
  report.has_release = true;
  if (settings.release_tolerance > 0) {
    // Default high end: the voltage that pulled in (holds: no drop). The dynamic pull-out can
    // be several times the quasi-static one (the plate switch from 180 V: 5-6x), so twice the
    // static one is no bracket.
    const Real high = settings.release_bracket_high > 0 ? settings.release_bracket_high : r.voltage;
    report.dynamic_pull_out = find_dynamic_pull_out(system, scene.control, report.approach.drop,
                                                    settings.release_bracket_low, high,
                                                    settings.release_tolerance, settings.run, r);
    report.has_dynamic_pull_out = true;
  }
}

void run_dynamic_study(SwitchScene& scene, CouplingManager& manager, const PullInSettings& settings,
                       ResultWriter& writer, PullInReport& report) {
  const QuasiStaticPullIn& qs = report.quasi_static;
  const StudyProgress progress(settings.progress);
  const Real low = settings.bracket_high > 0 ? settings.bracket_low : 0.8 * qs.pull_in_voltage;
  const Real high = settings.bracket_high > 0 ? settings.bracket_high : 1.02 * qs.pull_in_voltage;
  report.tolerance = settings.tolerance > 0 ? settings.tolerance
                                            : kRelativeBisectionTolerance * qs.pull_in_voltage;
  const VoltageWaveform& waveform = settings.waveform;
  DynamicOptions bisection = settings.run;
  bisection.output_interval = 0;
  bisection.fold = FoldBranch::of(qs);  // the settle and past-fold rules
  // A pulse's drop can release a structure that was past the unstable equilibrium of its step.
  bisection.stop_past_fold =
      settings.run.stop_past_fold && waveform.kind != VoltageWaveform::Kind::Pulse;
  DynamicOptions to_contact = bisection;
  to_contact.stop_past_fold = false;
  // Each bisection run, logged as it ends.
  auto logged = [&](const DynamicOptions& o, const std::string& what) {
    return [&, what](Real v) {
      DynamicRun r = manager.run(waveform, v, o);
      progress.run(what, v, r);
      return r;
    };
  };
  report.dynamic = find_dynamic_pull_in(logged(bisection, "dynamic: bisection run"), low, high,
                                        report.tolerance, settings.run.end_time,
                                        logged(to_contact, "dynamic: the upper end to contact"));
  report.has_dynamic = true;
  check_pull_in_time(manager, bisection, settings, progress, report);
  static const char* names[] = {"step", "ramp", "pulse"};
  report.waveform = names[static_cast<int>(waveform.kind)];

  DynamicOptions whole = settings.run;
  whole.stop_at_turning = false;                       // the whole history to end_time
  whole.stop_at_contact = !scene.contact().enabled();  // with contact: resting on the dielectric
  std::vector<Real> voltages = settings.voltages;
  if (settings.histories && voltages.empty())
    voltages = {0.97 * report.dynamic.voltage, 1.03 * report.dynamic.voltage};
  for (std::size_t k = 0; k < voltages.size(); ++k) {
    DynamicRun run = manager.run(waveform, voltages[k], whole);
    progress.run("dynamic: history", voltages[k], run);
    write_dynamic_history(writer, fmt::format("V{}", k), run, force_units(scene));
    report.histories.emplace_back(voltages[k], std::move(run));
  }
  if (settings.small_signal > 0) {
    const Real v = settings.small_signal * qs.pull_in_voltage;
    DynamicOptions o = settings.run;
    o.stop_at_turning = false;
    const DynamicRun run = manager.run(VoltageWaveform{}, v, o);
    progress.run("dynamic: small signal", v, run);
    write_dynamic_history(writer, "small_signal", run, force_units(scene));
    report.small_signal_voltage = v;
    report.small_signal = free_response(run.history);
  }
  if (settings.release) run_release(scene, *manager.switch_system(), settings, writer, report);
}

}  // namespace

PullInReport run_pull_in_study(SwitchScene& scene, const PullInSettings& settings,
                               ResultWriter& writer) {
  PullInReport report;
  const std::unique_ptr<CouplingManager> manager = make_coupling_manager(scene);
  switch (settings.analysis) {
    case Analysis::Transient:
      run_transient(scene, *manager, settings, writer, report);
      break;
    case Analysis::Static:
      report.static_voltage = settings.static_voltage;
      report.static_state = manager->solve_static(settings.static_voltage);
      report.has_static = true;
      scene.structure->write_fields(writer, 0, 0.0, report.static_state.u, {});
      break;
    case Analysis::Harmonic: {
      report.quasi_static = manager->quasi_static(settings.quasi_static);
      report.has_quasi_static = true;
      write_pull_in_curve(writer, report.quasi_static);
      if (settings.harmonic_bias >= report.quasi_static.pull_in_voltage)
        settings.reject_bias(fmt::format(
            "not below the quasi-static pull-in voltage {:.6g} V: no equilibrium to linearise "
            "about",
            report.quasi_static.pull_in_voltage));
      const std::vector<Real> state =
          equilibrium_at_voltage(*scene.actuation, scene.control, report.quasi_static,
                                 settings.harmonic_bias, settings.quasi_static);
      scene.structure->write_fields(writer, 0, 0.0, state, {});
      const std::vector<Index> film = film_unknowns(scene);
      report.harmonic =
          harmonic_under_bias(*manager->switch_system(), scene.control, settings.harmonic_bias,
                              state, settings.harmonic_frequencies, scene.film.get(), film);
      report.has_harmonic = true;
      write_harmonic_under_bias(writer, report.harmonic);
      break;
    }
    case Analysis::QuasiStatic:
    case Analysis::Dynamic: {
      report.quasi_static = manager->quasi_static(settings.quasi_static);
      report.has_quasi_static = true;
      if (settings.progress)
        std::fprintf(settings.progress,
                     "rfmems-pullin: quasi-static: fold at %.4f V (%ld solves)\n",
                     report.quasi_static.pull_in_voltage, report.quasi_static.solves);
      scene.structure->write_fields(writer, 0, 0.0,
                                    structure_part(scene, report.quasi_static.fold_state), {});
      write_pull_in_curve(writer, report.quasi_static);
      if (settings.bias_modes > 0) {
        report.bias_modes = modes_along_curve(*scene.actuation, scene.control, report.quasi_static,
                                              modal_mass(*scene.structure), settings.bias_modes,
                                              settings.quasi_static);
        write_bias_modes(writer, report.bias_modes);
      }
      if (settings.analysis == Analysis::Dynamic)
        run_dynamic_study(scene, *manager, settings, writer, report);
      break;
    }
  }
  report.counters = manager->counters();
  report.contact_gap = settings.analysis == Analysis::Transient ? settings.transient_run.contact_gap
                                                                : settings.run.contact_gap;
  return report;
}

namespace {

Json run_json(const DynamicRun& r) {
  return {{"pulled_in", r.pulled_in},
          {"pull_in_time", r.pulled_in && r.pull_in_time > 0 ? Json(r.pull_in_time) : Json()},
          {"final_time", r.final_time},
          {"final_control", r.history.empty() ? 0.0 : r.history.back().control},
          {"extreme_control", r.extreme_control},
          {"samples", r.history.size()},
          {"steps", r.stats.steps},
          {"residual_evals", r.stats.residual_evals},
          {"newton_iterations", r.stats.newton_iters}};
}

// Amplitudes and phases [deg] of complex amplitudes.
Json amplitude_phase(const std::vector<std::complex<Real>>& values, const std::string& units) {
  Json amplitude = Json::array(), phase = Json::array();
  for (const std::complex<Real>& z : values) {
    amplitude.push_back(std::abs(z));
    phase.push_back(std::arg(z) * 180 / M_PI);
  }
  return {{"amplitude", amplitude}, {"phase_deg", phase}, {"units", units}};
}

Json harmonic_json(const HarmonicUnderBias& h) {
  Json j = {{"bias", h.bias},
            {"static_control", h.static_control},
            {"frequencies", h.frequencies},
            {"control", amplitude_phase(h.control, "m/V")},
            {"factorizations", h.factorizations},
            {"refactorizations", h.refactorizations},
            {"solve_cpu_s", h.solve_cpu_s}};
  // The sweep's largest control response (a resonance, when the sweep brackets it).
  std::size_t peak = 0;
  for (std::size_t k = 0; k < h.control.size(); ++k)
    if (std::abs(h.control[k]) > std::abs(h.control[peak])) peak = k;
  if (!h.control.empty())
    j["peak"] = {{"frequency", h.frequencies[peak]}, {"amplitude", std::abs(h.control[peak])}};
  if (h.has_film)
    j["film"] = {{"force", amplitude_phase(h.film_force, "N/V")},
                 {"mean_gap", amplitude_phase(h.mean_gap, "m/V")},
                 {"spring", h.film_spring},
                 {"damping", h.film_damping}};
  return j;
}

Json coupling_json(const SwitchScene& scene, const CouplingOptions& c) {
  Json j = {{"scheme", coupling_scheme_name(c.scheme)}};
  if (c.scheme == CouplingScheme::StronglyCoupled) {
    j["tolerance"] = c.tolerance;
    j["max_iterations"] = c.max_iterations;
  }
  if (scene.gas() != GasModel::None && c.scheme != CouplingScheme::Monolithic)
    j["gas_every"] = c.gas_every;
  if (scene.immersed) j["strong_gas"] = c.strong_gas;
  return j;
}

}  // namespace

Json pull_in_summary(const SwitchScene& scene, const PullInSettings& settings,
                     const PullInReport& report) {
  Json j;
  j["structure"] = structure_name(scene.choice.models.structure);
  j["electrostatics"] = field_name(scene.field());
  j["gas"] = gas_name(scene.gas());
  j["mode"] = analysis_name(settings.analysis);
  j["gap"] = scene.gap;
  j["counters"] = report.counters;
  if (steps_in_time(settings.analysis)) {
    const DynamicOptions& o =
        settings.analysis == Analysis::Transient ? settings.transient_run : settings.run;
    j["contact_gap"] = o.contact_gap;
    j["coupling"] = coupling_json(scene, o.coupling);
  }
  if (scene.immersed) {
    const ImmersedField& f = *scene.immersed;
    j["immersed"] = {
        {"background_cells", {f.geometry.background_cells[0], f.geometry.background_cells[1]}},
        {"surface_segments", f.sw->rest_surface().n_segments()},
        {"first_bending_period", f.sw->first_bending_period()}};
  }
  if (report.has_static)
    j["static"] = {{"voltage", report.static_voltage},
                   {"control", report.static_state.control},
                   {"iterations", report.static_state.iterations}};
  if (report.has_transient) {
    const DynamicRun& r = report.transient;
    j["transient"] = run_json(r);
    j["transient"]["voltage"] = settings.transient_voltage;
    j["transient"]["wall_time_s"] = report.transient_wall_s;
    j["transient"]["cpu_time_s"] = report.transient_cpu_s;
    // A history that ends in contact has no small-signal response to fit.
    if (!r.pulled_in)
      j["transient"]["free_response"] = free_response_json(free_response(r.history));
  }
  const QuasiStaticPullIn& qs = report.quasi_static;
  if (report.has_quasi_static)
    j["quasi_static"] = {{"pull_in_voltage", qs.pull_in_voltage},
                         {"pull_in_displacement", qs.pull_in_displacement},
                         {"pull_in_fraction_of_gap", -qs.pull_in_displacement / scene.gap},
                         {"curve_points", qs.curve.size()},
                         {"solves", qs.solves},
                         {"newton_iterations", qs.newton_iterations}};
  if (!report.bias_modes.empty()) {
    Json modes = Json::array();
    for (const BiasedModes& b : report.bias_modes) {
      Json frequencies = Json::array(), damping = Json::array();
      for (const StructuralMode& m : b.modes) {
        frequencies.push_back(m.frequency);
        damping.push_back(m.damping_ratio);
      }
      modes.push_back({{"voltage", b.voltage},
                       {"control", b.displacement},
                       {"frequencies", frequencies},
                       {"damping_ratios", damping}});
    }
    j["quasi_static"]["modes"] = modes;
  }
  if (report.has_harmonic) j["harmonic"] = harmonic_json(report.harmonic);
  if (report.has_pull_out) {
    const QuasiStaticPullOut& po = report.pull_out;
    j["contact"] = {{"gap", scene.contact().gap}, {"penetration", scene.contact().penetration}};
    j["quasi_static"]["pull_out_voltage"] = po.pull_out_voltage;
    j["quasi_static"]["pull_out"] = {{"voltage", po.pull_out_voltage},
                                     {"released_voltage", po.released_voltage},
                                     {"contact_fraction", po.branch.back().contact_fraction},
                                     {"branch_points", po.branch.size()},
                                     {"solves", po.solves},
                                     {"newton_iterations", po.newton_iterations}};
  }
  if (!report.has_dynamic) return j;
  const DynamicPullIn& d = report.dynamic;
  // pull_in_time null: the upper end (past the unstable equilibrium) did not touch down by
  // end_time.
  j["dynamic"] = {{"pull_in_voltage", d.voltage},
                  {"not_pulling_in", d.lower},
                  {"pull_in_time", d.pull_in_time > 0 ? Json(d.pull_in_time) : Json()},
                  {"upper_past_fold", d.upper_past_fold},
                  {"ratio_to_quasi_static", d.voltage / qs.pull_in_voltage},
                  {"tolerance", report.tolerance},
                  {"runs", d.runs},
                  {"settled_runs", d.settled_runs},
                  {"past_fold_runs", d.past_fold_runs},
                  {"steps", d.steps},
                  {"residual_evals", d.residual_evals},
                  {"waveform", report.waveform}};
  Json histories = Json::array();
  for (const auto& [v, run] : report.histories) {
    Json h = run_json(run);
    h["voltage"] = v;
    histories.push_back(h);
  }
  j["dynamic"]["histories"] = histories;
  if (report.time_check_factor > 0)
    j["dynamic"]["pull_in_time_check"] =
        pull_in_time_check_json(report.time_check_factor, d.pull_in_time, report.time_check);
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
      const DynamicPullOut& o = report.dynamic_pull_out;
      r["pull_out_voltage"] = o.voltage;
      r["releasing"] = o.released;
      r["release_time_at_releasing"] = o.release_time;
      r["runs"] = o.runs;
      r["ratio_to_quasi_static"] = o.voltage / report.pull_out.pull_out_voltage;
    }
    j["dynamic"]["release"] = r;
  }
  if (report.small_signal_voltage > 0) {
    j["dynamic"]["small_signal"] = free_response_json(report.small_signal);
    j["dynamic"]["small_signal"]["voltage"] = report.small_signal_voltage;
  }
  return j;
}

CaseSchema pull_in_case_keys() { return embedded_case_schema("coupling/pull_in_study.keys.yaml"); }

}  // namespace rfmems

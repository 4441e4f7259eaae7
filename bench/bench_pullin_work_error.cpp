// bench_pullin_work_error: work against error for the dynamic pull-in TIME of the fixed-fixed
// plate switch of cases/switch_plate (Mindlin-Reissner plate 40 x 4 cells, L = 400 um,
// h = 4 um, gap 3.75 um, parallel-plate electrostatics over the whole length), under a step
// voltage above the dynamic pull-in voltage, without gas and with the Reynolds squeeze film at
// 1 atm (the monolithic plate + film system, coupling/squeeze_film_switch_system.hpp).
//
// The quantity: t_PI, the time at which the smallest gap falls to the contact gap (2 % of
// g0), found by IDA's root finding on min_gap - contact_gap (coupling/dynamic_pull_in.hpp:
// run_dynamic ends there and reports DynamicRun::pull_in_time). Near the dynamic pull-in
// voltage the membrane lingers by the unstable equilibrium, so t_PI is a sensitive measure of
// the whole trajectory, not only of its end.
//
// The integrators, each timed from building the IDA instance to touch-down:
//   ida_o2, ida_o5   IDA adaptive, BDF orders <= 2 and <= 5, rtol 1e-2 ... 1e-7,
//                    atol = 1e-4 x rtol x g0 on every component (the case default at
//                    rtol 1e-3 is 1e-4 g0: the same scaling).
//   ida_o2_w, ida_o5_w  the same with error weights per kind of unknown
//                    (coupling/state_tolerances.hpp): displacements d = --atol-factor x rtol
//                    x g0, velocities d x omega_1 (omega_1 measured here: the free response
//                    of a 20 V step, coupling/dynamic_pull_in.hpp free_response), film
//                    pressures d p_a / g0, the plate's rotations (algebraic) out of the error
//                    test with d / dx for Newton's test.
//   be, bdf2         fixed step dt (IdaOptions::fixed_step, max_order 1 and 2): IDA with
//                    hmin = hmax = dt and an error test that never rejects. The contact root
//                    is still located by IDA's interpolant within the last step.
//   be_cut, bdf2_cut the same, but a failed Newton solve (the 1/g^2 touch-down) may cut the
//                    step (IdaOptions::fixed_step_min = 1e-4 dt), which grows back to dt.
// The reference: IDA at --ref-rtol (default 1e-9) with max_order 5 and with max_order 2; their
// difference is reported as the reference's uncertainty, and a Richardson extrapolation of
// the two finest BDF2 runs as an independent check. Error = |t - t_ref| / t_ref.
//
// Work: residual evaluations (with KLU and an exact Jacobian this is the Newton iteration
// count plus IDACalcIC's), Jacobian evaluations, steps and wall time. The summary line gives,
// for each gas setting and for 1 % and 0.1 % error, the cheapest run of each family (adaptive:
// IDA orders <= 2 and <= 5; fixed: BE and BDF2) that meets it, and the cheapest from which
// every finer run of its method meets it too (see choose()), with the ratios fixed / adaptive.
// No interpolation between runs: the errors are not monotone in the tolerance, and a fixed
// step between two good ones may fail at touch-down.
//
// Output: one JSON object per line on stdout; progress on stderr.
//   bench_pullin_work_error [--quick] [--voltage 180] [--gas none reynolds] [--cap 60]
//       [--families ...] [--rate-factors 1 10 0] [--t-ref T (exploration: skip the reference)]
//       [--case switch_plate_damped --end-time 40e-6 --free-voltage 20]
//       [--ida-nonlin-conv C --ida-max-newton N --ida-dcj D --ida-eta-max-fx E ... : IDA's Newton
//        and step controls (IdaOptions) for the adaptive families only]
// Results: docs/pull-in.md, "Work against error" (scalar atol, error weights, cutting fixed
// steps, four voltages, IDA's controls, the fold) and "Damped switches" (the
// squeeze-film-dominated switch, cases/switch_plate_damped).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "core/error.hpp"
#include "coupling/dynamic_pull_in.hpp"
#include "coupling/state_tolerances.hpp"
#include "coupling/switch_scene.hpp"
#include "coupling/switch_system.hpp"
#include "io/case_file.hpp"
#include "solvers/ida_integrator.hpp"

using namespace rfmems;
using OJson = nlohmann::ordered_json;  // rfmems::Json is unordered
namespace fs = std::filesystem;

namespace {

using rfmems::bench::add_integrator_stats;
using rfmems::bench::cpu_now;
using rfmems::bench::default_cases_dir;
using rfmems::bench::emit;
using rfmems::bench::now;

struct Run {
  std::string failure;  // the solver's message if the run failed
  bool pulled_in = false;
  double t_pi = 0, seconds = 0;
  IntegratorStats stats;
};

// The voltage's rise time (--rise-time; 0: a step) and the end of every run (--end-time).
double g_rise_time = 0;
double g_end_time = 40e-6;

// One step-voltage (or ramped, with --rise-time) run from rest to touch-down (or end_time).
Run pull_in_run(SwitchSystem& system, Index control, double voltage, double gap,
                const IdaOptions& ida, const StateTolerances& tolerances = {}) {
  DynamicOptions o;
  o.end_time = g_end_time;
  o.contact_gap = 0.02 * gap;
  o.stop_at_turning = false;  // above V_dyn it must touch down; a turn would be reported as such
  o.output_interval = 0;
  o.ida = ida;
  o.ida.max_steps = 100000000;
  o.tolerances = tolerances;
  const double t0 = now();
  Run run;
  try {
    VoltageWaveform waveform;
    if (g_rise_time > 0) {
      waveform.kind = VoltageWaveform::Kind::Ramp;
      waveform.rise_time = g_rise_time;
    }
    const DynamicRun r = run_dynamic(system, control, waveform.at(voltage), o);
    run.pulled_in = r.pulled_in;
    run.t_pi = r.pull_in_time;
    run.stats = r.stats;
  } catch (const SolverError& e) {
    // A fixed step cannot be retried smaller: IDA gives up when Newton fails at h = hmin.
    run.failure = e.what();
  }
  run.seconds = now() - t0;
  return run;
}

// Where an adaptive run spends its steps: the same run as run_dynamic (rest, IDACalcIC, contact
// root) with IDA stopped every `window` to read its step count and current step size.
OJson step_profile(SwitchSystem& system, double voltage, double gap, const IdaOptions& options,
                   double window, const StateTolerances& tolerances = {}) {
  system.actuation().set_voltage_squared([voltage](Real) { return voltage * voltage; });
  std::vector<Real> y, yp;
  system.initial_state(0.0, y, yp);
  IdaOptions o = with_state_tolerances(options, system, tolerances);
  o.max_steps = 100000000;
  IdaIntegrator ida(system, o);
  ida.initialize(0.0, y, yp);
  ida.correct_initial_conditions(window);
  const double contact = 0.02 * gap;
  ida.set_roots(1, [&](Real, std::span<const Real> yy, std::span<const Real>, std::span<Real> g) {
    g[0] = system.min_gap(yy) - contact;
  });
  OJson rows = OJson::array();
  long before = 0;
  for (double t_out = window;; t_out += window) {
    const IdaIntegrator::Status status = ida.advance(t_out);
    const IntegratorStats st = ida.stats();
    rows.push_back({{"t_end_s", ida.time()},
                    {"steps", st.steps - before},
                    {"mean_step_s", window / std::max(1L, st.steps - before)},
                    {"last_step_s", st.last_step},
                    {"order", st.last_order},
                    {"min_gap_over_g0", system.min_gap(ida.y()) / gap}});
    before = st.steps;
    if (status == IdaIntegrator::Status::Root || t_out > g_end_time) break;
  }
  return rows;
}

OJson stats_json(const Run& run) {
  if (!run.failure.empty()) return OJson{{"failed", run.failure}, {"wall_s", run.seconds}};
  OJson j{{"pulled_in", run.pulled_in},
          {"t_pi_s", run.t_pi},
          {"wall_s", run.seconds},
          {"last_order", run.stats.last_order}};
  add_integrator_stats(j, run.stats);
  return j;
}

// A finished run as the summary sees it (failed runs have infinite error), in the order the
// runs were made: from the loosest tolerance / largest step to the finest.
struct Point {
  std::string param;
  double evals, wall, error;
};

// Per method and target error: the cheapest run that meets the target, and the cheapest from
// which every finer run of the method meets it too ("reliable": a user who picks that setting
// or any finer one gets the accuracy; a fixed step that happens to land its last step well
// while the next smaller ones fail at touch-down is cheapest but not reliable).
struct Choice {
  const Point* cheapest = nullptr;
  const Point* reliable = nullptr;
};

Choice choose(const std::vector<Point>& runs, double target) {
  Choice c;
  for (const Point& p : runs)
    if (p.error <= target && (!c.cheapest || p.evals < c.cheapest->evals)) c.cheapest = &p;
  for (std::size_t k = runs.size(); k-- > 0;) {
    if (!(runs[k].error <= target)) break;
    c.reliable = &runs[k];
  }
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Work against error of IDA and fixed-step BDF for the dynamic pull-in time of the "
      "plate switch (JSON lines)"};
  std::string cases = default_cases_dir(), case_name = "switch_plate";
  double free_voltage = 20.0;
  double voltage = 180.0, cap = 40.0, ref_rtol = 1e-9, ref_o2_rtol = 0;
  std::vector<std::string> gases{"none", "reynolds"};
  std::vector<double> rtols{1e-1, 3e-2, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
  std::vector<double> o5_rtols{1e-2, 1e-4, 1e-6}, profile_rtols{1e-2, 1e-4};
  std::vector<double> dts{1e-7, 5e-8, 2e-8, 1e-8, 5e-9, 2e-9, 1e-9, 5e-10, 2e-10};
  std::vector<double> w_rtols{1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 1e-4, 1e-5};
  std::vector<double> w_o5_rtols{1e-1, 1e-2, 1e-3, 1e-4, 1e-6};
  std::vector<double> cut_dts{2e-7, 1e-7, 5e-8, 2e-8, 1e-8, 5e-9, 2e-9};
  std::vector<std::string> families{"ida_o2", "ida_o5", "ida_o2_w", "ida_o5_w",
                                    "be",     "bdf2",   "be_cut",   "bdf2_cut"};
  double atol_factor = 1.0, velocity_rate = 0;
  std::vector<double> rate_factors{1.0};
  bool quick = false;
  // IDA's Newton and step control for the adaptive families (IdaOptions; 0: IDA's default).
  // The references and the fixed-step families keep IDA's defaults.
  IdaOptions control;
  double h0_periods = 0;
  app.add_option("--ida-nonlin-conv", control.nonlinear_convergence,
                 "adaptive families: IDASetNonlinConvCoef (0: IDA's 0.33)");
  app.add_option("--ida-max-newton", control.max_newton_iterations,
                 "adaptive families: IDASetMaxNonlinIters (0: IDA's 4)");
  app.add_option("--ida-max-conv-fails", control.max_convergence_failures,
                 "adaptive families: IDASetMaxConvFails (0: IDA's 10)");
  app.add_option("--ida-dcj", control.jacobian_cj_change,
                 "adaptive families: IDASetDeltaCjLSetup (0: IDA's 0.25)");
  app.add_option("--ida-eta-max-fx", control.step_growth_threshold,
                 "adaptive families: IDASetEtaFixedStepBounds upper bound (0: IDA's 2)");
  app.add_option("--ida-eta-max", control.max_step_growth,
                 "adaptive families: IDASetEtaMax (0: IDA's 2)");
  app.add_option("--ida-eta-conv-fail", control.convergence_failure_cut,
                 "adaptive families: IDASetEtaConvFail (0: IDA's 0.25)");
  app.add_option("--ida-h0-periods", h0_periods,
                 "adaptive families: initial step = this x sqrt(rtol) x 2 pi / omega_1 (0: IDA's)");
  app.add_option("--cases", cases, "the repository's cases/ directory");
  app.add_option("--case", case_name,
                 "the switch case under --cases (switch_plate; switch_plate_damped: the "
                 "squeeze-film-dominated one, docs/pull-in.md)");
  app.add_option("--end-time", g_end_time, "every run gives up (not pulled in) at this time [s]");
  app.add_option("--free-voltage", free_voltage,
                 "step voltage [V] of the free response that measures omega_1");
  app.add_option("--families", families, "integrator families to run (see the header)");
  app.add_option("--w-rtols", w_rtols, "rtols of ida_o2_w");
  app.add_option("--w-o5-rtols", w_o5_rtols, "rtols of ida_o5_w");
  app.add_option("--cut-dts", cut_dts, "fixed steps of be_cut, bdf2_cut [s]");
  app.add_option("--rate-factors", rate_factors,
                 "weighted families: velocity rates as multiples of omega_1 (0: velocities out "
                 "of the error test); methods ida_oK_w, ida_oK_wx10, ida_oK_woff");
  app.add_option("--atol-factor", atol_factor,
                 "weighted families: displacement atol = this x rtol x g0");
  app.add_option(
      "--velocity-rate", velocity_rate,
      "weighted families: velocity atol = displacement atol x this [1/s] (0: measured omega_1)");
  app.add_option("--rise-time", g_rise_time,
                 "linear voltage ramp over this time [s] instead of a step (default 0: step)");
  app.add_option("--voltage", voltage,
                 "step voltage [V] (dynamic V_PI: ~171 V vacuum, ~174 V at 1 atm)");
  app.add_option("--gas", gases, "gas models to run: none, reynolds");
  app.add_option("--rtols", rtols, "IDA relative tolerances, max_order 2");
  app.add_option("--o5-rtols", o5_rtols, "IDA relative tolerances, max_order 5");
  app.add_option("--profile-rtols", profile_rtols, "step profiles of max_order 2 at these rtols");
  app.add_option("--dts", dts, "fixed steps [s]");
  app.add_option("--ref-rtol", ref_rtol, "tolerance of the reference (max_order 5)");
  double given_t_ref = 0;
  app.add_option("--t-ref", given_t_ref,
                 "use this reference t_PI [s] instead of computing it (exploration runs only)");
  app.add_option("--ref-o2-rtol", ref_o2_rtol,
                 "also check the reference with max_order 2 at this rtol");
  app.add_option("--cap", cap, "skip runs predicted to take longer than this [s]");
  app.add_flag("--quick", quick, "smoke run: few tolerances and steps, reference at 1e-7");
  CLI11_PARSE(app, argc, argv);
  if (quick) {
    rtols = {1e-2, 1e-3};
    o5_rtols = {1e-2};
    profile_rtols = {1e-2};
    dts = {5e-9, 2e-9};
    w_rtols = {1e-2, 1e-3};
    w_o5_rtols = {1e-2};
    cut_dts = {5e-8, 1e-8};
    ref_rtol = 1e-6;
    cap = 10;
  }

  OJson summary_all = OJson::array();
  for (const std::string& gas : gases) {
    const std::string case_path = cases + "/" + case_name + "/case.yaml";
    const CaseFile cf = CaseFile::load(case_path, {"gas.model=" + gas});
    SwitchScene scene = build_switch_scene(cf.root(), fs::path(case_path).parent_path().string());
    const std::unique_ptr<SwitchSystem> system = make_switch_system(scene);
    const double gap = scene.gap;
    OJson common{{"bench", "pullin_work_error"},
                 {"case", case_name},
                 {"gas", gas},
                 {"voltage", voltage},
                 {"cells", scene.structure->structure_mesh().n_cells()},
                 {"unknowns", system->size()},
                 {"contact_gap", 0.02 * gap},
                 {"ida_controls",
                  {{"nonlinear_convergence", control.nonlinear_convergence},
                   {"max_newton_iterations", control.max_newton_iterations},
                   {"max_convergence_failures", control.max_convergence_failures},
                   {"jacobian_cj_change", control.jacobian_cj_change},
                   {"step_growth_threshold", control.step_growth_threshold},
                   {"max_step_growth", control.max_step_growth},
                   {"convergence_failure_cut", control.convergence_failure_cut},
                   {"initial_step_periods_over_sqrt_rtol", h0_periods}}}};
    std::fprintf(stderr, "gas %s: %lld unknowns, step %.1f V\n", gas.c_str(),
                 static_cast<long long>(system->size()), voltage);

    // Unit costs (best of 20 / 5) at a deflected state, to read the work counts.
    {
      std::vector<Real> y, yp;
      system->initial_state(0.0, y, yp);
      for (Index i = 0; i < scene.structure->structure().size(); i += 3) y[i] = -0.3 * gap;
      system->actuation().set_voltage_squared([voltage](Real) { return voltage * voltage; });
      std::vector<Real> r(y.size()), jac(system->jacobian_pattern().nnz());
      double t_res = 1e300, t_jac = 1e300;
      for (int i = 0; i < 20; ++i) {
        const double t1 = now();
        system->residual(0.0, y, yp, r);
        t_res = std::min(t_res, now() - t1);
      }
      for (int i = 0; i < 5; ++i) {
        std::fill(jac.begin(), jac.end(), 0.0);
        const double t1 = now();
        system->jacobian(0.0, 1e7, y, yp, jac);
        t_jac = std::min(t_jac, now() - t1);
      }
      OJson j = common;
      j["variant"] = "costs";
      j["jacobian_nnz"] = jac.size();
      j["t_residual_eval_s"] = t_res;
      j["t_jacobian_eval_s"] = t_jac;
      emit(j);
    }

    // ---- reference ---------------------------------------------------------------------
    auto adaptive = [&](double rtol, int order) {
      IdaOptions o;
      o.rtol = rtol;
      o.atol = 1e-4 * rtol * gap;
      o.max_order = order;
      return o;
    };
    // The adaptive families' runs: the reference's settings plus the --ida-* controls.
    auto tuned = [&](double rtol, int order, double omega) {
      IdaOptions o = control;
      const IdaOptions base = adaptive(rtol, order);
      o.rtol = base.rtol;
      o.atol = base.atol;
      o.max_order = base.max_order;
      if (h0_periods > 0) o.initial_step = h0_periods * std::sqrt(rtol) * 2 * M_PI / omega;
      return o;
    };
    auto runs_family = [&](const std::string& f) {
      return std::find(families.begin(), families.end(), f) != families.end();
    };
    // omega_1: the damped frequency of the free response to a --free-voltage step (20 V on
    // the default case: electrostatic softening (20/171)^2 ~ 1 %), IDA order <= 5 at rtol 1e-6
    // with the scalar atol. A heavily damped scene gives no free oscillation: --velocity-rate.
    double omega_1 = velocity_rate;
    if (omega_1 <= 0) {
      DynamicOptions o;
      o.end_time = 30e-6;
      o.contact_gap = 0.02 * gap;
      o.stop_at_turning = false;
      o.output_interval = 0.02e-6;
      o.ida = adaptive(1e-6, 5);
      const DynamicRun r =
          run_dynamic(*system, scene.control, VoltageWaveform{}.at(free_voltage), o);
      const FreeResponse fr = free_response(r.history);
      if (!fr.fitted || fr.frequency <= 0) {
        std::fprintf(stderr, "  no free oscillation at %g V: give --velocity-rate\n", free_voltage);
        return 1;
      }
      omega_1 = 2 * M_PI * fr.frequency;
      OJson j = common;
      j["variant"] = "omega_1";
      j["frequency_hz"] = fr.frequency;
      j["damping_ratio"] = fr.damping_ratio;
      j["fit_residual"] = fr.residual;
      j["fit_damping_ratio"] = fr.fit_damping_ratio;
      j["fit_frequency_hz"] = fr.fit_frequency;
      j["log_decrement_damping_ratio"] = fr.log_decrement.damping_ratio;
      j["swings"] = fr.log_decrement.swings;
      j["omega_1_rad_s"] = omega_1;
      emit(j);
      std::fprintf(stderr, "  omega_1 = %.4e rad/s (f = %.1f kHz, zeta %.3g, %g V)\n", omega_1,
                   fr.frequency / 1e3, fr.damping_ratio, free_voltage);
    }
    auto weighted = [&](double rtol, double rate_factor = 1.0) {
      // Factor 0: velocities out of the test (an atol 1e13 x d per second: never binding).
      return per_kind_tolerances(scene, atol_factor * rtol * gap,
                                 rate_factor > 0 ? rate_factor * omega_1 : 1e13);
    };

    // The reference (order <= 5 at ref_rtol) and two checks of it: order <= 5 at 10 x
    // ref_rtol, and optionally order <= 2 at --ref-o2-rtol (order 2 needs ~6x the steps of
    // order 5 at the same tolerance here).
    struct RefSpec {
      const char* name;
      double rtol;
      int order;
    };
    std::vector<RefSpec> specs{{"reference", ref_rtol, 5}, {"reference_loose", 10 * ref_rtol, 5}};
    if (ref_o2_rtol > 0) specs.push_back({"reference_o2", ref_o2_rtol, 2});
    std::vector<Run> refs;
    if (given_t_ref > 0) {
      specs.clear();
      Run given;
      given.pulled_in = true;
      given.t_pi = given_t_ref;
      refs.push_back(given);
    }
    for (const RefSpec& spec : specs) {
      std::fprintf(stderr, "  %s: order <= %d, rtol %.0e ...\n", spec.name, spec.order, spec.rtol);
      refs.push_back(
          pull_in_run(*system, scene.control, voltage, gap, adaptive(spec.rtol, spec.order)));
      OJson j = common;
      j["variant"] = spec.name;
      j["method"] = spec.order == 5 ? "ida_o5" : "ida_o2";
      j["rtol"] = spec.rtol;
      j.update(stats_json(refs.back()));
      emit(j);
      std::fprintf(stderr, "    t_PI = %.12e s, %ld steps, %.2f s\n", refs.back().t_pi,
                   refs.back().stats.steps, refs.back().seconds);
    }
    const double t_ref = refs[0].t_pi;
    if (!refs[0].pulled_in) {
      std::fprintf(stderr, "  %.1f V does not pull in within %g s: raise --voltage or --end-time\n",
                   voltage, g_end_time);
      return 1;
    }
    {
      OJson j = common;
      j["variant"] = "reference_check";
      j["t_ref_s"] = t_ref;
      for (std::size_t k = 1; k < specs.size(); ++k)
        j[std::string(specs[k].name) + "_vs_ref_rel"] = std::abs(refs[k].t_pi - t_ref) / t_ref;
      emit(j);
    }

    // ---- the runs ------------------------------------------------------------------------
    std::map<std::string, std::vector<Point>> points;
    auto record = [&](const std::string& method, OJson params, const Run& run) {
      OJson j = common;
      j["variant"] = "run";
      j["method"] = method;
      j.update(params);
      j.update(stats_json(run));
      const double err = std::abs(run.t_pi - t_ref) / t_ref;
      if (run.pulled_in) j["error"] = err;
      const std::string param = method + (params.contains("rtol") ? " rtol " + params["rtol"].dump()
                                                                  : " dt " + params["dt"].dump());
      points[method].push_back({param, static_cast<double>(run.stats.residual_evals), run.seconds,
                                run.pulled_in ? err : std::numeric_limits<double>::infinity()});
      emit(j);
      std::fprintf(stderr,
                   "  %-6s %s: t_PI %.9e s, error %.2e, %ld res, %ld jac, %ld steps, %.3f s\n",
                   method.c_str(), params.dump().c_str(), run.t_pi, err, run.stats.residual_evals,
                   run.stats.jacobian_evals, run.stats.steps, run.seconds);
    };
    struct AdaptiveFamily {
      std::string family, method;
      double rate_factor;
    };
    std::vector<AdaptiveFamily> adaptive_families{{"ida_o2", "ida_o2", 0}, {"ida_o5", "ida_o5", 0}};
    for (const char* f : {"ida_o2_w", "ida_o3_w", "ida_o4_w", "ida_o5_w"})
      for (double factor : rate_factors) {
        char suffix[16] = "";
        if (factor == 0)
          std::snprintf(suffix, sizeof suffix, "off");
        else if (factor != 1)
          std::snprintf(suffix, sizeof suffix, "x%g", factor);
        adaptive_families.push_back({f, std::string(f) + suffix, factor});
      }
    for (const AdaptiveFamily& af : adaptive_families) {
      if (!runs_family(af.family)) continue;
      const std::string& method = af.method;
      const int order = method[5] - '0';  // ida_oK...
      const bool w = af.family.back() == 'w';
      const std::vector<double>& list =
          w ? (order == 2 ? w_rtols : w_o5_rtols) : (order == 2 ? rtols : o5_rtols);  // o3-o5 alike
      double last_time = 0, last_steps = 0, before_steps = 0;
      for (double rtol : list) {
        OJson params{{"rtol", rtol}, {"max_order", order}};
        if (w) {
          const StateTolerances t = weighted(rtol, af.rate_factor);
          params["velocity_rate_over_omega_1"] = af.rate_factor;
          params["atol_displacement"] = t.displacement;
          params["atol_velocity"] = t.displacement * t.velocity_rate;
          params["atol_pressure"] = t.pressure;
          params["atol_rotation"] = t.quasi_static;
          params["suppress_rotations"] = true;
        } else {
          params["atol"] = 1e-4 * rtol * gap;
        }
        const double predicted =
            before_steps > 0 ? last_time * last_steps / before_steps : last_time;
        if (predicted > cap) {
          OJson j = common;
          j["variant"] = "skipped";
          j["method"] = method;
          j.update(params);
          j["predicted_wall_s"] = predicted;
          emit(j);
          continue;
        }
        const Run run =
            pull_in_run(*system, scene.control, voltage, gap, tuned(rtol, order, omega_1),
                        w ? weighted(rtol, af.rate_factor) : StateTolerances{});
        record(method, params, run);
        before_steps = last_steps;
        last_steps = static_cast<double>(run.stats.steps);
        last_time = run.seconds;
      }
    }
    std::map<int, std::map<double, double>> fixed_t;  // order -> dt -> t_PI
    for (const std::string method : {"be", "bdf2", "be_cut", "bdf2_cut"}) {
      if (!runs_family(method)) continue;
      const int order = method.rfind("be", 0) == 0 ? 1 : 2;
      const bool cut = method.find("_cut") != std::string::npos;
      double last_time = 0, last_dt = 0;
      for (double dt : cut ? cut_dts : dts) {
        OJson params{{"dt", dt}, {"max_order", order}};
        const double predicted = last_dt > 0 ? last_time * last_dt / dt : 0;  // cost ~ 1/dt
        if (predicted > cap) {
          OJson j = common;
          j["variant"] = "skipped";
          j["method"] = method;
          j.update(params);
          j["predicted_wall_s"] = predicted;
          emit(j);
          continue;
        }
        IdaOptions o;
        o.fixed_step = dt;
        o.fixed_step_min = cut ? 1e-4 * dt : 0.0;
        o.max_order = order;
        const Run run = pull_in_run(*system, scene.control, voltage, gap, o);
        record(method, params, run);
        last_time = run.seconds;
        last_dt = dt;
        if (run.pulled_in && !cut) fixed_t[order][dt] = run.t_pi;
      }
    }
    // Richardson check of the reference from the two finest runs of each fixed-step family,
    // and the observed order from the three finest.
    for (auto& [order, runs] : fixed_t) {
      if (runs.size() < 2) continue;
      auto fine = runs.begin(), coarse = std::next(fine);
      const double r = coarse->first / fine->first, rp = std::pow(r, order);
      const double t_rich = (rp * fine->second - coarse->second) / (rp - 1);
      OJson j = common;
      j["variant"] = "richardson_check";
      j["method"] = order == 1 ? "be" : "bdf2";
      j["dt_fine"] = fine->first;
      j["dt_coarse"] = coarse->first;
      j["t_richardson_s"] = t_rich;
      j["richardson_vs_ref_rel"] = std::abs(t_rich - t_ref) / t_ref;
      if (runs.size() >= 3) {
        auto third = std::next(coarse);
        const double e1 = coarse->second - fine->second, e2 = third->second - coarse->second;
        j["observed_order"] = std::log(std::abs(e2 / e1)) / std::log(third->first / coarse->first);
      }
      emit(j);
    }

    // ---- where the adaptive steps go ------------------------------------------------------
    for (double rtol : profile_rtols) {
      if (rtol <= 0) continue;  // --profile-rtols 0: no profiles
      OJson j = common;
      j["variant"] = "step_profile";
      j["method"] = "ida_o2";
      j["rtol"] = rtol;
      j["window_s"] = 0.5e-6;
      j["windows"] = step_profile(*system, voltage, gap, tuned(rtol, 2, omega_1), 0.5e-6);
      emit(j);
      if (runs_family("ida_o2_w")) {
        j["method"] = "ida_o2_w";
        j["windows"] =
            step_profile(*system, voltage, gap, tuned(rtol, 2, omega_1), 0.5e-6, weighted(rtol));
        emit(j);
      }
    }

    // ---- work at 1 % and 0.1 % -----------------------------------------------------------
    OJson s = common;
    s["variant"] = "summary";
    s["t_ref_s"] = t_ref;
    for (double target : {1e-2, 1e-3}) {
      OJson t;
      auto describe = [](const Point* p) {
        return p ? OJson{{"param", p->param},
                         {"residual_evals", p->evals},
                         {"wall_s", p->wall},
                         {"error", p->error}}
                 : OJson(nullptr);
      };
      OJson per = OJson::object();
      for (const auto& [m, runs] : points) {
        const Choice c = choose(runs, target);
        per[m] = {{"cheapest", describe(c.cheapest)}, {"reliable", describe(c.reliable)}};
      }
      t["per_method"] = per;
      for (const bool reliable : {false, true}) {
        auto family = [&](const std::vector<std::string>& members) {
          const Point* best = nullptr;
          for (const std::string& m : members) {
            if (!points.count(m)) continue;
            const Choice c = choose(points[m], target);
            const Point* p = reliable ? c.reliable : c.cheapest;
            if (p && (!best || p->evals < best->evals)) best = p;
          }
          return best;
        };
        // Adaptive with the scalar atol and with the state weights, against the fixed step
        // as before and against the fixed step allowed to cut its last steps.
        struct Comparison {
          const char* name;
          std::vector<std::string> adaptive, fixed;
        };
        std::vector<std::string> weighted_methods;  // every ida_oK_w* run
        for (const auto& [m, runs] : points)
          if (m.find("_w") != std::string::npos) weighted_methods.push_back(m);
        OJson r = OJson::object();
        for (const Comparison& c :
             {Comparison{"scalar_vs_fixed", {"ida_o2", "ida_o5"}, {"be", "bdf2"}},
              Comparison{"weighted_vs_fixed", weighted_methods, {"be", "bdf2"}},
              Comparison{"weighted_vs_fixed_or_cut",
                         weighted_methods,
                         {"be", "bdf2", "be_cut", "bdf2_cut"}}}) {
          const Point* a = family(c.adaptive);
          const Point* f = family(c.fixed);
          OJson e{{"adaptive", describe(a)}, {"fixed", describe(f)}};
          if (a && f) {
            e["ratio_fixed_over_adaptive_evals"] = f->evals / a->evals;
            e["ratio_fixed_over_adaptive_wall"] = f->wall / a->wall;
            std::fprintf(stderr,
                         "  error %g (%s, %s): adaptive %s %.0f evals / %.3f s, fixed %s %.0f "
                         "evals / %.3f s: fixed/adaptive %.2f (evals), %.2f (wall)\n",
                         target, reliable ? "reliable" : "cheapest", c.name, a->param.c_str(),
                         a->evals, a->wall, f->param.c_str(), f->evals, f->wall,
                         f->evals / a->evals, f->wall / a->wall);
          }
          r[c.name] = e;
        }
        t[reliable ? "reliable" : "cheapest"] = r;
      }
      char key[16];
      std::snprintf(key, sizeof key, "at_%g", target);
      s[key] = t;
    }
    emit(s);
  }
  return 0;
}

// Cost of the contact phase of the plate switch (cases/switch_plate with 0.1 um of eps_r = 7.6
// on the electrode and the contact penalty g_c = 75 nm, delta = 7.5 nm; docs/pull-in.md,
// "Contact and pull-out"): one JSON line per phase, CPU seconds of this process.
//
//   approach:     step to --voltage from rest, touch-down, on in contact for --delay (IDA);
//   pull_out:     the quasi-static pull-out from the state at the drop (pseudo-transient
//                 relaxation + Newton down the contact branch, quasi_static_pull_out.hpp);
//   hold:         the drop to --hold, until release or --window;
//   dynamic_pull_out: bisection on the hold voltage in [0, --voltage] to --tolerance;
//   --touching-only: only the touching point of the no-contact branch (the smallest gap of the
//                 reconstructed surface at g_c; touching_point.hpp), which the quasi-static
//                 pull-out approaches as delta -> 0: its mesh dependence without any dynamics;
//                 with --pull-out-from-touching also the quasi-static pull-out from the plate
//                 pressed on at 1.25 x that voltage.
//
//   bench_plate_release --cells 40,4 --gas reynolds
#include <CLI/CLI.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "coupling/dynamic_release.hpp"
#include "coupling/pull_in_study.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/quasi_static_pull_out.hpp"
#include "coupling/switch_scene.hpp"
#include "coupling/switch_system.hpp"
#include "coupling/touching_point.hpp"
#include "io/case_file.hpp"

using namespace rfmems;
using Json = nlohmann::json;

int main(int argc, char** argv) {
  CLI::App app("contact, hold and pull-out of the plate switch: cost per phase");
  std::string cells = "40,4", gas = "reynolds";
  double voltage = 180, hold = 10, tolerance = 0.5, delay = 2e-6, window = 20e-6;
  bool bisect = true, touching_only = false, touching_pull_out = false;
  app.add_option("--cells", cells, "plate cells nx,ny");
  app.add_option("--gas", gas, "none | reynolds");
  app.add_option("--voltage", voltage, "the step that pulls in [V]");
  app.add_option("--hold", hold, "the hold voltage of the recorded release [V]");
  app.add_option("--tolerance", tolerance, "bisection tolerance on the dynamic pull-out [V]");
  app.add_option("--delay", delay, "the drop, after touch-down [s]");
  app.add_option("--window", window, "a hold not released by drop + window holds [s]");
  app.add_flag("!--no-bisection", bisect, "skip the dynamic pull-out bisection");
  app.add_flag("--touching-only", touching_only,
               "only the touching point of the no-contact branch");
  app.add_flag("--pull-out-from-touching", touching_pull_out,
               "with --touching-only: also the quasi-static pull-out from 1.25 x the touching "
               "point (no dynamic approach)");
  std::vector<std::string> sets;
  app.add_option("--set", sets, "further case overrides key=value (e.g. material.nu=0)");
  CLI11_PARSE(app, argc, argv);

  const std::string path = bench::default_cases_dir() + "/switch_plate/case.yaml";
  std::vector<std::string> overrides{"mesh.cells=[" + cells + "]", "gas.model=" + gas,
                                     "actuation.dielectric={thickness: 0.1 um, permittivity: 7.6}",
                                     "actuation.contact={gap: 75 nm, penetration: 7.5 nm}"};
  overrides.insert(overrides.end(), sets.begin(), sets.end());
  const CaseFile cf = CaseFile::load(path, overrides);
  SwitchScene scene = build_switch_scene(cf.root(), bench::default_cases_dir() + "/switch_plate");
  const PullInSettings settings = read_pull_in_settings(cf.root(), scene);
  const auto system = make_switch_system(scene);
  Json base = {{"bench", "plate_release"}, {"cells", cells}, {"gas", gas}, {"voltage", voltage}};

  if (touching_only) {
    const double c = bench::cpu_now();
    const QuasiStaticPullIn in =
        trace_pull_in(*scene.actuation, scene.control, settings.quasi_static);
    const TouchingPoint touching = find_touching_point(
        *scene.actuation, in.fold_state, scene.contact().gap, 1e-4 * scene.contact().gap);
    Json t = base;
    t["phase"] = "touching_point";
    t["cpu_s"] = bench::cpu_now() - c;
    t["pull_in_voltage"] = in.pull_in_voltage;
    t["touching_voltage"] = touching.voltage;
    t["min_gap"] = scene.actuation->min_gap(touching.state);
    t["control_cell"] = touching.control / 3;
    t["solves"] = touching.iterations;
    bench::emit(t);
    if (!touching_pull_out) return 0;
    // The quasi-static pull-out from the plate pressed on at 1.25 x the touching point (the
    // relaxation from the touching state: a small contact, the last one to lift).
    const double c1 = bench::cpu_now();
    PullOutOptions po;
    po.start_voltage = 1.25 * touching.voltage;
    po.voltage_tolerance = settings.quasi_static.voltage_tolerance;
    const QuasiStaticPullOut out =
        trace_pull_out(*scene.actuation, touching.control, touching.state, po);
    Json p = base;
    p["phase"] = "pull_out_from_touching";
    p["cpu_s"] = bench::cpu_now() - c1;
    p["pull_out_voltage"] = out.pull_out_voltage;
    p["released_voltage"] = out.released_voltage;
    p["pull_out_over_touching"] = out.pull_out_voltage / touching.voltage;
    p["contact_fraction_at_start"] = out.branch.front().contact_fraction;
    p["contact_fraction_at_pull_out"] = out.branch.back().contact_fraction;
    p["solves"] = out.solves;
    bench::emit(p);
    return 0;
  }
  ReleaseOptions r;
  r.voltage = voltage;
  r.delay = delay;
  r.window = window;
  r.lift = 0.05 * scene.gap;
  double c0 = bench::cpu_now();
  const ReleaseApproach approach = approach_contact(*system, scene.control, settings.run, r);
  Json j = base;
  j["phase"] = "approach";
  j["cpu_s"] = bench::cpu_now() - c0;
  j["pull_in_time"] = approach.run.pull_in_time;
  j["drop_time"] = approach.drop.t;
  j["contact_fraction_at_drop"] = system->contact_fraction(approach.drop.y);
  bench::add_integrator_stats(j, approach.run.stats);
  bench::emit(j);

  c0 = bench::cpu_now();
  PullOutOptions po;
  po.start_voltage = voltage;
  po.voltage_tolerance = settings.quasi_static.voltage_tolerance;
  const QuasiStaticPullOut out =
      trace_pull_out(*scene.actuation, scene.control, approach.drop.y, po);
  j = base;
  j["phase"] = "pull_out";
  j["cpu_s"] = bench::cpu_now() - c0;
  j["pull_out_voltage"] = out.pull_out_voltage;
  j["released_voltage"] = out.released_voltage;
  j["contact_fraction_at_start"] = out.branch.front().contact_fraction;
  j["contact_fraction_at_pull_out"] = out.branch.back().contact_fraction;
  j["solves"] = out.solves;
  j["relaxation_steps"] = out.relaxation_steps;
  j["newton_iterations"] = out.newton_iterations;
  bench::emit(j);

  c0 = bench::cpu_now();
  const DynamicRun h = run_hold(*system, scene.control, approach.drop, hold, settings.run, r);
  j = base;
  j["phase"] = "hold";
  j["cpu_s"] = bench::cpu_now() - c0;
  j["hold_voltage"] = hold;
  j["released"] = h.released;
  j["release_after"] = h.released ? h.release_time - approach.drop.t : 0.0;
  bench::add_integrator_stats(j, h.stats);
  bench::emit(j);

  if (!bisect) return 0;
  c0 = bench::cpu_now();
  const DynamicPullOut d = find_dynamic_pull_out(*system, scene.control, approach.drop, 0.0,
                                                 voltage, tolerance, settings.run, r);
  j = base;
  j["phase"] = "dynamic_pull_out";
  j["cpu_s"] = bench::cpu_now() - c0;
  j["pull_out_voltage"] = d.voltage;
  j["releasing"] = d.released;
  j["ratio_to_quasi_static"] = d.voltage / out.pull_out_voltage;
  j["runs"] = d.runs;
  j["steps"] = d.steps;
  j["residual_evals"] = d.residual_evals;
  bench::emit(j);
  return 0;
}

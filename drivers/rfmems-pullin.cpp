// rfmems-pullin: the pull-in of an electrostatically actuated switch. The case states the
// structure (a Mindlin-Reissner plate or a plane beam), the gap, the electrode and the
// electrostatics (parallel-plate law, or the Laplace field in a moving gap mesh), and asks for
//   quasi_static: the deflection-voltage curve through its fold (displacement control with
//                 KINSOL, stable and unstable branches): the static pull-in voltage;
//   dynamic:      a step voltage from rest under IDA with contact and turning-point roots;
//                 the dynamic pull-in voltage by bisection, the pull-in time, and the
//                 histories at voltages around it (a laplace case: the plane beam under the
//                 Laplace field recomputed per IDA step, coupling/laplace_dynamic_switch.hpp);
//   transient:    one step voltage from rest to an end time or touch-down, integrated by the
//                 case's coupling scheme (coupling: monolithic | staggered | strongly_coupled,
//                 coupling/coupling_settings.hpp): the centre-deflection history;
//   with actuation.contact: the quasi-static pull-out voltage, and (pull_in.release) the drop
//                 to a hold voltage after touch-down, the release time, and the dynamic
//                 pull-out voltage by bisection on the hold.
//
// Sample runs:
//   rfmems-pullin cases/switch_plate/case.yaml                  # dynamic, prints V_PI and t_PI
//   rfmems-pullin cases/switch_plane_laplace/case.yaml --json   # quasi-static, Laplace
//   rfmems-pullin cases/switch_plate/case.yaml --set pull_in.mode=quasi_static
//   rfmems-pullin cases/cantilever_switch/case.yaml   # immersed-boundary cantilever (a case
//       with an `immersed` block: coupling/immersed_switch_study.hpp): dynamic V_PI by bisection
//   mpirun -np 2 rfmems-pullin cases/cantilever_switch/case.yaml --set gas.model=esbgk
//       --set pull_in.mode=transient   # the ESBGK gas distributed over 2 ranks
//   rfmems-pullin cases/switch_plate/case.yaml --set pull_in.mode=transient
//       --set pull_in.transient.voltage=180V --set pull_in.transient.end_time=5us
//       --set coupling.scheme=strongly_coupled --set coupling.macro_step=0.1us
//
// Output: out/<name>.h5 (+ .xdmf): the structure's fields at the fold (step 0),
// /pull_in/curve, /dynamic/V<k> (see coupling/pull_in_study.hpp). Exit codes as rfmems-solid:
// 0 success; 2 bad input (one line on stderr, no result file); 1 other failures.
#include <fmt/format.h>

#include <cstdio>
#include <iostream>
#include <map>
#include <string>

#include "coupling/coupling_settings.hpp"
#include "coupling/immersed_switch_study.hpp"
#include "coupling/pull_in_study.hpp"
#include "coupling/scene_validity.hpp"
#include "coupling/switch_scene.hpp"
#include "io/atomic_file.hpp"
#include "io/case_file.hpp"
#include "io/driver_main.hpp"
#include "io/interrupt_cleanup.hpp"
#include "io/json_summary.hpp"
#include "io/result_writer.hpp"
#include "parallel/communication_counters.hpp"
#include "parallel/communicator.hpp"

namespace {

using namespace rfmems;

// What the run at a fraction of the tolerances says of the reported pull-in time (the
// summary's dynamic.pull_in_time_check, pull_in_results.hpp).
std::string time_check_note(const Json& dynamic) {
  if (!dynamic.contains("pull_in_time_check")) return "";
  const Json& c = dynamic["pull_in_time_check"];
  const double factor = c["tolerance_factor"].get<double>();
  if (c["relative_error_estimate"].is_null())
    return fmt::format(" (at {:g} x the tolerances this voltage does not pull in: it is within "
                       "the integration error of V_dyn)",
                       factor);
  return fmt::format(" ({:.2g} % from a run at {:g} x the tolerances: {:.3f} us)",
                     100 * c["relative_error_estimate"].get<double>(), factor,
                     1e6 * c["pull_in_time"].get<double>());
}

// The immersed-boundary switch (an `immersed` block: coupling/immersed_switch_study.hpp).
// With gas: esbgk or immersed.electrostatics_distributed every rank of mpirun runs it: the gas
// and (with the key) the field are distributed over the ranks (ImmersedEsbgkSettings::comm,
// ImmersedSwitch::distribute_electrostatics), the rest (marking, fits, structure) is computed
// redundantly on every rank from the same data. The root writes the result; the
// others write to a scratch file of their own that is never finished (deleted on exit).
int run_immersed(const DriverCase& run_case, const DriverOptions& options) {
  const CaseFile& case_file = run_case.file;
  const CaseNode& root = run_case.root;
  const Communicator world = Communicator::world();
  ImmersedSwitchCase c = read_immersed_switch_case(root, run_case.dir);
  case_file.check_all_used();
  const std::string output =
      world.is_root() ? run_case.output : run_case.output + ".rank" + std::to_string(world.rank());
  ResultWriter writer(output, *c.beam->mesh);
  remove_on_interrupt(temp_path_for(output));
  Json summary;
  summary["case"] = run_case.name;
  summary["ranks"] = world.size();
  summary["model"] = "plane_immersed";
  summary["output"] = {{"h5", writer.path()}, {"xdmf", writer.xdmf_path()}};
  summary["immersed"] = run_immersed_switch_study(c, root, writer);
  if (!world.is_serial()) {
    // What the root sent and waited for (parallel/communication_counters.hpp).
    const CommunicationCounters sent = communication_counters();
    summary["communication_rank0"] = {{"messages", sent.messages},
                                      {"bytes", sent.bytes},
                                      {"exchanges", sent.exchanges},
                                      {"reductions", sent.reductions},
                                      {"wait_cpu_s", sent.wait_cpu_seconds},
                                      {"wait_wall_s", sent.wait_wall_seconds}};
  }
  summary["wall_time_s"] = run_case.elapsed();
  writer.write_metadata({{"case_file", case_file.path()},
                         {"case_name", run_case.name},
                         {"case_text", case_file.text()},
                         {"case_effective", case_file.effective_text()},
                         {"model", "plane_immersed"},
                         {"summary", json_text(summary)}},
                        {{"wall_time_s", run_case.elapsed()}});
  if (!world.is_root()) return 0;
  writer.finish();
  if (options.json) {
    std::cout << json_text(summary) << std::flush;
  } else if (!options.quiet) {
    const Json& j = summary["immersed"];
    if (j.contains("dynamic"))
      std::printf(
          "%s (immersed, gas %s): dynamic pull-in at %.2f V (%.2f V does not), pull-in "
          "time %.3f us%s; %d runs\n",
          run_case.name.c_str(), j["gas"].get<std::string>().c_str(),
          j["dynamic"]["pull_in_voltage"].get<double>(),
          j["dynamic"]["not_pulling_in"].get<double>(),
          1e6 * j["dynamic"]["pull_in_time"].get<double>(),
          time_check_note(j["dynamic"]).c_str(), j["dynamic"]["runs"].get<int>());
    if (j.contains("transient")) {
      // A run that pulled in has a pull-in time and no damping figures (immersed_switch_study).
      const Json& t = j["transient"];
      std::printf("%s (immersed, gas %s): %.1f V, max tip deflection %.4f um, ",
                  run_case.name.c_str(), j["gas"].get<std::string>().c_str(),
                  t["voltage"].get<double>(), 1e6 * t["max_deflection"].get<double>());
      if (t["pulled_in"].get<bool>())
        std::printf("pull-in time %.4f us\n", 1e6 * t["pull_in_time"].get<double>());
      else
        std::printf("damping ratio %.4g\n", t["damping_ratio"].get<double>());
    }
    if (j.contains("static"))
      std::printf("%s (immersed): %.1f V, static tip deflection %.5f um\n", run_case.name.c_str(),
                  j["static"]["voltage"].get<double>(), 1e6 * j["static"]["control"].get<double>());
    if (j.contains("quasi_static"))
      std::printf("%s (immersed): quasi-static pull-in at %.2f V\n", run_case.name.c_str(),
                  j["quasi_static"]["pull_in_voltage"].get<double>());
    std::printf("wrote %s (%.1f s)\n", writer.path().c_str(), run_case.elapsed());
  }
  return 0;
}

int run(const DriverOptions& options) {
  const DriverCase run_case(options);
  const CaseFile& case_file = run_case.file;
  const CaseNode& root = run_case.root;
  const std::string& name = run_case.name;
  const std::string& output = run_case.output;
  auto elapsed = [&] { return run_case.elapsed(); };
  // Under mpirun: the immersed switch with the ESBGK gas on every rank (its gas is
  // distributed); everything else on the root while the other ranks wait.
  const Communicator world = Communicator::world();
  if (root.has("immersed")) {
    const bool distributed =
        root.child_or_empty("gas").get_string("model", "none") == "esbgk" ||
        root.child("immersed").get_bool("electrostatics_distributed", false);
    if (!world.is_root() && !distributed) return 0;
    return run_immersed(run_case, options);
  }
  if (!world.is_root()) return 0;
  const std::string mode =
      root.child("pull_in").get_choice("mode", {"quasi_static", "dynamic", "transient"});
  SwitchScene scene = build_switch_scene(
      root, run_case.dir, mode == "quasi_static" ? AnalysisType::Static : AnalysisType::Transient);
  const PullInSettings settings = read_pull_in_settings(root, scene);
  case_file.check_all_used();  // a typo stops the run here, before any solving

  ResultWriter writer(output, scene.structure->structure_mesh());
  remove_on_interrupt(temp_path_for(output));
  const PullInReport report = run_pull_in_study(scene, settings, writer);

  Json summary;
  summary["case"] = name;
  summary["model"] = scene.structure->kind();
  summary["mesh"] = {{"cells", scene.structure->structure_mesh().n_cells()}};
  summary["output"] = {{"h5", writer.path()}, {"xdmf", writer.xdmf_path()}};
  summary["pull_in"] = pull_in_summary(scene, report);
  summary["coupling"] = {{"scheme", coupling_scheme_name(settings.coupling.scheme)}};
  if (settings.coupling.scheme != CouplingScheme::Monolithic) {
    summary["coupling"]["macro_step"] = settings.coupling.macro_step;
    summary["coupling"]["macro_steps"] = report.macro_steps;
    summary["coupling"]["coupling_iterations"] = report.coupling_iterations;
    if (settings.coupling.scheme == CouplingScheme::StronglyCoupled) {
      summary["coupling"]["tolerance"] = settings.coupling.tolerance;
      summary["coupling"]["max_iterations"] = settings.coupling.max_iterations;
    }
  }
  const ValidityReport validity = switch_scene_validity(root, scene, report);
  if (!options.quiet) print_validity_warnings("rfmems-pullin", validity);
  summary["validity"] = validity.to_json();
  summary["wall_time_s"] = elapsed();
  writer.write_metadata({{"case_file", case_file.path()},
                         {"case_name", name},
                         {"case_text", case_file.text()},
                         {"case_effective", case_file.effective_text()},
                         {"model", scene.structure->kind()},
                         {"electrostatics",
                          summary["pull_in"]["electrostatics"].get<std::string>()},
                         {"dynamic_electrostatics",
                          report.has_dynamic
                              ? summary["pull_in"]["dynamic"]["electrostatics"].get<std::string>()
                              : std::string("none")},
                         {"summary", json_text(summary)}},
                        {{"wall_time_s", elapsed()}});
  writer.finish();

  if (options.json) {
    std::cout << json_text(summary) << std::flush;
  } else if (!options.quiet && report.has_transient) {
    const DynamicRun& r = report.transient;
    std::printf(
        "%s (%s, %s coupling): %.2f V step, centre deflection %.4f um at %.3f us%s; "
        "%ld steps, %ld residual evaluations",
        name.c_str(), scene.structure->kind().c_str(),
        coupling_scheme_name(settings.coupling.scheme).c_str(), settings.transient_voltage,
        r.history.empty() ? 0.0 : r.history.back().control * 1e6, r.final_time * 1e6,
        r.pulled_in ? " (touch-down)" : "", r.stats.steps, r.stats.residual_evals);
    if (settings.coupling.scheme != CouplingScheme::Monolithic)
      std::printf(", %ld coupling passes over %ld macro steps", report.coupling_iterations,
                  report.macro_steps);
    std::printf("\nwrote %s (%.1f s)\n", writer.path().c_str(), elapsed());
  } else if (!options.quiet) {
    const QuasiStaticPullIn& qs = report.quasi_static;
    std::printf("%s (%s, %s): quasi-static pull-in at %.2f V, control deflection %.3f um "
                "(%.1f %% of the gap)\n",
                name.c_str(), scene.structure->kind().c_str(),
                summary["pull_in"]["electrostatics"].get<std::string>().c_str(),
                qs.pull_in_voltage, qs.pull_in_displacement * 1e6,
                -100 * qs.pull_in_displacement / scene.gap);
    if (report.has_pull_out)
      std::printf("  quasi-static pull-out at %.2f V (resting on the dielectric over %.1f %% of the "
                  "electrode just above it)\n",
                  report.pull_out.pull_out_voltage, 100 * report.pull_out.branch.back().contact_fraction);
    if (report.has_dynamic) {
      const std::string time =
          report.dynamic.pull_in_time == 0
              ? std::string("no touch-down by end_time (past the unstable equilibrium)")
              : fmt::format("pull-in time {:.3f} us{}", report.dynamic.pull_in_time * 1e6,
                            time_check_note(summary["pull_in"]["dynamic"]));
      std::printf("  dynamic pull-in (%s voltage, %s%s%s) at %.2f V (%.3f of quasi-static; %.2f V "
                  "does not), %s; %d runs\n",
                  report.waveform.c_str(),
                  summary["pull_in"]["dynamic"]["electrostatics"].get<std::string>().c_str(),
                  report.dynamic_coupling.empty() ? "" : ", ", report.dynamic_coupling.c_str(),
                  report.dynamic.voltage, report.dynamic.voltage / qs.pull_in_voltage,
                  report.dynamic.lower, time.c_str(), report.dynamic.runs);
    }
    if (report.has_release) {
      const DynamicRun& h = report.hold;
      std::printf("  release: step to %.2f V, touch-down at %.3f us, drop to %.2f V at %.3f us: %s",
                  report.release_voltage, report.approach.run.pull_in_time * 1e6,
                  report.hold_voltage, report.approach.drop.t * 1e6,
                  h.released ? "released" : "holds");
      if (h.released) std::printf(" %.3f us later", (h.release_time - report.approach.drop.t) * 1e6);
      std::printf("\n");
      if (report.has_dynamic_pull_out)
        std::printf("  dynamic pull-out at %.2f V (holds; %.2f V releases, %.3f us after the drop); "
                    "%d runs\n",
                    report.dynamic_pull_out.voltage, report.dynamic_pull_out.released,
                    report.dynamic_pull_out.release_time * 1e6, report.dynamic_pull_out.runs);
    }
    std::printf("wrote %s (%.1f s)\n", writer.path().c_str(), elapsed());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return driver_main("rfmems-pullin",
                     "rfmems-pullin: quasi-static and dynamic pull-in of an electrostatic switch",
                     argc, argv, run, RankUse::AllRanks);
}

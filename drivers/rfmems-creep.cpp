// rfmems-creep: creep of a plate structure over hundreds of hours (thesis ch. 4):
// a membrane under a pressure and/or a hold voltage sags as its bending stresses creep; with
// a gap the run reports the switch's creep life (the gap reaches a threshold, or the membrane
// collapses onto the electrode when the held equilibrium disappears). Implicit (IDA) or
// explicit (forward Euler, fixed dt) integration; checkpoints and restart.
//
//   rfmems-creep CASE.yaml [--set KEY=VALUE]... [-o RESULT.h5] [--json] [--quiet]
//                [--restart CHECKPOINT.h5] [--checkpoint-every-steps N]
//                [--checkpoint-every-seconds T] [--hold-voltage-for-gap GAP]
//
// Sample runs:
//   rfmems-creep cases/creep_fixed_fixed/case.yaml          # 500 h, Table 4.1 plate
//   rfmems-creep cases/creep_switch_hold/case.yaml --json   # creep life of a held switch
//   rfmems-creep cases/creep_switch_hold/case.yaml --set actuation.voltage=60V
//   rfmems-creep CASE --checkpoint-every-seconds 60; after a crash: same + --restart FILE
//   rfmems-creep cases/frogleg_varactor/case.yaml --hold-voltage-for-gap 1.43um --json
//
// --hold-voltage-for-gap GAP solves no creep: it finds the hold voltage whose elastic
// equilibrium at t = 0 has the gap g0 + w = GAP at the case's first probe
// (physics/creep/hold_voltage_search.hpp; the case's actuation.voltage, if any, is the first
// trial), prints it (JSON with --json: voltage_V, gap_m, probe, trials) and exits; a GAP not
// below g0, or beyond the pull-in fold, is bad input (exit 2).
//
// Checkpoints go to <result without .h5>.checkpoint.h5 (atomically replaced) at output times
// when a trigger is due; --restart resumes from one and gives bit for bit the result of the
// uninterrupted run (physics/creep/creep_run.hpp). Output: <result>.h5 (+ .xdmf): fields at
// t = 0, every output time and the end of life (physics/creep/creep_plate_model.hpp), the time
// series /creep/history (time, probes' w, min_gap, max_surface_von_mises, max_creep_strain),
// /creep/final_state (the full state at the final time, one row), metadata with the summary.
// Exit codes as the other drivers: 0 success; 2 bad input (one line on stderr, no result
// file); 1 other failures.
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "coupling/scene_validity.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/driver_main.hpp"
#include "io/interrupt_cleanup.hpp"
#include "io/json_summary.hpp"
#include "io/progress.hpp"
#include "io/result_writer.hpp"
#include "io/run_limits.hpp"
#include "io/units.hpp"
#include "physics/creep/creep_case.hpp"
#include "physics/creep/creep_plate_model.hpp"
#include "physics/creep/hold_voltage_search.hpp"

namespace {

using namespace rfmems;

constexpr const char* kProgram = "rfmems-creep";

// The options only this driver has (the shared ones go to driver_main).
struct CreepOptions {
  std::string restart;
  long every_steps = -1;  // -1: the case's value
  double every_seconds = -1;
  std::string hold_voltage_for_gap;  // a length: find the hold voltage and exit
};
CreepOptions creep_options;

// The settings a checkpoint is tied to: the case after overrides, without its checkpoint
// triggers (changing how often to checkpoint must not invalidate a checkpoint).
std::string physics_hash(const CaseFile& file) {
  YAML::Node root = YAML::Load(file.effective_text());
  if (root["creep"] && root["creep"].IsMap()) root["creep"].remove("checkpoint");
  YAML::Emitter out;
  out << root;
  return settings_hash(out.c_str());
}

std::string checkpoint_path_for(const std::string& output) {
  const std::string stem = output.ends_with(".h5") ? output.substr(0, output.size() - 3) : output;
  return stem + ".checkpoint.h5";
}

Json nullable(Real x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

// --hold-voltage-for-gap: the voltage whose elastic gap at the first probe is the given one.
int print_hold_voltage_for_gap(const CreepCase& creep, const DriverOptions& options) {
  const std::string option = "--hold-voltage-for-gap";
  auto bad = [&](const std::string& what) {
    return InputError(
        fmt::format("option '{}' = '{}': {}", option, creep_options.hold_voltage_for_gap, what));
  };
  Real target = 0;
  try {
    target = parse_quantity(creep_options.hold_voltage_for_gap, Dimension::Length);
  } catch (const std::invalid_argument& e) {
    throw bad(e.what());
  }
  if (!creep.has_gap) throw bad("the case has no actuation section (no gap)");
  if (creep.probes.empty()) throw bad("the case has no probe to measure the gap at");
  if (!(target > 0 && target < creep.initial_gap))
    throw bad(fmt::format("must be in (0, actuation.gap = {:.6g} m)", creep.initial_gap));
  HoldVoltageSearchResult r;
  try {
    HoldVoltageSearchOptions search;
    if (creep.hold) search.first_voltage = creep.hold->voltage;  // the case's value: a guess
    r = find_hold_voltage(case_probe_gap(creep, 0), target, search);
  } catch (const SolverError& e) {
    throw bad(e.what());
  }
  if (options.json) {
    Json trials = Json::array();
    for (const HoldVoltageTrial& t : r.trials)
      trials.push_back({{"voltage_V", t.voltage}, {"gap_m", t.gap ? Json(*t.gap) : Json(nullptr)}});
    Json out;
    out["voltage_V"] = r.voltage;
    out["gap_m"] = r.gap;
    out["target_gap_m"] = target;
    out["initial_gap_m"] = creep.initial_gap;
    out["probe"] = creep.probes[0].name;
    out["trials"] = trials;
    std::cout << json_text(out) << std::flush;
  } else {
    std::printf("hold voltage %.9g V: gap %.9g m at probe %s (%zu trials)\n", r.voltage, r.gap,
                creep.probes[0].name.c_str(), r.trials.size());
  }
  return 0;
}

int run(const DriverOptions& options) {
  const DriverCase run_case(options);
  const CaseFile& case_file = run_case.file;
  CreepCase creep = read_creep_case(run_case.root, run_case.dir);
  case_file.check_all_used();  // a typo stops the run here, before any solving
  if (!creep_options.hold_voltage_for_gap.empty())
    return print_hold_voltage_for_gap(creep, options);
  const ValidityReport validity = creep_case_validity(run_case.root, creep);
  if (!options.quiet) print_validity_warnings("rfmems-creep", validity);

  CreepRunSettings& settings = creep.settings;
  settings.checkpoint_path = checkpoint_path_for(run_case.output);
  settings.settings_hash = physics_hash(case_file);
  if (creep_options.every_steps >= 0) settings.checkpoint_every_steps = creep_options.every_steps;
  if (creep_options.every_seconds >= 0)
    settings.checkpoint_every_seconds = creep_options.every_seconds;
  Checkpoint restart;
  if (is_result_path(creep_options.restart))
    throw InputError(
        fmt::format("option '--restart' = '{}': is also the result file (-o {}): the "
                    "run would overwrite the checkpoint it resumes from",
                    creep_options.restart, run_case.output));
  if (!creep_options.restart.empty()) restart = read_checkpoint(creep_options.restart);

  CreepRunModel model = make_plate_creep_model(creep);
  if (creep.hold && creep_options.restart.empty()) {
    // A hold voltage above pull-in has no elastic equilibrium: bad input, not a solver failure.
    try {
      std::vector<Real> y, yp;
      model.make_system()->initial_state(0, y, yp);
    } catch (const std::exception&) {
      run_case.root.child("actuation")
          .fail("voltage",
                "no elastic equilibrium at this hold voltage (above the pull-in voltage?)");
    }
  }

  ProgressReporter progress(options.quiet, settings.end_time());
  model.on_segment = [&](Real t, Real h, long steps) { progress.update(t, h, steps); };
  const CreepRunResult result = run_creep(
      model, settings, creep_options.restart.empty() ? nullptr : &restart, creep_options.restart);
  progress.finish();

  // The result file is written only now: a run killed before leaves no partial result.
  const std::string& output = run_case.output;
  ResultWriter writer(output, *creep.plate->mesh);
  remove_on_interrupt(temp_path_for(output));
  for (std::size_t k = 0; k < result.outputs.size(); ++k)
    write_plate_creep_output(creep, writer, static_cast<int>(k), result.outputs[k]);
  writer.write_time_series("creep", "history", result.series_times, result.series,
                           model.series_columns);
  writer.write_time_series("creep", "final_state", {result.final_time}, {result.state});

  const bool implicit = settings.integration == CreepRunSettings::Integration::Implicit;
  Json summary;
  summary["case"] = run_case.name;
  summary["model"] = creep.structure->kind();
  summary["mesh"] = {{"cells", creep.plate->mesh->n_cells()}};
  summary["integration"] = implicit ? "implicit" : "explicit";
  if (!implicit) summary["dt_s"] = settings.explicit_dt;
  summary["end_time_s"] = settings.end_time();
  summary["final_time_s"] = result.final_time;
  summary["end"] = to_string(result.end);
  summary["life_reached"] = result.life_reached();
  summary["lifetime_s"] = nullable(result.lifetime);
  summary["lifetime_h"] = nullable(result.lifetime / 3600);
  if (!result.message.empty()) summary["solver_message"] = result.message;
  summary["hold_voltage_V"] = creep.hold ? creep.hold->voltage : 0.0;
  if (creep.has_gap) summary["gap_m"] = creep.initial_gap;
  summary["plate_thickness_m"] = creep.plate->section.thickness;
  Json probes = Json::object();
  const std::vector<double>& first = result.series.front();
  const std::vector<double>& last = result.series.back();
  for (std::size_t p = 0; p < creep.probes.size(); ++p)
    probes[creep.probes[p].name] = {{"w_initial", first[p]}, {"w_final", last[p]}};
  summary["probes"] = probes;
  for (std::size_t k = creep.probes.size(); k < model.series_columns.size(); ++k)
    summary["final"][model.series_columns[k]] = last[k];
  if (creep.has_gap) summary["initial_min_gap"] = first[creep.probes.size()];
  summary["steps"] = result.steps;
  summary["segments"] = result.segments;
  summary["n_outputs"] = result.outputs.size();
  summary["restarted"] = result.restarted;
  if (result.restarted) summary["restart_time_s"] = result.restart_time;
  summary["checkpoints_written"] = result.checkpoints_written;
  summary["checkpoint"] = settings.checkpoint_path;
  summary["output"] = {{"h5", writer.path()}, {"xdmf", writer.xdmf_path()}};
  summary["validity"] = validity.to_json();
  summary["wall_time_s"] = run_case.elapsed();
  writer.write_metadata({{"case_file", case_file.path()},
                         {"case_name", run_case.name},
                         {"case_text", case_file.text()},
                         {"case_effective", case_file.effective_text()},
                         {"model", creep.structure->kind()},
                         {"settings_hash", settings.settings_hash},
                         {"summary", json_text(summary)}},
                        {{"wall_time_s", run_case.elapsed()}});
  writer.finish();

  if (options.json) {
    std::cout << json_text(summary) << std::flush;
  } else if (!options.quiet) {
    std::printf("%s (%s creep, %s): %ld steps to t = %.4g h", run_case.name.c_str(),
                creep.structure->kind().c_str(), implicit ? "implicit" : "explicit", result.steps,
                result.final_time / 3600);
    if (!creep.probes.empty())
      std::printf(", %s: w %.4e -> %.4e m", creep.probes[0].name.c_str(), first[0], last[0]);
    std::printf("\n");
    if (result.life_reached())
      std::printf("  creep life %.4g h (%s)\n", result.lifetime / 3600,
                  to_string(result.end).c_str());
    std::printf("wrote %s (%.1f s)\n", writer.path().c_str(), run_case.elapsed());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  auto creep_flags = [](CLI::App& app) {
    app.add_option("--restart", creep_options.restart,
                   "resume from this checkpoint (written for the same case settings)");
    app.add_option("--checkpoint-every-steps", creep_options.every_steps,
                   "write a checkpoint at the first output time after every N steps")
        ->check(check_count);
    app.add_option("--checkpoint-every-seconds", creep_options.every_seconds,
                   "write a checkpoint at the first output time after every T wall seconds")
        ->check(check_finite_non_negative);
    app.add_option("--hold-voltage-for-gap", creep_options.hold_voltage_for_gap,
                   "print the hold voltage whose elastic gap at the first probe is GAP "
                   "(e.g. 1.43um) and exit");
  };
  return driver_main(kProgram,
                     "rfmems-creep: creep of a plate (pressure, hold voltage), creep life, "
                     "checkpoints.",
                     argc, argv, run, RankUse::RootOnly, creep_flags);
}

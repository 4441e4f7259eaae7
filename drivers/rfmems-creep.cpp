// rfmems-creep: creep of a plate structure over hundreds of hours (thesis ch. 4, issue 5):
// a membrane under a pressure and/or a hold voltage sags as its bending stresses creep; with
// a gap the run reports the switch's creep life (the gap reaches a threshold, or the membrane
// collapses onto the electrode when the held equilibrium disappears). Implicit (IDA) or
// explicit (forward Euler, fixed dt) integration; checkpoints and restart.
//
//   rfmems-creep CASE.yaml [--set KEY=VALUE]... [-o RESULT.h5] [--json] [--quiet]
//                [--restart CHECKPOINT.h5] [--checkpoint-every-steps N]
//                [--checkpoint-every-seconds T]
//
// Sample runs:
//   rfmems-creep cases/creep_fixed_fixed/case.yaml          # 500 h, Table 4.1 plate
//   rfmems-creep cases/creep_switch_hold/case.yaml --json   # creep life of a held switch
//   rfmems-creep cases/creep_switch_hold/case.yaml --set actuation.voltage=60V
//   rfmems-creep CASE --checkpoint-every-seconds 60; after a crash: same + --restart FILE
//
// Checkpoints go to <result without .h5>.checkpoint.h5 (atomically replaced) at output times
// when a trigger is due; --restart resumes from one and gives bit for bit the result of the
// uninterrupted run (physics/creep/creep_run.hpp). Output: <result>.h5 (+ .xdmf): fields at
// t = 0, every output time and the end of life (physics/creep/creep_plate_model.hpp), the time
// series /creep/history (time, probes' w, min_gap, max_surface_von_mises, max_creep_strain),
// /creep/final_state (the full state at the final time, one row), metadata with the summary.
// Exit codes as the other drivers: 0 success; 2 bad input (one line on stderr, no result
// file); 1 other failures.
#include <CLI/CLI.hpp>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
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
#include "io/units.hpp"
#include "physics/creep/creep_case.hpp"
#include "physics/creep/creep_plate_model.hpp"

namespace {

using namespace rfmems;

constexpr const char* kProgram = "rfmems-creep";

// The options only this driver has (the shared ones go to driver_main).
struct CreepOptions {
  std::string restart;
  long every_steps = -1;      // -1: the case's value
  double every_seconds = -1;
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

int run(const DriverOptions& options) {
  const DriverCase run_case(options);
  const CaseFile& case_file = run_case.file;
  CreepCase creep = read_creep_case(run_case.root, run_case.dir);
  case_file.check_all_used();  // a typo stops the run here, before any solving
  const ValidityReport validity = creep_case_validity(run_case.root, creep);
  if (!options.quiet) print_validity_warnings("rfmems-creep", validity);

  CreepRunSettings& settings = creep.settings;
  settings.checkpoint_path = checkpoint_path_for(run_case.output);
  settings.settings_hash = physics_hash(case_file);
  if (creep_options.every_steps >= 0) settings.checkpoint_every_steps = creep_options.every_steps;
  if (creep_options.every_seconds >= 0)
    settings.checkpoint_every_seconds = creep_options.every_seconds;
  Checkpoint restart;
  if (!creep_options.restart.empty()) restart = read_checkpoint(creep_options.restart);

  CreepRunModel model = make_plate_creep_model(creep);
  if (creep.hold && creep_options.restart.empty()) {
    // A hold voltage above pull-in has no elastic equilibrium: bad input, not a solver failure.
    try {
      std::vector<Real> y, yp;
      model.make_system()->initial_state(0, y, yp);
    } catch (const std::exception&) {
      run_case.root.child("actuation").fail(
          "voltage", "no elastic equilibrium at this hold voltage (above the pull-in voltage?)");
    }
  }

  ProgressReporter progress(options.quiet, settings.end_time());
  model.on_segment = [&](Real t, Real h, long steps) { progress.update(t, h, steps); };
  const CreepRunResult result = run_creep(model, settings,
                                          creep_options.restart.empty() ? nullptr : &restart,
                                          creep_options.restart);
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
                creep.structure->kind().c_str(), implicit ? "implicit" : "explicit",
                result.steps, result.final_time / 3600);
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
        ->check(CLI::NonNegativeNumber);
    app.add_option("--checkpoint-every-seconds", creep_options.every_seconds,
                   "write a checkpoint at the first output time after every T wall seconds")
        ->check(CLI::NonNegativeNumber);
  };
  return driver_main(kProgram,
                     "rfmems-creep: creep of a plate (pressure, hold voltage), creep life, "
                     "checkpoints.",
                     argc, argv, run, RankUse::RootOnly, creep_flags);
}

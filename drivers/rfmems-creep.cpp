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
// --hold-voltage-for-gap GAP solves no creep: it prints the hold voltage whose elastic gap
// g0 + w at the case's first probe is GAP (the case's actuation.voltage is the first trial)
// and exits; a GAP not below g0, or beyond the pull-in fold, is bad input (exit 2).
// Checkpoints go to <result without .h5>.checkpoint.h5 at output times when a trigger is due;
// --restart resumes from one bit for bit (physics/creep/creep_run.hpp). What the result file
// and the summary hold: physics/creep/creep_results.hpp. Exit codes as the other drivers.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/creep_text.hpp"
#include "io/driver_main.hpp"
#include "io/interrupt_cleanup.hpp"
#include "io/json_summary.hpp"
#include "io/progress.hpp"
#include "io/result_writer.hpp"
#include "io/run_limits.hpp"
#include "physics/creep/creep_case.hpp"
#include "physics/creep/creep_plate_model.hpp"
#include "physics/creep/creep_results.hpp"
#include "physics/creep/creep_validity.hpp"

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

int run(const DriverOptions& options) {
  const DriverCase run_case(options);
  const CaseFile& case_file = run_case.file;
  CreepCase creep = read_creep_case(run_case.root, run_case.dir);
  if (!run_case.finish_reading()) return 0;  // a typo stops the run here, before any solving
  if (!creep_options.hold_voltage_for_gap.empty()) {
    const Json hold =
        hold_voltage_for_gap(creep, "--hold-voltage-for-gap", creep_options.hold_voltage_for_gap);
    if (options.json)
      std::cout << json_text(hold) << std::flush;
    else
      std::fputs(hold_voltage_text(hold).c_str(), stdout);
    return 0;
  }
  const ValidityReport validity = creep_case_validity(creep);
  if (!options.quiet) print_validity_warnings(kProgram, validity);

  CreepRunSettings& settings = creep.settings;
  settings.checkpoint_path = checkpoint_path_for(run_case.output);
  settings.settings_hash = case_settings_hash(case_file, "creep", "checkpoint");
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
  if (creep_options.restart.empty()) check_hold_equilibrium(run_case.root, creep, model);

  ProgressReporter progress(options.quiet, settings.end_time());
  model.on_segment = [&](Real t, Real h, long steps) { progress.update(t, h, steps); };
  const CreepRunResult result = run_creep(
      model, settings, creep_options.restart.empty() ? nullptr : &restart, creep_options.restart);
  progress.finish();

  // The result file is written only now: a run killed before leaves no partial result.
  ResultWriter writer(run_case.output, *creep.plate->mesh);
  remove_on_interrupt(temp_path_for(run_case.output));
  write_creep_results(writer, creep, model, result);
  Json summary = creep_summary(creep, model, result);
  summary["case"] = run_case.name;
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
  if (options.json)
    std::cout << json_text(summary) << std::flush;
  else if (!options.quiet)
    std::printf("%swrote %s (%.1f s)\n", creep_text(summary).c_str(), writer.path().c_str(),
                run_case.elapsed());
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
                     creep_case_keys(), argc, argv, run, RankUse::RootOnly, creep_flags);
}

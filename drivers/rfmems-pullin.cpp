// rfmems-pullin: the pull-in of an electrostatically actuated switch. The case picks one model
// per slot (coupling/scene_combinations.hpp): the structure (a Mindlin-Reissner plate or a
// plane beam), the field that pulls it (the parallel-plate law, the Laplace field in a moving
// gap mesh, or the immersed-boundary field on a background mesh), the gas under it (none, the
// Reynolds film, the ESBGK kinetic gas), the analysis and the coupling scheme; the coupling
// manager (coupling/coupling_manager.hpp) runs the one pull-in study
// (coupling/pull_in_study.hpp):
//   static:       the equilibrium at a voltage;
//   quasi_static: the deflection-voltage curve through its fold under displacement control:
//                 the static pull-in voltage;
//   dynamic:      a voltage waveform from rest with contact, turning-back, settled and
//                 past-the-fold events; the dynamic pull-in voltage by bisection, the pull-in
//                 time and its error estimate, the histories around it and the small-signal
//                 response; with actuation.contact the pull-out and release;
//   transient:    one step voltage from rest to an end time or touch-down.
//
// Sample runs:
//   rfmems-pullin cases/switch_plate/case.yaml                  # dynamic, prints V_PI and t_PI
//   rfmems-pullin cases/switch_plane_laplace/case.yaml --json   # quasi-static, Laplace
//   rfmems-pullin cases/switch_plate/case.yaml --set pull_in.mode=quasi_static
//   rfmems-pullin cases/cantilever_switch/case.yaml             # immersed-boundary cantilever
//   mpirun -np 2 rfmems-pullin cases/cantilever_switch/case.yaml --set gas.model=esbgk
//       --set pull_in.mode=transient   # the ESBGK gas distributed over 2 ranks
//   rfmems-pullin cases/switch_plate/case.yaml --set pull_in.mode=transient
//       --set pull_in.transient.voltage=180V --set pull_in.transient.end_time=5us
//       --set coupling.scheme=strongly_coupled
//   rfmems-pullin --scenes                                      # what a scene can combine
//
// Output: out/<name>.h5 (+ .xdmf): the structure's fields (step 0), /pull_in/curve and
// /dynamic/<run> (coupling/pull_in_results.hpp); --json prints the summary. Exit codes as
// rfmems-solid: 0 success; 2 bad input (one line on stderr, no result file); 1 other failures.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <string>

#include "coupling/pull_in_study.hpp"
#include "coupling/scene_combinations.hpp"
#include "coupling/switch_scene.hpp"
#include "coupling/switch_validity.hpp"
#include "io/atomic_file.hpp"
#include "io/case_file.hpp"
#include "io/driver_main.hpp"
#include "io/interrupt_cleanup.hpp"
#include "io/json_summary.hpp"
#include "io/pull_in_text.hpp"
#include "io/result_writer.hpp"
#include "parallel/communication_counters.hpp"
#include "parallel/communicator.hpp"

namespace {

using namespace rfmems;

// Under mpirun the immersed field with the ESBGK gas (or its distributed electrostatics) runs on
// every rank, its gas (field) distributed over them, the rest computed redundantly from the same
// data; every other scene runs on the root while the other ranks wait. The root writes the
// result; the others write to a scratch file of their own that is never finished (deleted on
// exit).
bool runs_on_every_rank(const CaseNode& root) {
  const SceneModels models = read_scene_choice(root).models;
  return models.field == FieldModel::Immersed &&
         (models.gas == GasModel::Esbgk || immersed_electrostatics_distributed(root));
}

int run(const DriverOptions& options) {
  const DriverCase run_case(options);
  const CaseFile& case_file = run_case.file;
  const CaseNode& root = run_case.root;
  const Communicator world = Communicator::world();
  if (!world.is_root() && !runs_on_every_rank(root)) return 0;
  SwitchScene scene = build_switch_scene(root, run_case.dir);
  PullInSettings settings = read_pull_in_settings(root, scene);
  if (!options.quiet && world.is_root()) settings.progress = stderr;
  if (!run_case.finish_reading()) return 0;  // a typo stops the run here, before any solving

  const std::string output =
      world.is_root() ? run_case.output : run_case.output + ".rank" + std::to_string(world.rank());
  ResultWriter writer(output, scene.structure->structure_mesh());
  remove_on_interrupt(temp_path_for(output));
  const PullInReport report = run_pull_in_study(scene, settings, writer);

  Json summary;
  summary["case"] = run_case.name;
  summary["ranks"] = world.size();
  summary["model"] = scene.structure->kind();
  summary["mesh"] = {{"cells", scene.structure->structure_mesh().n_cells()}};
  summary["output"] = {{"h5", writer.path()}, {"xdmf", writer.xdmf_path()}};
  summary["pull_in"] = pull_in_summary(scene, settings, report);
  if (!world.is_serial()) {
    // What this rank sent and waited for (parallel/communication_counters.hpp).
    const CommunicationCounters sent = communication_counters();
    summary["communication_rank0"] = {
        {"messages", sent.messages},           {"bytes", sent.bytes},
        {"exchanges", sent.exchanges},         {"reductions", sent.reductions},
        {"wait_cpu_s", sent.wait_cpu_seconds}, {"wait_wall_s", sent.wait_wall_seconds}};
  }
  const ValidityReport validity = switch_scene_validity(scene, report);
  if (!options.quiet && world.is_root()) print_validity_warnings("rfmems-pullin", validity);
  summary["validity"] = validity.to_json();
  summary["wall_time_s"] = run_case.elapsed();
  writer.write_metadata({{"case_file", case_file.path()},
                         {"case_name", run_case.name},
                         {"case_text", case_file.text()},
                         {"case_effective", case_file.effective_text()},
                         {"model", scene.structure->kind()},
                         {"electrostatics", field_name(scene.field())},
                         {"summary", json_text(summary)}},
                        {{"wall_time_s", run_case.elapsed()}});
  if (!world.is_root()) return 0;
  writer.finish();
  if (options.json) {
    std::cout << json_text(summary) << std::flush;
  } else if (!options.quiet) {
    std::cout << pull_in_text(run_case.name, summary["pull_in"]);
    std::printf("wrote %s (%.1f s)\n", writer.path().c_str(), run_case.elapsed());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return driver_main("rfmems-pullin",
                     "rfmems-pullin: quasi-static and dynamic pull-in of an electrostatic switch",
                     join_schemas({switch_case_keys(), pull_in_case_keys()}), argc, argv, run,
                     RankUse::AllRanks, [](CLI::App& app) {
                       app.add_flag_callback(
                           "--scenes",
                           [] {
                             std::cout << scene_table_markdown();
                             throw CLI::Success();
                           },
                           "print the table of what a scene can combine and exit");
                     });
}

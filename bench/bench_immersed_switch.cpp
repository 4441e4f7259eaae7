// The immersed-boundary cantilever switch (cases/cantilever_switch): cost per coupled
// step split by physics, and the error of the staggered coupling against the implicit one and
// against a tighter tolerance.
//
// For the case (optionally --set overrides, as rfmems-pullin takes them) and a step voltage:
//   run "staggered"  the case's run (IBM load refreshed after each IDA step)
//   run "tight"      the same with rtol and atol / 10
//   run "implicit"   the IBM load inside every residual (--implicit)
//   run "fresh_lu"   the case's run with a fresh electrostatic LU per evaluation (--fresh-lu;
//                    the default keeps KLU's analysis while the pattern holds): per-call
//                    electrostatics CPU of both, in one process
// (--no-tight skips the tight run)
// one JSON line each: max tip deflection, pull-in time (if any), steps, IBM evaluations, CPU
// seconds per physics (move, marking, interpolation, electrostatics, transfer, gas, structure)
// and per step, and the ratios to the first run's CPU. Then a line of differences.
//
//   build/bench/bench_immersed_switch cases/cantilever_switch/case.yaml --voltage 80
//       --end-time 2e-6 [--set "mesh.cells=[46, 4]" ...] [--implicit] [--gas reynolds]
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "bench_support.hpp"
#include "coupling/field_coupled_structure.hpp"
#include "coupling/pull_in_study.hpp"
#include "coupling/switch_scene.hpp"
#include "io/case_file.hpp"
#include "physics/elasticity/elasticity_scene.hpp"

using namespace rfmems;

int main(int argc, char** argv) {
  CLI::App app{"immersed cantilever switch: cost split and coupling error"};
  std::string path;
  std::vector<std::string> sets;
  double voltage = 80, end_time = 2e-6;
  bool implicit = false, fresh_lu = false, no_tight = false;
  std::string gas = "none";
  app.add_option("case", path)->required();
  app.add_option("--set", sets, "key=value overrides");
  app.add_option("--voltage", voltage);
  app.add_option("--end-time", end_time);
  app.add_flag("--implicit", implicit, "also the implicit run (IBM in every residual)");
  app.add_flag("--fresh-lu", fresh_lu, "also the run with a fresh electrostatic LU per call");
  app.add_flag("--no-tight", no_tight, "skip the tight-tolerance run");
  app.add_option("--gas", gas, "none | reynolds | esbgk");
  CLI11_PARSE(app, argc, argv);
  sets.push_back("gas.model=" + gas);
  sets.push_back("pull_in.mode=transient");
  sets.push_back("pull_in.transient.voltage=" + std::to_string(voltage));
  sets.push_back("pull_in.transient.end_time=" + std::to_string(end_time));

  const CaseFile file = CaseFile::load(path, sets);
  const CaseNode root = file.root();
  const std::string dir = path.substr(0, path.find_last_of('/') + 1);
  SwitchScene scene = build_switch_scene(root, dir.empty() ? "." : dir);
  if (!scene.immersed) throw InputError("bench_immersed_switch needs an immersed case");
  ImmersedField& field = *scene.immersed;
  DynamicOptions run = read_pull_in_settings(root, scene).transient_run;
  run.output_interval = end_time / 400;

  struct Result {
    std::string name;
    DynamicRun run;
    ImmersedPhysicsTimes times;
    CoupledRunTimes loop;
    double wall;
    double cpu() const { return times.total() + loop.gas + loop.structure; }
  };
  std::vector<Result> results;
  FieldCoupledStructure beam(*dynamic_cast<ElasticityScene&>(*scene.structure).op, *field.sw,
                             field.sw->control());
  auto go = [&](const std::string& name, DynamicOptions o) {
    field.sw->reset_times();
    beam.reset_times();
    std::unique_ptr<StructureGas> g = field.make_gas();
    const double w0 = bench::now();
    DynamicRun history = beam.run(voltage, o, g.get());
    results.push_back(
        {name, std::move(history), field.sw->times(), beam.times(), bench::now() - w0});
    const Result& r = results.back();
    const ImmersedPhysicsTimes& t = r.times;
    const double cpu = r.cpu();
    nlohmann::json j;
    j["bench"] = "immersed_switch";
    j["run"] = name;
    j["case"] = path;
    j["overrides"] = sets;
    j["voltage"] = voltage;
    j["end_time"] = end_time;
    j["beam_cells"] = scene.structure->structure_mesh().n_cells();
    j["background_cells"] = {field.geometry.background_cells[0],
                             field.geometry.background_cells[1]};
    j["max_tip_deflection"] = -r.run.extreme_control;
    j["pulled_in"] = r.run.pulled_in;
    j["pull_in_time"] = r.run.pull_in_time;
    j["damping_ratio"] = free_response(r.run.history).damping_ratio;
    j["steps"] = r.run.stats.steps;
    j["ibm_evaluations"] = t.load_evaluations;
    j["electrostatic_analyses"] = t.electrostatic_analyses;
    j["electrostatics_cpu_ms_per_evaluation"] =
        1e3 * t.electrostatics / std::max(1L, t.load_evaluations);
    j["cpu_s"] = {{"move", t.move},
                  {"marking", t.marking},
                  {"interpolation", t.interpolation},
                  {"electrostatics", t.electrostatics},
                  {"transfer", t.transfer},
                  {"gas", r.loop.gas},
                  {"structure", r.loop.structure},
                  {"total", cpu}};
    j["cpu_ms_per_step"] = 1e3 * cpu / std::max(1L, r.run.stats.steps);
    j["cpu_ratio_to_first"] = cpu / std::max(1e-12, results.front().cpu());
    j["wall_s"] = r.wall;
    double load[3] = {0, 0, 0};
    if (getloadavg(load, 3) < 1) load[0] = -1;
    j["load_average_1min"] = load[0];
    bench::emit(j);
  };
  go("staggered", run);
  if (fresh_lu) {
    field.sw->set_electrostatics_lu(LuReuse::Fresh);
    go("fresh_lu", run);
    field.sw->set_electrostatics_lu(LuReuse::Reuse);
  }
  if (!no_tight) {
    DynamicOptions tight = run;
    tight.ida.rtol /= 10;
    tight.ida.atol /= 10;
    go("tight", tight);
  }
  if (implicit) {
    DynamicOptions o = run;
    o.coupling.scheme = CouplingScheme::Implicit;
    go("implicit", o);
  }
  nlohmann::json d;
  d["bench"] = "immersed_switch_errors";
  const DynamicRun& a = results[0].run;
  for (std::size_t i = 1; i < results.size(); ++i) {
    const DynamicRun& b = results[i].run;
    d["staggered_vs_" + results[i].name] = {
        {"max_tip_relative", a.extreme_control / b.extreme_control - 1},
        {"pull_in_time_relative", b.pull_in_time > 0 ? a.pull_in_time / b.pull_in_time - 1 : 0.0}};
  }
  bench::emit(d);
  return 0;
}

// rfmems-solid: linear elastodynamics and elastostatics of a solid (beams, plates, 3D bodies)
// with the cell-centred FV elasticity operator. Reads a case file, builds the scene, runs a
// static (KINSOL or segregated) or transient (IDA) analysis, writes an HDF5 + XDMF result.
//
// Sample runs:
//   rfmems-solid cases/cantilever_vibration/case.yaml          # -> out/cantilever_vibration.h5
//   rfmems-solid cases/cantilever_static/case.yaml --json --quiet
//   rfmems-solid cases/cantilever_static/case.yaml --set mesh.cells=[320,32] -o out/fine.h5
//
// Exit codes: 0 success; 2 bad input (case file, option, mesh file): one line
// "rfmems-solid: <message>" on stderr and no result file; 1 any other failure.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/case_file.hpp"
#include "io/interrupt_cleanup.hpp"
#include "io/json_summary.hpp"
#include "io/probes.hpp"
#include "io/progress.hpp"
#include "physics/elasticity/elasticity_analysis.hpp"
#include "physics/elasticity/elasticity_results.hpp"
#include "physics/elasticity/elasticity_scene.hpp"

namespace {

namespace fs = std::filesystem;
using namespace rfmems;

struct Options {
  std::string case_path;
  std::vector<std::string> overrides;
  std::string output;
  bool json = false;
  bool quiet = false;
};

// Messages go out on one line, whatever the text inside them holds.
void print_error(const std::string& message) {
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  std::fprintf(stderr, "rfmems-solid: %s\n", line.c_str());
}

int run(const Options& options) {
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };

  const CaseFile case_file = CaseFile::load(options.case_path, options.overrides);
  const CaseNode root = case_file.root();
  const fs::path case_dir = fs::absolute(options.case_path).parent_path();
  const std::string name = root.get_string("name", case_dir.filename().string());

  const AnalysisType type = read_analysis_type(root);
  ElasticityScene scene = build_elasticity_scene(root, case_dir.string(), type);
  const AnalysisSettings settings = read_analysis_settings(root, scene);
  std::vector<Probe> probes = read_probes(root.child_or_empty("probes"), *scene.mesh);
  case_file.check_all_used();  // a typo stops the run here, before any solving

  const std::string output = options.output.empty() ? "out/" + name + ".h5" : options.output;
  ElasticityResults results(output, scene, std::move(probes));
  remove_on_interrupt(temp_path_for(output));  // exceptions clean up; signals need this
  ProgressReporter progress(options.quiet || type == AnalysisType::Static, settings.end_time);
  const AnalysisStats stats = run_analysis(scene, settings, results, progress);
  progress.finish();
  results.finish(case_file, name, stats, elapsed());

  const Json summary = elasticity_summary(name, scene, results, stats, elapsed());
  if (options.json) {
    std::cout << json_text(summary) << std::flush;
  } else if (!options.quiet) {
    for (const auto& [probe, value] : summary["probes"].items()) {
      std::printf("probe %s: ux = %.6e m, uy = %.6e m", probe.c_str(), value["ux"].get<double>(),
                  value["uy"].get<double>());
      if (scene.mesh->dim() == 3) std::printf(", uz = %.6e m", value["uz"].get<double>());
      std::printf("\n");
    }
    std::printf("wrote %s and %s (%.1f s)\n", results.path().c_str(),
                results.xdmf_path().c_str(), elapsed());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"rfmems-solid: static and transient linear elasticity of a solid (FV)"};
  app.add_option("case", options.case_path, "case file (YAML)")->required();
  app.add_option("--set", options.overrides,
                 "override a case key, e.g. --set mesh.cells=[320,32] (repeatable)")
      ->allow_extra_args(false);
  app.add_option("-o,--output", options.output,
                 "result file (default out/<case name>.h5; an .xdmf is written beside it)");
  app.add_flag("--json", options.json, "print a JSON summary on stdout");
  app.add_flag("--quiet", options.quiet, "no progress or summary lines");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    print_error(std::string(e.what()) + " (see --help)");
    return 2;
  }

  try {
    return run(options);
  } catch (const InputError& e) {  // also MeshError
    print_error(e.what());
    return 2;
  } catch (const std::exception& e) {
    print_error(std::string("error: ") + e.what());
    return 1;
  }
}

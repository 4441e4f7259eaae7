// rfmems-flow-factor: the Poiseuille flow factor Q(Kn) = G / (delta / 6) of the kinetic gas
// over a list of Kn (physics/gas/kinetic/poiseuille_flow_factor.hpp), written as the table the
// Reynolds film reads with `gas.rarefaction: table` (materials/flow_factor_table.hpp).
//
// Sample runs:
//   rfmems-flow-factor cases/flow_factor/case.yaml -o docs/data/flow_factor_bgk.csv
//   rfmems-flow-factor cases/flow_factor/case.yaml --set gas.collision=esbgk --json --quiet
//
// Output: a CSV file (-o, default out/<case name>.csv) written atomically, its '#' header
// holding the command, the date and the case; --json prints the rows. Exit codes as every
// driver: 0 success; 2 bad input (one line on stderr, no table); 1 other failures (a point
// that does not converge).
#include <fmt/chrono.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/driver_main.hpp"
#include "io/json_summary.hpp"
#include "physics/gas/kinetic/kinetic_case.hpp"
#include "physics/gas/kinetic/poiseuille_flow_factor.hpp"

namespace {

using namespace rfmems;

constexpr const char* kProgram = "rfmems-flow-factor";

int run(const DriverOptions& options) {
  const DriverCase run_case(options);
  const std::vector<FlowFactorPoint> points =
      read_flow_factor_points(run_case.root.child("flow_factor"));
  // Every other key is the channel's: building it once checks them all before any solving.
  build_kinetic_scene(run_case.root, run_case.dir);
  if (!run_case.finish_reading()) return 0;

  std::vector<FlowFactorResult> results;
  for (const FlowFactorPoint& point : points) {
    results.push_back(compute_flow_factor(options.case_path, options.overrides, point));
    const FlowFactorResult& r = results.back();
    if (!options.quiet)
      std::fprintf(stderr,
                   "%s: Kn = %-9.4g delta = %-9.4g G = %.6f  Q = %.6f  (%d sweeps, %.1f s)\n",
                   kProgram, point.knudsen, r.rarefaction_parameter, r.flow_rate, r.flow_factor,
                   r.sweeps, r.seconds);
  }

  // One header line: an override's own line breaks become spaces.
  std::string command = fmt::format("{} {}", kProgram, options.case_path);
  for (std::string s : options.overrides) {
    std::replace(s.begin(), s.end(), '\n', ' ');
    command += " --set '" + s + "'";
  }
  const std::string output =
      std::filesystem::path(run_case.output).replace_extension(".csv").string();
  const std::vector<std::string> header = {
      "Poiseuille flow factor Q(Kn) = G / (delta / 6) of the kinetic gas (rfmems-flow-factor)",
      "command: " + command + " -o " + output,
      fmt::format("date: {:%Y-%m-%d %H:%M} UTC, {:.1f} s wall", std::chrono::system_clock::now(),
                  run_case.elapsed()),
      "Kn = lambda / H = sqrt(pi) / (2 delta), lambda = (mu / p) sqrt(pi R T / 2); G the "
      "normalised flow rate"};
  create_parent_directory(output);
  write_file_atomic(output, flow_factor_csv(results, header));

  if (options.json) {
    Json rows = Json::array();
    for (const FlowFactorResult& r : results)
      rows.push_back({{"knudsen", r.point.knudsen},
                      {"delta", r.rarefaction_parameter},
                      {"flow_rate", r.flow_rate},
                      {"flow_factor", r.flow_factor},
                      {"cells", r.point.cells},
                      {"velocity_points", r.point.velocity_points},
                      {"sweeps", r.sweeps},
                      {"seconds", r.seconds}});
    std::cout << json_text({{"case", run_case.name},
                            {"output", output},
                            {"points", rows},
                            {"wall_time_s", run_case.elapsed()}})
              << std::flush;
  } else if (!options.quiet) {
    std::printf("wrote %s (%zu points, %.1f s)\n", output.c_str(), results.size(),
                run_case.elapsed());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return driver_main(kProgram,
                     "rfmems-flow-factor: the Poiseuille flow factor Q(Kn) of the kinetic gas",
                     join_schemas({kinetic_case_keys(), flow_factor_case_keys()}), argc, argv, run);
}

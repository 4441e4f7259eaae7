#include "io/driver_main.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>

#include "core/error.hpp"
#include "parallel/communicator.hpp"

namespace rfmems {

DriverCase::DriverCase(const DriverOptions& options)
    : file(CaseFile::load(options.case_path, options.overrides)),
      root(file.root()),
      start_(std::chrono::steady_clock::now()) {
  const std::filesystem::path path = std::filesystem::absolute(options.case_path).parent_path();
  dir = path.string();
  name = root.get_string("name", path.filename().string());
  output = options.output.empty() ? "out/" + name + ".h5" : options.output;
}

double DriverCase::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void print_driver_error(const std::string& program, const std::string& message) {
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  std::fprintf(stderr, "%s: %s\n", program.c_str(), line.c_str());
}

namespace {

int parse_and_run(const std::string& program, const std::string& description, int argc,
                  char** argv, const std::function<int(const DriverOptions&)>& run,
                  const ExtraOptions& extra_options, bool distributed) {
  DriverOptions options;
  CLI::App app{description};
  app.add_option("case", options.case_path, "case file (YAML)")->required();
  app.add_option("--set", options.overrides,
                 "override a case key, e.g. --set mesh.cells=[320,32] (repeatable)")
      ->allow_extra_args(false);
  app.add_option("-o,--output", options.output,
                 "result file (default out/<case name>.h5; an .xdmf is written beside it)");
  app.add_flag("--json", options.json, "print a JSON summary on stdout");
  app.add_flag("--quiet", options.quiet, "no progress or summary lines");
  if (extra_options) extra_options(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    print_driver_error(program, std::string(e.what()) + " (see --help)");
    return 2;
  }
  const Communicator world = Communicator::world();
  try {
    return run(options);
  } catch (const InputError& e) {  // also MeshError
    // Every rank reads the same input and fails alike: one line, from the root.
    if (world.is_root()) print_driver_error(program, e.what());
    return 2;
  } catch (const std::exception& e) {
    print_driver_error(program, std::string("error: ") + e.what());
    // A solver failure may hit one rank only (a ghost exchange, a reduction or an IDA step
    // the others are inside): they would wait for it for ever, so the job ends here. The
    // result file is written through a temporary and renamed, so nothing half is left.
    if (distributed && !world.is_serial()) world.abort(1);
    return 1;
  }
}

}  // namespace

int driver_main(const std::string& program, const std::string& description, int argc,
                char** argv, const std::function<int(const DriverOptions&)>& run,
                RankUse ranks, const ExtraOptions& extra_options) {
  MpiSession session(&argc, &argv);
  const Communicator world = Communicator::world();
  Index code = 0;
  if (ranks == RankUse::AllRanks || world.is_root())
    code = parse_and_run(program, description, argc, argv, run, extra_options,
                         ranks == RankUse::AllRanks);
  // One verdict for every rank: the worst (the root's, when only the root runs).
  return static_cast<int>(world.max(code));
}

}  // namespace rfmems

#include "io/driver_main.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <new>

#include "core/error.hpp"
#include "io/case_schema_yaml.hpp"
#include "io/run_limits.hpp"
#include "io/units.hpp"
#include "parallel/communicator.hpp"

namespace rfmems {

namespace {

namespace fs = std::filesystem;

// Bad input about the result path: "option '-o' = '<path>': <what>" (the default path is
// named as such).
[[noreturn]] void fail_output(const DriverOptions& options, const std::string& output,
                              const std::string& what) {
  if (options.output.empty())
    throw InputError(fmt::format("result file '{}' (out/<case name>.h5): {}", output, what));
  throw InputError(fmt::format("option '-o' = '{}': {}", output, what));
}

// The result's directory (or, if it is yet to be made, its nearest existing ancestor) takes a
// new file: one is created there and removed, so that an unwritable path stops the run before
// any solving rather than after it.
void check_writable(const DriverOptions& options, const std::string& output) {
  std::error_code ec;
  if (fs::is_directory(output, ec)) fail_output(options, output, "is a directory");
  fs::path dir = fs::absolute(output, ec).parent_path();
  while (!dir.empty() && !fs::exists(dir, ec) && dir != dir.parent_path()) dir = dir.parent_path();
  if (!fs::is_directory(dir, ec))
    fail_output(options, output, dir.string() + " is not a directory");
  const std::string probe =
      (dir / fmt::format(".rfmems-write-probe-{}", static_cast<long>(::getpid()))).string();
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0)
    fail_output(options, output,
                fmt::format("cannot create a file in {}: {}", dir.string(), std::strerror(errno)));
  ::close(fd);
  ::unlink(probe.c_str());
}

// The keys DriverCase reads for every driver (driver_main.keys.yaml).
CaseSchema run_case_keys() { return embedded_case_schema("io/driver_main.keys.yaml"); }

}  // namespace

DriverCase::DriverCase(const DriverOptions& options)
    : file(CaseFile::load(options.case_path, options.overrides)),
      root(file.root()),
      check_only_(options.check_only),
      start_(std::chrono::steady_clock::now()) {
  file.declare_schema(options.schema);
  const fs::path path = fs::absolute(options.case_path).parent_path();
  dir = path.string();
  name = root.get_string("name", path.filename().string());
  // The name becomes out/<name>.h5: a path (../x), an empty name or a dot name would put the
  // result elsewhere or hide it.
  if (root.has("name"))
    root.require(!name.empty() && name != "." && name != ".." &&
                     name.find_first_of("/\\") == std::string::npos,
                 "name", "a case name must be a plain, non-empty file name (no '/')");
  output = options.output.empty() ? "out/" + name + ".h5" : options.output;
  set_result_path(output);
  if (is_result_path(options.case_path))
    fail_output(options, output, "is the case file: the run would overwrite its input");
  check_writable(options, output);
}

bool DriverCase::finish_reading() const {
  file.check_all_used();
  return !check_only_;
}

double DriverCase::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string check_finite_non_negative(const std::string& text) {
  double x = 0;
  if (!parse_real(text, x) || x < 0) return "must be a finite number >= 0, not '" + text + "'";
  return "";
}

std::string check_count(const std::string& text) {
  double x = 0;
  if (!parse_real(text, x) || x < 0 || x != std::floor(x) || x > 9.0e15)
    return fmt::format("must be an integer in [0, {:g}], not '{}'", 9.0e15, text);
  return "";
}

void print_driver_error(const std::string& program, const std::string& message) {
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  std::fprintf(stderr, "%s: %s\n", program.c_str(), line.c_str());
}

namespace {

int parse_and_run(const std::string& program, const std::string& description,
                  const CaseSchema& schema, int argc, char** argv,
                  const std::function<int(const DriverOptions&)>& run,
                  const ExtraOptions& extra_options, bool distributed) {
  DriverOptions options;
  options.schema = join_schemas({run_case_keys(), schema});
  CLI::App app{description};
  app.add_option("case", options.case_path, "case file (YAML)")->required();
  app.add_option("--set", options.overrides,
                 "override a case key, e.g. --set mesh.cells=[320,32] (repeatable)")
      ->allow_extra_args(false);
  CLI::Option* output =
      app.add_option("-o,--output", options.output,
                     "result file (default out/<case name>.h5; an .xdmf is written beside it)");
  std::uint64_t max_memory = 0;
  app.add_option("--max-memory", max_memory,
                 "memory the run may use, e.g. '4 GiB' (default: MemAvailable of /proc/meminfo); "
                 "a case estimated to need more is refused")
      ->transform(CLI::AsSizeValue(true))
      ->check(CLI::Range(std::uint64_t{1}, std::numeric_limits<std::uint64_t>::max()));
  app.add_flag("--json", options.json, "print a JSON summary on stdout");
  app.add_flag("--quiet", options.quiet, "no progress or summary lines");
  app.add_flag("--check", options.check_only,
               "read the case and build the model, then exit without solving (0: the case is "
               "valid)");
  app.add_flag_callback(
      "--help-case",
      [&] {
        std::fputs(format_case_schema(program, options.schema).c_str(), stdout);
        throw CLI::Success();
      },
      "print every case key this program reads (type, unit, default, allowed, meaning) and "
      "exit");
  if (extra_options) extra_options(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    print_driver_error(program, std::string(e.what()) + " (see --help)");
    return 2;
  }
  if (output->count() > 0 && options.output.empty()) {
    print_driver_error(program, "option '-o' = '': expected a file name (see --help)");
    return 2;
  }
  set_memory_limit(max_memory);
  const Communicator world = Communicator::world();
  try {
    return run(options);
  } catch (const InputError& e) {  // also MeshError
    // Every rank reads the same input and fails alike: one line, from the root.
    if (world.is_root()) print_driver_error(program, e.what());
    return 2;
  } catch (const std::exception& e) {
    // Memory ran out although the case's estimate fitted (or the case has no estimate): say
    // so plainly rather than "std::bad_alloc".
    if (dynamic_cast<const std::bad_alloc*>(&e))
      print_driver_error(
          program,
          fmt::format("error: out of memory (limit {}, {}); try a coarser mesh",
                      format_bytes(static_cast<double>(memory_limit())), memory_limit_source()));
    else
      print_driver_error(program, std::string("error: ") + e.what());
    // A solver failure may hit one rank only (a ghost exchange, a reduction or an IDA step
    // the others are inside): they would wait for it for ever, so the job ends here. The
    // result file is written through a temporary and renamed, so nothing half is left.
    if (distributed && !world.is_serial()) world.abort(1);
    return 1;
  }
}

}  // namespace

int driver_main(const std::string& program, const std::string& description,
                const CaseSchema& schema, int argc, char** argv,
                const std::function<int(const DriverOptions&)>& run, RankUse ranks,
                const ExtraOptions& extra_options) {
  MpiSession session(&argc, &argv);
  const Communicator world = Communicator::world();
  Index code = 0;
  if (ranks == RankUse::AllRanks || world.is_root())
    code = parse_and_run(program, description, schema, argc, argv, run, extra_options,
                         ranks == RankUse::AllRanks);
  // One verdict for every rank: the worst (the root's, when only the root runs).
  return static_cast<int>(world.max(code));
}

}  // namespace rfmems

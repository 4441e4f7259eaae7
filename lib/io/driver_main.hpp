// The command line every rfmems driver shares:
//
//   <program> CASE.yaml [--set KEY=VALUE]... [-o RESULT.h5] [--json] [--quiet]
//             [--max-memory SIZE] [--check]
//   <program> --help-case
//
// --help-case prints the driver's case schema (every key its readers accept, with type, unit,
// default, allowed values and meaning: io/case_schema.hpp) and exits 0. --check reads the case
// and builds the model, so that every key is checked, and exits 0 before any solving.
//
// and its error contract: bad input (InputError, MeshError, a bad option) prints one line
// "<program>: <message>" on stderr and exits 2; any other failure exits 1 (running out of
// memory too, with a line saying so); --help exits 0.
//
// Checked before any solving, as bad input: the result path (-o, not empty) is not the case
// file nor any other input (the mesh file, a checkpoint to resume from: io/run_limits.hpp), and
// a file can be created in its directory; a structured mesh's memory estimate fits in
// --max-memory (default: MemAvailable).
//
// Under mpirun every driver starts MPI. A driver whose physics is distributed runs on every
// rank (RankUse::AllRanks); the others (a structure small enough for one rank) run on the root
// while the other ranks wait, so `mpirun -np P` gives the serial answer and one output file.
// Every rank exits with the root's code. A failure other than bad input while every rank runs
// may be on one rank alone, with the others inside a collective: that rank prints its line and
// ends the whole job (MPI_Abort, exit 1) rather than leave them waiting.
#pragma once
#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "io/case_file.hpp"

namespace CLI {
class App;
}

namespace rfmems {

struct DriverOptions {
  std::string case_path;
  std::vector<std::string> overrides;
  std::string output;  // empty: out/<case name>.h5
  bool json = false;
  bool quiet = false;
  bool check_only = false;  // --check
  CaseSchema schema;        // the driver's
};

// The case a driver runs: loaded with the overrides, its directory (for relative mesh files),
// its name (`name:`, a plain file name, else the directory's name), the result path (-o, else
// out/<name>.h5; checked as above and made the run's result_path()), and the wall clock since
// loading began.
struct DriverCase {
  explicit DriverCase(const DriverOptions& options);
  CaseFile file;
  CaseNode root;
  std::string dir, name, output;
  double elapsed() const;
  // Once the readers are done: every key of the case must have been read (a typo stops the
  // run here, before any solving; the tests also check the reads against the schema). False
  // under --check: the case is valid and the run ends here.
  bool finish_reading() const;

 private:
  bool check_only_;
  std::chrono::steady_clock::time_point start_;
};

enum class RankUse { RootOnly, AllRanks };

// Options only one driver has: it adds them to the parser (CLI11) before parsing, with their
// own checks (a failed check is bad input: exit 2).
using ExtraOptions = std::function<void(CLI::App&)>;

// Parses the command line and calls run(options), mapping exceptions to exit codes. `schema`
// lists the case keys the driver's readers accept.
int driver_main(const std::string& program, const std::string& description,
                const CaseSchema& schema, int argc, char** argv,
                const std::function<int(const DriverOptions&)>& run,
                RankUse ranks = RankUse::RootOnly, const ExtraOptions& extra_options = {});

// A CLI11 check for a numeric option: a finite number >= 0 ("" if it is one, else why not).
// CLI::NonNegativeNumber lets NaN through (and its message prints DBL_MAX in 309 digits).
std::string check_finite_non_negative(const std::string& text);
// The same for a count: an integer >= 0 (a real with an integral value, 1e3, is one).
std::string check_count(const std::string& text);

// "<program>: <message>" on one line on stderr (newlines in the message become spaces).
void print_driver_error(const std::string& program, const std::string& message);

}  // namespace rfmems

// Checkpoints of long runs (creep runs of thousands of hours): everything a run
// needs to resume at model time t exactly as if it had never stopped.
//
// HDF5 layout (one file, written ATOMICALLY: "<path>.tmp.<pid>", closed, then renamed over
// <path>, so a run killed at any moment, SIGKILL included, leaves either the previous complete
// checkpoint or the new complete one, never a torn file):
//   /                  attributes format = "rfmems-checkpoint", format_version, time,
//                      settings_hash
//   /state, /state_dot the integrator's state y and y' at `time` (double, exact bits)
//   /numbers           attributes: counters (steps so far, next output index, wall time...)
//   /arrays/<name>     1-D double datasets: the recorded series and output fields so far
//                      (a name may contain '/', which nests groups)
//
// The settings hash (settings_hash()) ties a checkpoint to the settings it was written for:
// a restart with another case is refused by the caller, not silently mixed.
//
// Which integrator history the checkpoint needs: none. The creep run (physics/creep/
// creep_run.hpp) restarts its integrator at every checkpoint time in the uninterrupted run as
// well, so (t, y, y') is the whole state.
#pragma once
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/types.hpp"
#include "io/case_file.hpp"

namespace rfmems {

struct Checkpoint {
  Real time = 0;
  std::vector<Real> state, state_dot;
  std::string settings_hash;
  std::map<std::string, double> numbers;
  std::map<std::string, std::vector<double>> arrays;
};

// Writes the checkpoint atomically (temporary + rename; the parent directory is created).
// Throws std::runtime_error naming the file on an HDF5 or file-system failure, leaving the
// previous checkpoint (if any) in place and no temporary behind.
void write_checkpoint(const std::string& path, const Checkpoint& checkpoint);

// Reads a checkpoint. A missing file, a file that is not an rfmems checkpoint or a malformed
// one -> InputError naming the file (a bad --restart argument is bad input).
Checkpoint read_checkpoint(const std::string& path);

// A stable 64-bit FNV-1a hash of a settings text, as 16 hex digits (the same on every build
// and machine, unlike std::hash).
std::string settings_hash(std::string_view text);

// The settings hash of a case after its overrides, without `section.key` (the checkpoint
// triggers: how often to checkpoint must not invalidate a checkpoint).
std::string case_settings_hash(const CaseFile& file, const std::string& section,
                               const std::string& key);

// Where a run writing `result` (…/name.h5) keeps its checkpoint: …/name.checkpoint.h5.
std::string checkpoint_path_for(const std::string& result);

}  // namespace rfmems

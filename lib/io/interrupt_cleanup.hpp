// Cleaning up when the run is interrupted (Ctrl-C, kill, a batch system's time limit). An
// exception unwinds through the owners of temporary files, which delete them themselves; a
// signal does not, so a handler does it and then lets the signal take its usual course (the
// exit status still says "killed by SIGINT/SIGTERM/SIGHUP").
//
// On SIGINT, SIGTERM or SIGHUP the handler, in this order: kills the registered child process
// (SIGKILL) and reaps it, so that it writes nothing more; unlinks every registered file; removes
// every registered directory (which must be empty by then: register the files in it too).
#pragma once
#include <sys/types.h>

#include <string>

namespace rfmems {

// Unlinks `path` on SIGINT, SIGTERM or SIGHUP: the result file's temporary. One path per
// process; a later call replaces it. Paths longer than 4095 bytes are ignored.
void remove_on_interrupt(const std::string& path);

// While alive, the file (or empty directory) `path` is removed on an interrupt. At most 8 are
// registered at once (more are ignored); paths longer than 4095 bytes are ignored.
class RemoveOnInterrupt {
 public:
  enum class Kind { File, Directory };
  RemoveOnInterrupt(const std::string& path, Kind kind);
  ~RemoveOnInterrupt();
  RemoveOnInterrupt(const RemoveOnInterrupt&) = delete;
  RemoveOnInterrupt& operator=(const RemoveOnInterrupt&) = delete;

 private:
  int slot_ = -1;
};

// While alive, the child process `pid` is killed (SIGKILL) and reaped on an interrupt. One
// child at a time: a later guard replaces an earlier one until it goes away.
class KillOnInterrupt {
 public:
  explicit KillOnInterrupt(pid_t pid);
  ~KillOnInterrupt();
  KillOnInterrupt(const KillOnInterrupt&) = delete;
  KillOnInterrupt& operator=(const KillOnInterrupt&) = delete;
};

}  // namespace rfmems

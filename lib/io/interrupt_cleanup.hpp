// Removing a result file's temporary when the run is interrupted (Ctrl-C, kill, a batch
// system's time limit). An exception unwinds through ResultWriter, which deletes its
// temporary itself; a signal does not, so a handler unlinks the file and then lets the signal
// take its usual course (the exit status still says "killed by SIGINT/SIGTERM").
#pragma once
#include <string>

namespace rfmems {

// Unlinks `path` on SIGINT, SIGTERM or SIGHUP. One path per process; a later call replaces
// it. Paths longer than 4095 bytes are ignored.
void remove_on_interrupt(const std::string& path);

}  // namespace rfmems

// The signal handler behind remove_on_interrupt: only async-signal-safe calls (unlink,
// signal, raise) on a path stored in a static buffer beforehand.
#include "io/interrupt_cleanup.hpp"

#include <unistd.h>

#include <csignal>
#include <cstring>

namespace rfmems {

namespace {

char g_path[4096] = {};

extern "C" void remove_and_reraise(int sig) {
  if (g_path[0] != '\0') ::unlink(g_path);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

void remove_on_interrupt(const std::string& path) {
  if (path.size() >= sizeof g_path) return;
  std::memcpy(g_path, path.c_str(), path.size() + 1);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, remove_and_reraise);
}

}  // namespace rfmems

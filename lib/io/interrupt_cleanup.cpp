// The signal handler behind interrupt_cleanup.hpp: only async-signal-safe calls (kill, waitpid,
// unlink, rmdir, signal, raise) on paths stored in static buffers beforehand. A slot's path is
// written before the slot is marked in use, and unmarked before it is reused, so the handler
// never reads a path being written.
#include "io/interrupt_cleanup.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <mutex>

namespace rfmems {

namespace {

constexpr int kSlots = 9;  // slot 0: remove_on_interrupt's path; 1..8: RemoveOnInterrupt
constexpr std::size_t kPathSize = 4096;

struct Slot {
  char path[kPathSize] = {};
  std::atomic<int> state{0};  // 0 free, 1 file, 2 directory
};

Slot g_slots[kSlots];
std::atomic<pid_t> g_child{0};
std::mutex g_register;  // serialises registrations (not taken by the handler)

static_assert(std::atomic<int>::is_always_lock_free && std::atomic<pid_t>::is_always_lock_free,
              "the signal handler reads these atomics");

extern "C" void clean_up_and_reraise(int sig) {
  const pid_t child = g_child.load();
  if (child > 0) {
    ::kill(child, SIGKILL);
    while (::waitpid(child, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  for (Slot& s : g_slots)
    if (s.state.load() == 1) ::unlink(s.path);
  for (Slot& s : g_slots)
    if (s.state.load() == 2) ::rmdir(s.path);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// A signal ignored when the program started stays ignored (nohup's SIGHUP, SIGINT of a
// background job): the run was asked not to stop on it.
void install_handler() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction current {};
      if (::sigaction(sig, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
      std::signal(sig, clean_up_and_reraise);
    }
  });
}

void store(Slot& s, const std::string& path, int state) {
  s.state.store(0);
  std::memcpy(s.path, path.c_str(), path.size() + 1);
  s.state.store(state);
}

}  // namespace

void remove_on_interrupt(const std::string& path) {
  if (path.size() >= kPathSize) return;
  const std::lock_guard lock(g_register);
  store(g_slots[0], path, 1);
  install_handler();
}

RemoveOnInterrupt::RemoveOnInterrupt(const std::string& path, Kind kind) {
  if (path.size() >= kPathSize) return;
  const std::lock_guard lock(g_register);
  for (int k = 1; k < kSlots; ++k)
    if (g_slots[k].state.load() == 0) {
      store(g_slots[k], path, kind == Kind::File ? 1 : 2);
      slot_ = k;
      break;
    }
  install_handler();
}

RemoveOnInterrupt::~RemoveOnInterrupt() {
  if (slot_ > 0) g_slots[slot_].state.store(0);
}

KillOnInterrupt::KillOnInterrupt(pid_t pid) {
  g_child.store(pid);
  install_handler();
}

KillOnInterrupt::~KillOnInterrupt() { g_child.store(0); }

}  // namespace rfmems

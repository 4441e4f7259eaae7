// Runs gmsh (path from the RFMEMS_GMSH compile definition) to mesh a .geo file into MSH 4.1
// ASCII. posix_spawn passes each argument as is, so paths need no shell quoting. An interrupt
// of the driver while gmsh runs kills gmsh and removes its files (io/interrupt_cleanup.hpp).
#include "mesh/gmsh_runner.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "core/error.hpp"
#include "io/interrupt_cleanup.hpp"

#ifndef RFMEMS_GMSH
#define RFMEMS_GMSH "gmsh"
#endif

extern char** environ;

namespace rfmems {
namespace {

using namespace std::string_literals;

// Shortest text that reads back as the same double, so -setnumber gets exactly `value`.
std::string format_number(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

// First line of gmsh's output that reports an error, or the first line if none does.
std::string first_error_line(const std::string& log_path) {
  std::ifstream in(log_path);
  std::string line, first;
  while (std::getline(in, line)) {
    if (line.find("Error") != std::string::npos) return line;
    if (first.empty()) first = line;
  }
  return first;
}

}  // namespace

std::string generate_gmsh_mesh(const std::string& geo_path,
                               const std::map<std::string, double>& numbers,
                               const std::string& out_msh_path, int dim) {
  namespace fs = std::filesystem;
  if (dim != 2 && dim != 3)
    throw InputError(geo_path + ": gmsh mesh dimension must be 2 or 3, not " + std::to_string(dim));
  std::error_code ec;
  if (!fs::is_regular_file(geo_path, ec)) throw InputError(geo_path + ": no such file");
  const fs::path out(out_msh_path);
  if (out.has_parent_path()) fs::create_directories(out.parent_path(), ec);
  // gmsh may write a file even when it fails, so an old one must not be mistaken for success.
  fs::remove(out, ec);

  std::vector<std::string> args = {RFMEMS_GMSH, geo_path};
  for (const auto& [name, value] : numbers) {
    args.insert(args.end(), {"-setnumber", name, format_number(value)});
  }
  // -v 1: errors only, so a successful run prints nothing but a failure can be explained.
  args.insert(args.end(),
              {"-"s + std::to_string(dim), "-format", "msh41", "-o", out_msh_path, "-v", "1"});
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  // gmsh prints its messages on stdout; collect both streams in a log next to the mesh.
  const std::string log_path = out_msh_path + ".log";
  const RemoveOnInterrupt remove_log(log_path, RemoveOnInterrupt::Kind::File);
  const RemoveOnInterrupt remove_mesh(out_msh_path, RemoveOnInterrupt::Kind::File);
  // The interrupt signals are blocked from before the spawn until gmsh's pid is registered, so
  // that no interrupt in between leaves gmsh running; gmsh itself starts with none blocked.
  sigset_t interrupts, previous;
  sigemptyset(&interrupts);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&interrupts, sig);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  pthread_sigmask(SIG_BLOCK, &interrupts, &previous);
  posix_spawnattr_setsigmask(&attributes, &previous);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
  const int spawn_error = posix_spawnp(&pid, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  int status = 0;
  {
    const KillOnInterrupt kill_gmsh(spawn_error == 0 ? pid : 0);
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    if (spawn_error != 0)
      throw InputError(geo_path + ": cannot run " + args[0] + ": " + std::strerror(spawn_error));
    while (waitpid(pid, &status, 0) < 0) {
      if (errno != EINTR)
        throw InputError(geo_path + ": lost track of gmsh: " + std::strerror(errno));
    }
  }
  const std::string error_line = first_error_line(log_path);
  fs::remove(log_path, ec);

  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const std::string how = WIFEXITED(status)
                                ? "exit status "s + std::to_string(WEXITSTATUS(status))
                                : "killed by signal "s + std::to_string(WTERMSIG(status));
    fs::remove(out, ec);
    throw InputError(geo_path + ": gmsh failed (" + how + ")" +
                     (error_line.empty() ? std::string() : ": " + error_line));
  }
  if (!fs::is_regular_file(out, ec))
    throw InputError(geo_path + ": gmsh wrote no mesh to " + out_msh_path);
  return out_msh_path;
}

}  // namespace rfmems

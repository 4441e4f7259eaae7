// Small pieces every benchmark program uses: clocks, one JSON object per stdout line, the
// repository's cases/ directory.
#pragma once
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/dense_stiffness.hpp"
#include "core/error.hpp"
#include "core/system_operator.hpp"
#include "solvers/ida_integrator.hpp"

namespace rfmems::bench {

// Wall-clock seconds (steady clock; differences only).
inline double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// CPU seconds of this process (immune to other processes on a shared machine).
inline double cpu_now() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// One JSON object per line on stdout (any type with dump()).
template <class J>
void emit(const J& j) {
  std::cout << j.dump() << std::endl;
}

// The header line of a run's JSON lines: the command as typed (program and arguments), the
// date (UTC) and the machine's 1-minute load average when the run starts (shared machines: wall
// times rise with it, CPU times much less).
template <class J>
J run_header(const std::string& program, int argc, char** argv) {
  char date[16];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  std::string command = "build/bench/" + program;
  for (int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
  std::ifstream loadavg("/proc/loadavg");
  double load = 0;
  loadavg >> load;
  return J{
      {"section", "header"}, {"command", command}, {"date", date}, {"load_average_1min", load}};
}

// A list of meshes "nx,ny;nx,ny" (or "nx,nz,nw;..." in 3D) -> {nx, ny, nw}, absent counts 0;
// `option` names the command-line option in the error for an entry that is not a number.
inline std::vector<std::array<int, 3>> parse_meshes(const std::string& text,
                                                    const std::string& option) {
  std::vector<std::array<int, 3>> out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    std::array<int, 3> mesh{0, 0, 0};
    std::size_t from = start;
    for (int d = 0; d < 3 && from < end; ++d) {
      const std::size_t comma = std::min(text.find(',', from), end);
      try {
        mesh[d] = std::stoi(text.substr(from, comma - from));
      } catch (const std::logic_error&) {
        throw InputError(option + ": '" + text + "' is not a list nx,ny;...");
      }
      from = comma + 1;
    }
    out.push_back(mesh);
    start = end + 1;
  }
  return out;
}

// The repository's cases/ directory, from this header's path (CMake compiles by absolute path).
inline std::string default_cases_dir() {
  return (std::filesystem::path(__FILE__).parent_path().parent_path() / "cases").string();
}

// The integrator's work counts into a benchmark's JSON object (the keys the recorded
// docs/figures/*.jsonl use).
template <class J>
void add_integrator_stats(J& j, const IntegratorStats& s) {
  j["steps"] = s.steps;
  j["residual_evals"] = s.residual_evals;
  j["jacobian_evals"] = s.jacobian_evals;
  j["newton_iters"] = s.newton_iters;
  j["error_test_fails"] = s.error_test_fails;
  j["newton_fails"] = s.newton_fails;
}

// max_k |w_k - reference(t_k)| / max_k |reference(t_k)| over a run's (t, w) samples.
template <class Reference>
double max_relative_error(const std::vector<std::pair<double, double>>& samples,
                          const Reference& reference) {
  double e = 0, scale = 0;
  for (auto [t, w] : samples) {
    const double wr = reference.at(t);
    e = std::max(e, std::abs(w - wr));
    scale = std::max(scale, std::abs(wr));
  }
  return e / scale;
}

}  // namespace rfmems::bench

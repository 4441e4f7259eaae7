// Small pieces every benchmark program uses: clocks, one JSON object per stdout line, the
// repository's cases/ directory.
#pragma once
#include <chrono>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <string>

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

// The repository's cases/ directory, from this header's path (CMake compiles by absolute path).
inline std::string default_cases_dir() {
  return (std::filesystem::path(__FILE__).parent_path().parent_path() / "cases").string();
}

}  // namespace rfmems::bench

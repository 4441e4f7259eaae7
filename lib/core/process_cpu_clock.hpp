// CPU seconds of the process (CLOCK_PROCESS_CPUTIME_ID), and a scope that adds its CPU time to
// a counter: per-physics cost accounting of coupled runs on a loaded machine, where wall time
// is noisy (the results pages under docs/ report CPU time beside wall time).
#pragma once
#include <time.h>

namespace rfmems {

inline double process_cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct ScopedCpuTimer {
  double& sink;
  double start = process_cpu_seconds();
  ~ScopedCpuTimer() { sink += process_cpu_seconds() - start; }
};

}  // namespace rfmems

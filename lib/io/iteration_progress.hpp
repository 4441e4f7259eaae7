// Progress of a steady iteration (the kinetic solvers) on stderr: every few seconds the
// iteration, its residual ratio and, once there is enough history, the contraction rate's
// forecast of the iterations and the wall time still needed (solvers/convergence_forecast.hpp):
//
//   iteration 388: residual ratio 2.887e-01, 0.99817 per iteration, ~6.9e+03 more to 1e-06
//   (~4m32s) (15 s)
//
// When the forecast first passes kSlowSeconds, one warning with the remedy the caller gives
// (e.g. "use solver.type: comet" for the sequential solver near the continuum).
#pragma once
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

class IterationProgress {
 public:
  static constexpr double kSlowSeconds = 600;
  static constexpr double kInterval = 5;  // seconds between lines

  // program: the warning's prefix; remedy: appended to it (may be empty).
  IterationProgress(bool quiet, Real tolerance, std::string program, std::string remedy,
                    std::FILE* out = stderr);

  // The solvers' monitor: called after each iteration; never asks to stop.
  bool operator()(int iteration, Real ratio);

 private:
  using Clock = std::chrono::steady_clock;
  bool quiet_;
  Real tolerance_;
  std::string program_, remedy_;
  std::FILE* out_;
  Clock::time_point start_ = Clock::now();
  double last_print_ = -kInterval;
  bool warned_ = false;
  std::vector<Real> ratios_;
};

}  // namespace rfmems

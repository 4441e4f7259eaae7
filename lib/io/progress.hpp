// Progress of a time integration on stderr: simulated time, step size, steps, elapsed and
// estimated remaining wall time. On a terminal one line is rewritten in place ('\r'); in a
// log file (not a terminal) a line is written every ~5 s of wall time, so logs stay short.
#pragma once
#include <chrono>
#include <cstdio>
#include <string>

namespace rfmems {

// A wall-time span for a person: "12.3 s", "4m05s", "2h10m"; "?" when not finite.
std::string format_duration(double seconds);

class ProgressReporter {
 public:
  // quiet: print nothing. t_end: the simulated end time (<= 0: unknown, no estimate).
  // out: where to print (stderr; tests pass a file).
  ProgressReporter(bool quiet, double t_end, std::FILE* out = stderr);
  ~ProgressReporter();
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  // Called after each accepted step; cheap when nothing is printed.
  void update(double t, double h, long steps);
  // Prints the final state and ends the line. Further calls do nothing.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  std::string line(Clock::time_point now) const;
  void print(Clock::time_point now);

  bool quiet_;
  bool terminal_;
  double t_end_;
  std::FILE* out_;
  Clock::time_point start_, last_print_;
  // First update seen: the rate of progress is measured from here, so setup time and a
  // non-zero start time do not skew the estimate.
  bool have_first_ = false;
  double t_first_ = 0.0;
  Clock::time_point wall_first_;
  double t_ = 0.0, h_ = 0.0;
  long steps_ = 0;
  std::size_t last_length_ = 0;  // of the line on the terminal, to blank what is left of it
  bool line_open_ = false;       // a terminal line without its newline yet
  bool finished_ = false;
};

}  // namespace rfmems

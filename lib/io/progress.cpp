// ProgressReporter: formatting and throttling of the progress line.
#include "io/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>

namespace rfmems {

std::string format_duration(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  if (s < 60) return fmt::format("{:.1f} s", s);
  const long total = std::lround(s);
  if (total < 3600) return fmt::format("{}m{:02}s", total / 60, total % 60);
  return fmt::format("{}h{:02}m", total / 3600, (total % 3600) / 60);
}

namespace {

// A terminal is refreshed a few times per second; a log gets one line per 5 s.
constexpr double kTerminalInterval = 0.25;
constexpr double kLogInterval = 5.0;

double seconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration<double>(d).count();
}

}  // namespace

ProgressReporter::ProgressReporter(bool quiet, double t_end, std::FILE* out)
    : quiet_(quiet),
      terminal_(out != nullptr && ::isatty(::fileno(out)) == 1),
      t_end_(t_end),
      out_(out),
      start_(Clock::now()),
      last_print_(start_) {}

ProgressReporter::~ProgressReporter() {
  // An exception is on its way out: end our line so its message starts on a fresh one.
  if (line_open_ && out_ != nullptr) std::fputc('\n', out_);
}

std::string ProgressReporter::line(Clock::time_point now) const {
  std::string s = fmt::format("t = {:.4g} s", t_);
  if (t_end_ > 0) s += fmt::format(" / {:.4g} s ({:.1f}%)", t_end_, 100.0 * t_ / t_end_);
  s += fmt::format("  h = {:.3g} s  steps {}  elapsed {}", h_, steps_,
                   format_duration(seconds(now - start_)));
  if (t_end_ > 0 && !finished_) {
    const double dt_wall = seconds(now - wall_first_), dt_sim = t_ - t_first_;
    const double left = dt_sim > 0 && dt_wall > 0 ? (t_end_ - t_) * dt_wall / dt_sim : -1.0;
    s += "  left ~" + format_duration(left);
  }
  return s;
}

void ProgressReporter::print(Clock::time_point now) {
  const std::string text = line(now);
  if (terminal_) {
    const std::size_t pad = last_length_ > text.size() ? last_length_ - text.size() : 0;
    std::fprintf(out_, "\r%s%*s", text.c_str(), static_cast<int>(pad), "");
    last_length_ = text.size();
    line_open_ = true;
  } else {
    std::fprintf(out_, "%s\n", text.c_str());
  }
  std::fflush(out_);
  last_print_ = now;
}

void ProgressReporter::update(double t, double h, long steps) {
  if (quiet_ || finished_ || out_ == nullptr) return;
  const auto now = Clock::now();
  if (!have_first_) {
    have_first_ = true;
    t_first_ = t;
    wall_first_ = now;
  }
  t_ = t;
  h_ = h;
  steps_ = steps;
  if (seconds(now - last_print_) >= (terminal_ ? kTerminalInterval : kLogInterval)) print(now);
}

void ProgressReporter::finish() {
  if (finished_) return;
  finished_ = true;
  if (quiet_ || out_ == nullptr) return;
  print(Clock::now());
  if (terminal_) std::fputc('\n', out_);
  line_open_ = false;
  std::fflush(out_);
}

}  // namespace rfmems

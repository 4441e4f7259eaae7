// Period and amplitude of a sampled oscillation about a known mean (e.g. the static
// deflection under the held load), from linearly interpolated upward zero crossings.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

namespace rfmems::test_support {

struct Oscillation {
  double period = 0;
  int n_periods = 0;
  double first_amplitude = 0, last_amplitude = 0;  // max |x - mean| in the first / last period
};

inline Oscillation analyse_oscillation(const std::vector<double>& t, const std::vector<double>& x,
                                       double mean, double t_start) {
  std::vector<double> crossings;
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i - 1] < t_start) continue;
    double a = x[i - 1] - mean, b = x[i] - mean;
    if (a < 0 && b >= 0) crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * (-a) / (b - a));
  }
  Oscillation o;
  if (crossings.size() < 2) return o;
  o.n_periods = static_cast<int>(crossings.size()) - 1;
  o.period = (crossings.back() - crossings.front()) / o.n_periods;
  auto amplitude = [&](double from, double to) {
    double m = 0;
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t[i] >= from && t[i] <= to) m = std::max(m, std::abs(x[i] - mean));
    return m;
  };
  o.first_amplitude = amplitude(crossings[0], crossings[1]);
  o.last_amplitude = amplitude(crossings[o.n_periods - 1], crossings[o.n_periods]);
  return o;
}

}  // namespace rfmems::test_support

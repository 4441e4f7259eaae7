// Observed orders of accuracy from a mesh-refinement series.
#pragma once
#include <cmath>
#include <cstddef>
#include <vector>

namespace rfmems::test_support {

// Least-squares slope of log(error) against log(h) over the whole series.
inline double fitted_order(const std::vector<double>& h, const std::vector<double>& e) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double m = static_cast<double>(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double x = std::log(h[i]), y = std::log(e[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

}  // namespace rfmems::test_support

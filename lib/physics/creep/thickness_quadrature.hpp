// Through-thickness integration points of a plate section (thesis ch. 4: "typically 20"
// points, Simpson's rule). Composite Simpson on z in [-h/2, h/2] with an even number N of
// intervals: N + 1 points z_i = -h/2 + i h/N, weights (h/N)/3 (1, 4, 2, 4, ..., 4, 1). It
// integrates cubics exactly, so the elastic moment int z sigma dz of a linear stress profile
// is exact; the plastic profiles are smooth in z away from t = 0.
#pragma once
#include <fmt/format.h>

#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"

namespace rfmems {

struct ThicknessQuadrature {
  std::vector<Real> z, weight;

  Index size() const { return static_cast<Index>(z.size()); }

  static ThicknessQuadrature simpson(Real thickness, int intervals) {
    if (intervals < 2 || intervals % 2 != 0)
      throw InputError(fmt::format(
          "creep: through-thickness intervals must be even and >= 2 (Simpson), got {}", intervals));
    ThicknessQuadrature q;
    const Real dz = thickness / intervals;
    for (int i = 0; i <= intervals; ++i) {
      q.z.push_back(-0.5 * thickness + i * dz);
      const Real c = (i == 0 || i == intervals) ? 1 : (i % 2 == 1 ? 4 : 2);
      q.weight.push_back(c * dz / 3);
    }
    return q;
  }
};

}  // namespace rfmems

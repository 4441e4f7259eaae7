#include "physics/structure/gap_element.hpp"

#include <limits>

namespace rfmems {

LowestGapPoint lowest_gap_point(std::span<const GapElement> elements, std::span<const Real> y) {
  LowestGapPoint lowest;
  Real u_min = std::numeric_limits<Real>::infinity();
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (const GapPoint& q : elements[e].points)
      if (const Real u = gap_displacement(q, y); u < u_min) {
        u_min = u;
        lowest = {e, &q};
      }
  return lowest;
}

}  // namespace rfmems

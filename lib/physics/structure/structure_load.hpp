// A load on a structure's unknowns from what lies across its gap (a field, a gas), and its
// total along the gap axis [N, or N/m per unit depth of a plane structure; negative: closing].
#pragma once
#include <vector>

#include "core/types.hpp"

namespace rfmems {

struct StructureLoad {
  std::vector<Real> force;  // per structure unknown
  Real force_y = 0;
};

}  // namespace rfmems

// One term of a linear map of a system's unknowns, v = sum_k weight_k y[dof_k]: how a value
// evaluated off the unknowns (a reconstruction at a point, e.g. the plate's deflection inside a
// cell) depends on them, so that an operator using it can differentiate it exactly. Neutral
// ground for the plate operator (PlateOperator::deflection_weights, which fills it) and the
// structure's gap quadrature (GapPoint, physics/structure/gap_element.hpp, which stores it).
#pragma once
#include <span>

#include "core/types.hpp"

namespace rfmems {

struct DofWeight {
  Index dof;
  Real weight;
};

// constant + sum_k weight_k y[dof_k] (added in that order).
inline Real weighted_sum(std::span<const DofWeight> terms, std::span<const Real> y,
                         Real constant = 0) {
  Real sum = constant;
  for (const DofWeight& t : terms) sum += t.weight * y[t.dof];
  return sum;
}

}  // namespace rfmems

// Static equilibrium R(t, y) = 0 of a structural operator with KINSOL (exact Newton + KLU).
#pragma once
#include <vector>

#include "core/system_operator.hpp"
#include "solvers/kinsol_solver.hpp"

namespace rfmems {

struct StaticSolution {
  std::vector<Real> y;
  NonlinearStats stats;
};

// Starts from y0 (zero if empty).
StaticSolution solve_static(SecondOrderOperator& op, Real t, const KinsolOptions& options = {},
                            std::vector<Real> y0 = {});

}  // namespace rfmems

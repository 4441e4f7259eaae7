#include "solvers/static_solve.hpp"

#include "core/structural_systems.hpp"

namespace rfmems {

StaticSolution solve_static(SecondOrderOperator& op, Real t, const KinsolOptions& options,
                            std::vector<Real> y0) {
  StaticSystem system(op);
  KinsolOptions kin = options;
  kin.round_off_floor = true;
  KinsolSolver solver(system, kin);
  StaticSolution solution;
  solution.y = y0.empty() ? std::vector<Real>(op.size(), 0.0) : std::move(y0);
  solution.stats = solver.solve(t, solution.y);
  return solution;
}

}  // namespace rfmems

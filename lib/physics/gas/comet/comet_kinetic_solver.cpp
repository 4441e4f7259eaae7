#include "physics/gas/comet/comet_kinetic_solver.hpp"

#include <fmt/format.h>

#include <string>

#include "io/case_schema_yaml.hpp"

namespace rfmems {

CometOptions read_comet_options(const CaseNode& solver) {
  CometOptions o;
  o.coupling = comet_coupling_from_name(
      solver.get_choice("coupling", {"conserved", "velocity"}, "conserved"));
  o.multigrid = solver.get_bool("multigrid", true);
  // auto (default: F-cycles with one-pass coarse sweeps below f_cycle_below_knudsen, V-cycles
  // above; comet_solver.hpp, docs/kinetic.md, "COMET cycle by regime") | V | W | F.
  o.cycle_shape =
      comet_cycle_from_name(solver.get_choice("cycle", {"auto", "V", "W", "F"}, "auto"));
  o.f_cycle_below_knudsen = solver.get_real("f_cycle_below_knudsen", 0.02, Range::non_negative());
  o.coarse_symmetric = solver.get_bool("coarse_symmetric", true);
  o.pre_sweeps = static_cast<int>(solver.get_int("pre_sweeps", 1, Range::closed(0, 100)));
  o.post_sweeps = static_cast<int>(solver.get_int("post_sweeps", 1, Range::closed(0, 100)));
  if (o.pre_sweeps + o.post_sweeps < 1)
    solver.fail("post_sweeps", "pre_sweeps + post_sweeps must be >= 1");
  o.coarsest_sweeps =
      static_cast<int>(solver.get_int("coarsest_sweeps", 4, Range::closed(1, 1000)));
  o.symmetric = solver.get_bool("symmetric", true);
  o.min_coarse_cells = solver.get_int("min_coarse_cells", 8, Range::closed(1, 1e9));
  o.sequential_above_knudsen =
      solver.get_real("sequential_above_knudsen", 0.2, Range::non_negative());
  o.cell_newton_iterations =
      static_cast<int>(solver.get_int("cell_newton_iterations", 1, Range::closed(1, 100)));
  return o;
}

KineticSolveResult solve_comet(KineticOperator& op, std::span<Real> f, CometOptions options,
                               Real tolerance, int max_iterations,
                               const std::function<bool(int, Real)>& monitor) {
  options.tolerance = tolerance;
  options.max_cycles = max_iterations;
  options.monitor = monitor;
  CometSolver solver(op, options);
  const CometResult r = solver.solve(f);
  KineticSolveResult out;
  out.method = r.method;
  if (out.method != std::string("comet"))
    out.handover = fmt::format(
        "COMET handed the solve to the sequential solver: domain Kn = {:.4g} >= "
        "solver.sequential_above_knudsen = {:.4g}, where a sweep is cheaper than a cycle",
        r.knudsen, options.sequential_above_knudsen);
  out.converged = r.converged;
  out.iterations = r.cycles;
  out.initial_residual = r.initial_residual;
  out.residual_ratio = r.residual_ratio;
  out.final_residual = r.residual_ratio * r.initial_residual;
  out.seconds = r.wall_seconds;
  out.history = r.history;
  out.stop_reason = r.stop_reason;
  return out;
}

CaseSchema comet_case_keys() {
  return embedded_case_schema("physics/gas/comet/comet_kinetic_solver.keys.yaml");
}

}  // namespace rfmems

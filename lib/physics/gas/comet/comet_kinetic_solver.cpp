#include "physics/gas/comet/comet_kinetic_solver.hpp"

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
  return {{"solver",
           "COMET's settings (solver.type: comet)",
           {
               {"coupling", "choice", "conserved", "conserved, velocity",
                "what the cell's implicit update couples: the conserved moments or the velocity"},
               {"multigrid", "bool", "true", "", "agglomeration multigrid on the cell systems"},
               {"cycle", "choice", "auto", "auto, V, W, F",
                "the multigrid cycle (auto: F below f_cycle_below_knudsen, V above)"},
               {"f_cycle_below_knudsen", "number", "0.02", ">= 0",
                "auto cycle: the Knudsen number below which F-cycles are used"},
               {"coarse_symmetric", "bool", "true", "", "symmetric sweeps on coarse levels"},
               {"pre_sweeps", "integer", "1", "in [0, 100]", "sweeps before coarse correction"},
               {"post_sweeps", "integer", "1", "in [0, 100]",
                "sweeps after coarse correction (pre + post >= 1)"},
               {"coarsest_sweeps", "integer", "4", "in [1, 1000]", "sweeps on the coarsest level"},
               {"symmetric", "bool", "true", "", "symmetric (forward and backward) sweeps"},
               {"min_coarse_cells", "integer", "8", "in [1, 1000000000]",
                "agglomeration stops at this many cells"},
               {"sequential_above_knudsen", "number", "0.2", ">= 0",
                "above this Knudsen number the sequential solver runs instead"},
               {"cell_newton_iterations", "integer", "1", "in [1, 100]",
                "Newton iterations of each cell's nonlinear update"},
           }}};
}

}  // namespace rfmems

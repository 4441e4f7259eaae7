// COMET as one of the kinetic steady solvers the rfmems-gas driver picks by name
// (physics/gas/kinetic/kinetic_case.hpp: `solver: {type: comet, ...}`): its case keys and the
// call with the registry's signature, reporting a KineticSolveResult (iterations = cycles;
// after a hand-over to the sequential solver, sweeps, with method and handover saying so).
//
//   solver:
//     type: comet
//     tolerance: 1e-6            # ||r|| / ||r_0|| (read by read_kinetic_solver_settings)
//     max_iterations: 1000       # V-cycles (idem)
//     coupling: conserved        # conserved (default) | velocity (thesis: u, v, w only)
//     multigrid: true            # false: single-level point Gauss-Seidel
//     cycle: auto                # auto (default) | V | W | F
//     f_cycle_below_knudsen: 0.02  # auto: F-cycles, one-pass coarse sweeps, below this Kn;
//                                  # V-cycles above (comet_solver.hpp)
//     coarse_symmetric: true     # V, W, F: false = one-pass sweeps on the coarse levels
//     pre_sweeps: 1              # per level, each a forward + backward pass when symmetric
//     post_sweeps: 1
//     coarsest_sweeps: 4
//     symmetric: true
//     min_coarse_cells: 8        # agglomerate down to this many cells
//     cell_newton_iterations: 1
//     sequential_above_knudsen: 0.2   # regime switch (comet_solver.hpp); 0: always COMET
// The COMET keys must be read before the case's unused-key check: call read_comet_options on
// the `solver:` node when the scene is built (with type comet), not only when solving.
#pragma once
#include <functional>
#include <span>

#include "io/case_file.hpp"
#include "physics/gas/comet/comet_solver.hpp"
#include "physics/gas/kinetic/kinetic_solve_result.hpp"

namespace rfmems {

// The COMET keys of a `solver:` map (defaults as in CometOptions); InputError on bad values.
CometOptions read_comet_options(const CaseNode& solver);

// Runs COMET with these options; tolerance, max_iterations (cycles) and monitor override.
KineticSolveResult solve_comet(KineticOperator& op, std::span<Real> f, CometOptions options,
                               Real tolerance, int max_iterations,
                               const std::function<bool(int, Real)>& monitor);

// The keys read_comet_options reads (comet_kinetic_solver.keys.yaml; io/case_schema.hpp).
CaseSchema comet_case_keys();

}  // namespace rfmems

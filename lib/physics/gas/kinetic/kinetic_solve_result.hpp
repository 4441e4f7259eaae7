// What a steady kinetic solve reports, whichever solver ran it (sequential, COMET).
// Residual scaling (kinetic_operator.hpp): ratio = ||r||_2 / ||r_0||_2 of the full steady
// residual, r_0 that of the initial state; converged when ratio <= tolerance (1e-6 default).
#pragma once
#include <string>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

struct KineticSolveResult {
  // The solver that ran: "sequential" (iterations are sweeps) or "comet" (iterations are
  // V/W/F-cycles). COMET hands a domain above its sequential_above_knudsen to the sequential
  // solver (comet_solver.hpp): then method is "sequential" and handover says why.
  std::string method = "sequential";
  std::string handover;  // empty unless the requested solver handed the solve over
  bool converged = false;
  int iterations = 0;         // outer iterations of `method` (sweeps or cycles)
  Real initial_residual = 0;  // ||r_0||_2
  Real final_residual = 0;    // ||r||_2 at exit
  Real residual_ratio = 0;    // final / initial
  double seconds = 0;         // wall time
  std::vector<Real> history;  // residual ratio after each iteration
  // Set when the solve stopped before its cap because its contraction rate forecast that the
  // cap would not suffice (solvers/convergence_forecast.hpp): the sentence that says so.
  std::string stop_reason;
};

}  // namespace rfmems

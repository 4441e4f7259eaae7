// The touching point of the no-contact branch: the voltage at which the structure's surface
// first reaches the contact gap g_c (the dielectric), which the quasi-static pull-out
// approaches as the penalty's penetration delta -> 0 (quasi_static_pull_out.hpp).
//
// The smallest gap is ParallelPlateActuation::min_gap (over the quadrature points of the
// reconstructed surface, not a cell's unknown), so it is found by displacement control of the
// element whose points hold the smallest gap (re-chosen as the plate deforms: along the free
// edges, not the centre line) and a secant iteration on that element's deflection d:
//   f(d) = min_gap(y(d)) - g_c = 0,   d_{k+1} = d_k - f_k (d_k - d_{k-1}) / (f_k - f_{k-1})
// (the first step with slope 1: min_gap moves with the control unknown).
#pragma once
#include <span>
#include <vector>

#include "coupling/quasi_static_pull_in.hpp"

namespace rfmems {

struct TouchingPoint {
  Real voltage = 0;
  std::vector<Real> state;  // structure unknowns, then V^2
  Index control = -1;       // the controlled unknown at the end
  int iterations = 0;       // displacement-control solves
};

// from: a solved state of the no-contact branch (structure unknowns, then V^2; e.g. the fold
// state of trace_pull_in). Iterates until |min_gap - contact_gap| <= tolerance (SolverError
// after 30 solves).
TouchingPoint find_touching_point(ParallelPlateActuation& actuation, std::span<const Real> from,
                                  Real contact_gap, Real tolerance,
                                  const QuasiStaticOptions& options = {});

}  // namespace rfmems

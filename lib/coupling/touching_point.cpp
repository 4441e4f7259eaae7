#include "coupling/touching_point.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace rfmems {

namespace {

// The unknown of the element whose points hold the smallest gap.
Index smallest_gap_unknown(const ParallelPlateActuation& act, std::span<const Real> y) {
  const LowestGapPoint lowest = lowest_gap_point(act.elements(), y);
  return lowest.point ? act.elements()[lowest.element].dof : -1;
}

}  // namespace

TouchingPoint find_touching_point(ParallelPlateActuation& act, std::span<const Real> from,
                                  Real contact_gap, Real tolerance,
                                  const QuasiStaticOptions& options) {
  TouchingPoint t;
  t.state.assign(from.begin(), from.end());
  t.control = smallest_gap_unknown(act, t.state);
  Real f = act.min_gap(t.state) - contact_gap;
  Real d_prev = 0, f_prev = 0;
  bool secant = false;
  while (std::abs(f) > tolerance) {
    if (++t.iterations > 30)
      throw SolverError(
          fmt::format("touching point: min gap {:.4e} m after 30 solves", f + contact_gap));
    const Real d = t.state[t.control];
    const Real slope = secant && f != f_prev ? (f - f_prev) / (d - d_prev) : 1.0;
    d_prev = d;
    f_prev = f;
    t.state = follow_displacement(act, t.control, t.state, {d - f / slope}, options);
    f = act.min_gap(t.state) - contact_gap;
    const Index control = smallest_gap_unknown(act, t.state);
    secant = control == t.control;
    t.control = control;
  }
  t.voltage = std::sqrt(t.state[act.size()]);
  return t;
}

}  // namespace rfmems

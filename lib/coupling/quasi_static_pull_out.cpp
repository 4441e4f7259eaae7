#include "coupling/quasi_static_pull_out.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "core/structural_systems.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "solvers/kinsol_solver.hpp"

namespace rfmems {

QuasiStaticPullOut trace_pull_out(ParallelPlateActuation& act, Index control,
                                  std::span<const Real> guess, const PullOutOptions& options) {
  const ContactPenalty& contact = act.contact();
  if (!contact.enabled()) throw std::logic_error("trace_pull_out: the actuation has no contact");
  if (options.start_voltage <= 0) throw std::logic_error("trace_pull_out: start_voltage <= 0");
  const Index n = act.size();
  const Real g0 = act.initial_gap();
  StaticSystem system(act);
  KinsolOptions kin;
  kin.max_iterations = options.max_newton_iterations;
  kin.line_search = true;
  kin.relative_tolerance = options.newton_tolerance;
  kin.residual_scale = stiffness_scale(act) * g0;
  KinsolSolver solver(system, kin);

  QuasiStaticPullOut out;
  // The equilibrium at voltage v from `from`; false if Newton fails or leaves the dielectric.
  auto solve = [&](Real v, const std::vector<Real>& from, std::vector<Real>& state, long& iterations) {
    act.set_voltage_squared([v](Real) { return v * v; });
    state = from;
    ++out.solves;
    try {
      iterations = solver.solve(0.0, state).newton_iters;
    } catch (const std::exception&) {  // SolverError, or a closed gap in every line-search try
      return false;
    }
    out.newton_iterations += iterations;
    return act.min_gap(state) < contact.gap;
  };
  auto point = [&](Real v, const std::vector<Real>& state, long iterations) {
    return ContactBranchPoint{v, state[control], act.min_gap(state), act.contact_fraction(state),
                              iterations};
  };

  // The guess, scaled so that the control unknown sits one penetration below the contact gap.
  std::vector<Real> pressed(guess.begin(), guess.begin() + n);
  if (pressed[control] >= 0)
    throw std::logic_error("trace_pull_out: the guess must deflect the control towards the electrode");
  const Real target = -(g0 - contact.gap + contact.penetration);
  for (Real& x : pressed) x *= target / guess[control];
  std::vector<Real> state, trial;
  long iterations = 0;
  Real v = options.start_voltage;
  if (!solve(v, pressed, state, iterations))
    throw SolverError(fmt::format("pull-out: no equilibrium in contact found at {:.4g} V (start "
                                  "above the pull-in voltage)",
                                  v));
  out.branch.push_back(point(v, state, iterations));
  // Descent until the contact equilibrium is lost.
  Real lower = 0;
  while (true) {
    const Real next = options.step_ratio * v;
    if (next < options.voltage_tolerance) break;  // still in contact near 0 V (lower = 0)
    if (!solve(next, state, trial, iterations)) {
      lower = next;
      break;
    }
    state = trial;
    v = next;
    out.branch.push_back(point(v, state, iterations));
  }
  // Bisection between lower (released) and v (in contact), from the last contact state.
  while (v - lower > options.voltage_tolerance) {
    const Real mid = 0.5 * (v + lower);
    if (solve(mid, state, trial, iterations)) {
      state = trial;
      v = mid;
      out.branch.push_back(point(v, state, iterations));
    } else {
      lower = mid;
    }
  }
  out.pull_out_voltage = v;
  out.released_voltage = lower;
  out.state = state;
  return out;
}

}  // namespace rfmems

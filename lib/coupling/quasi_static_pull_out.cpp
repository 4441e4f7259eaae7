#include "coupling/quasi_static_pull_out.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "core/structural_systems.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "solvers/kinsol_solver.hpp"

namespace rfmems {

namespace {

struct ContactSolver {
  ParallelPlateActuation& act;
  StaticSystem system;
  Real tolerance;  // on ||F||_inf [N]
  KinsolSolver solver;
  long solves = 0, newton = 0;
  ContactSolver(ParallelPlateActuation& a, const PullOutOptions& options)
      : act(a),
        system(a),
        tolerance(options.newton_tolerance * stiffness_scale(a) * a.initial_gap()),
        solver(system, [&] {
          KinsolOptions kin;
          kin.max_iterations = options.max_newton_iterations;
          kin.line_search = true;
          kin.relative_tolerance = options.newton_tolerance;
          kin.residual_scale = stiffness_scale(a) * a.initial_gap();
          return kin;
        }()) {}
  // The equilibrium at voltage v from `from`; false if Newton fails or leaves the dielectric.
  bool solve(Real v, const std::vector<Real>& from, std::vector<Real>& state, long& iterations) {
    act.set_voltage_squared([v](Real) { return v * v; });
    state = from;
    ++solves;
    NonlinearStats stats;
    try {
      stats = solver.solve(0.0, state);
    } catch (const std::exception&) {  // SolverError, RecoverableError from the film/gap
      return false;
    }
    iterations = stats.newton_iters;
    newton += iterations;
    // KINSOL can stop with a warning (a stalled line search at the fold, where the Jacobian is
    // singular and no solution exists below it): only a small residual is an equilibrium.
    if (stats.final_residual > 10 * tolerance) return false;
    return act.min_gap(state) < act.contact().gap;
  }
};

void check_contact(const ParallelPlateActuation& act, Real voltage) {
  if (!act.contact().enabled()) throw std::logic_error("pull-out: the actuation has no contact");
  if (voltage <= 0) throw std::logic_error("pull-out: the voltage must be > 0");
}

}  // namespace

std::vector<Real> press_onto_dielectric(ParallelPlateActuation& act, Index control,
                                        std::span<const Real> guess, Real voltage,
                                        const PullOutOptions& options) {
  check_contact(act, voltage);
  const Index n = act.size();
  const ContactPenalty& contact = act.contact();
  if (guess.size() != static_cast<std::size_t>(n + 1) || guess[control] >= 0)
    throw std::logic_error(
        "press_onto_dielectric: the guess must be a displacement-controlled "
        "state (structure, V^2) deflected towards the electrode");
  std::vector<Real> path;
  const Real half = -(act.initial_gap() - contact.gap + 0.5 * contact.penetration);
  for (int k = 1; k <= 12; ++k) path.push_back(guess[control] + (half - guess[control]) * k / 12);
  QuasiStaticOptions qs;
  qs.newton_tolerance = options.newton_tolerance;
  qs.max_newton_iterations = options.max_newton_iterations;
  const std::vector<Real> controlled = follow_displacement(act, control, guess, path, qs);
  std::vector<Real> state(controlled.begin(), controlled.begin() + n), trial;
  Real v = std::sqrt(std::max(controlled[n], 0.0));
  ContactSolver cs(act, options);
  long iterations = 0;
  Real ratio = 1 / options.step_ratio;
  while (v < voltage) {
    const Real next = std::min(voltage, v * ratio);
    if (cs.solve(next, state, trial, iterations)) {
      state = trial;
      v = next;
      ratio = std::min(1 / options.step_ratio, 1 + 2 * (ratio - 1));
    } else if ((ratio = 1 + 0.5 * (ratio - 1)) < 1 + 1e-3) {
      throw SolverError(
          fmt::format("pull-out: no equilibrium in contact reached at {:.4g} V "
                      "(the contact branch from the touching point folds at {:.4g} V)",
                      voltage, v));
    }
  }
  return state;
}

QuasiStaticPullOut trace_pull_out(ParallelPlateActuation& act, Index control,
                                  std::span<const Real> contact_state,
                                  const PullOutOptions& options) {
  check_contact(act, options.start_voltage);
  const Index n = act.size();
  ContactSolver cs(act, options);
  QuasiStaticPullOut out;
  auto point = [&](Real v, const std::vector<Real>& state, long iterations) {
    return ContactBranchPoint{v, state[control], act.min_gap(state), act.contact_fraction(state),
                              iterations};
  };
  auto solve = [&](Real v, const std::vector<Real>& from, std::vector<Real>& state, long& it) {
    const bool ok = cs.solve(v, from, state, it);
    out.solves = cs.solves;
    out.newton_iterations = cs.newton;
    return ok;
  };
  std::vector<Real> state, trial;
  long iterations = 0;
  Real v = options.start_voltage;
  if (!solve(v, std::vector<Real>(contact_state.begin(), contact_state.begin() + n), state,
             iterations))
    throw SolverError(
        fmt::format("pull-out: no equilibrium in contact at {:.4g} V from the given "
                    "state",
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

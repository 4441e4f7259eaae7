#include "coupling/quasi_static_pull_out.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "core/structural_systems.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "solvers/kinsol_solver.hpp"
#include "solvers/pseudo_transient_relaxation.hpp"

namespace rfmems {

namespace {

// The structure's stiffness diagonal at rest: the pseudo-mass of the relaxation.
std::vector<Real> rest_stiffness_diagonal(ParallelPlateActuation& act) {
  const CsrPattern& k = act.structure().stiffness_pattern();
  std::vector<Real> values(k.nnz()), zero(act.size(), 0.0), d(act.size());
  act.structure().stiffness(0.0, zero, values);
  for (Index i = 0; i < act.size(); ++i) d[i] = std::abs(values[k.find(i, i)]);
  return d;
}

struct ContactSolver {
  ParallelPlateActuation& act;
  StaticSystem system;
  Real tolerance;  // on ||F||_inf [N]
  KinsolSolver solver;
  std::vector<Real> pseudo_mass;
  bool relax;
  long solves = 0, newton = 0, relaxation_steps = 0;
  ContactSolver(ParallelPlateActuation& a, const PullOutOptions& options)
      : act(a),
        system(a),
        tolerance(options.newton_tolerance * stiffness_scale(a) * a.initial_gap()),
        solver(system,
               [&] {
                 KinsolOptions kin;
                 kin.max_iterations = options.max_newton_iterations;
                 kin.line_search = true;
                 kin.relative_tolerance = options.newton_tolerance;
                 kin.residual_scale = stiffness_scale(a) * a.initial_gap();
                 return kin;
               }()),
        pseudo_mass(rest_stiffness_diagonal(a)),
        relax(options.relax) {}
  // The equilibrium at voltage v from `from`: the pseudo-transient flow to within
  // kRelaxed x the tolerance (the nearest stable equilibrium), then Newton to the tolerance.
  // Released: an equilibrium off the dielectric, or (Newton alone) none found, the fold;
  // Failed: the relaxation or its Newton polish did not converge (not a release).
  static constexpr Real kRelaxed = 100;
  enum class Outcome { Contact, Released, Failed };
  Outcome solve(Real v, const std::vector<Real>& from, std::vector<Real>& state, long& iterations) {
    act.set_voltage_squared([v](Real) { return v * v; });
    state = from;
    ++solves;
    iterations = 0;
    if (relax && !relax_to(kRelaxed * tolerance, state)) return Outcome::Failed;
    const std::vector<Real> relaxed = state;
    bool converged = false;
    try {
      const NonlinearStats stats = solver.solve(0.0, state);
      iterations = stats.newton_iters;
      newton += iterations;
      // KINSOL can stop with a warning (a stalled line search at the fold, where the Jacobian
      // is singular and no solution exists below it): only a small residual is an equilibrium.
      converged = stats.final_residual <= 10 * tolerance;
    } catch (const std::exception&) {  // SolverError, RecoverableError from the film/gap
    }
    if (!converged) {
      if (!relax) return Outcome::Released;  // no equilibrium near: past the fold
      // Near a fold of the branch Newton is slow (singular Jacobian): the flow goes on.
      state = relaxed;
      if (!relax_to(10 * tolerance, state)) return Outcome::Failed;
    }
    return act.min_gap(state) < act.contact().gap ? Outcome::Contact : Outcome::Released;
  }
  bool relax_to(Real target, std::vector<Real>& state) {
    PseudoTransientOptions pt;
    pt.tolerance = target;
    pt.initial_step = 100;  // from a nearby equilibrium: start coarse, SER shrinks it if needed
    const PseudoTransientStats s = relax_pseudo_transient(system, state, pseudo_mass, pt);
    relaxation_steps += s.steps;
    newton += s.newton_iterations;
    return s.converged;
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
  const std::vector<Real> controlled = follow_displacement(act, control, guess, path, qs);
  std::vector<Real> state(controlled.begin(), controlled.begin() + n), trial;
  Real v = std::sqrt(std::max(controlled[n], 0.0));
  ContactSolver cs(act, options);
  long iterations = 0;
  Real ratio = 1 / options.step_ratio;
  while (v < voltage) {
    const Real next = std::min(voltage, v * ratio);
    if (cs.solve(next, state, trial, iterations) == ContactSolver::Outcome::Contact) {
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
  // true: in contact at v; false: released at v; a failed solve is an error, not a release.
  auto solve = [&](Real v, const std::vector<Real>& from, std::vector<Real>& state, long& it) {
    const ContactSolver::Outcome outcome = cs.solve(v, from, state, it);
    out.solves = cs.solves;
    out.newton_iterations = cs.newton;
    out.relaxation_steps = cs.relaxation_steps;
    if (outcome == ContactSolver::Outcome::Failed)
      throw SolverError(fmt::format(
          "pull-out: the relaxation to the equilibrium at {:.6g} V did not converge", v));
    return outcome == ContactSolver::Outcome::Contact;
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

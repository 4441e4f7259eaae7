// Quasi-static pull-out (release): the lowest voltage at which a switch pulled in stays on the
// dielectric, from the static equilibrium in contact (the actuation's contact penalty,
// contact_penalty.hpp) under voltage control.
//
// On a lumped actuator voltage control is regular on the contact branch: the penalty's
// stiffness V^2 A p1(g_c) phi'(s)/delta outweighs the electrostatic softening. On a plate it is
// not: the contact front sits between cells, and the cell next to it is softened by
// V^2 eps0 / g_ec^3 per area, more than the plate's bending stiffness per cell at the default
// switch's 10-20 um cells above ~50 V, so the branch folds each time the front moves by a cell
// (docs/pull-in.md, "Contact and pull-out"). Each solve therefore first follows the
// pseudo-transient flow from the previous contact state (pseudo_transient_relaxation.hpp: the
// nearest stable equilibrium, through those local snaps) and then polishes with Newton.
//
// From a state resting on the dielectric (pulled in: the end of a dynamic approach, or
// press_onto_dielectric) the equilibrium R(y) + V^2 q(y) = 0 is solved at start_voltage, then at
// V_{k+1} = step_ratio V_k, each from the previous contact state, while the solution stays in
// contact (min gap < g_c). The first voltage whose equilibrium is off the dielectric (or,
// Newton alone, without an equilibrium: the fold) and the last with one in contact bracket the
// pull-out voltage; bisection, always from the last contact state, narrows the bracket to
// voltage_tolerance. A relaxation that does not converge is a SolverError, not a release.
//
// For a lumped parallel-plate actuator (spring k, area A, gap g0 over a dielectric t_d, eps_r,
// contact gap g_c) the contact equilibrium k (g0 - g) = A V^2 (p1(g) - p_c) exists down to
//   V_PO = g_ec sqrt(2 k (g0 - g_c) / (eps0 A)),    g_ec = g_c + t_d / eps_r,
// (p_c -> 0 as the penetration -> 0), which test_contact_pull_out.cpp checks.
#pragma once
#include <span>
#include <vector>

#include "physics/electrostatics/parallel_plate_actuation.hpp"

namespace rfmems {

struct PullOutOptions {
  Real start_voltage = 0;         // [V] a voltage above the pull-in voltage
  Real step_ratio = 0.9;          // descent V_{k+1} = step_ratio V_k
  Real voltage_tolerance = 0.01;  // [V] on the pull-out voltage
  Real newton_tolerance = 1e-10;  // KINSOL: ||F||_inf <= this x k_ref g0
  int max_newton_iterations = 50;
  // Each solve first relaxes by pseudo-transient continuation from the previous contact state
  // (pseudo_transient_relaxation.hpp), then Newton polishes: the stable contact equilibrium
  // through the contact branch's local folds. false: Newton alone (a lumped actuator).
  bool relax = true;
};

struct ContactBranchPoint {
  Real voltage;           // [V]
  Real control;           // the control unknown's deflection [m]
  Real min_gap;           // [m]
  Real contact_fraction;  // of the electrode's area
  long newton_iterations;
};

struct QuasiStaticPullOut {
  Real pull_out_voltage = 0;  // the lowest voltage found with a contact equilibrium
  Real released_voltage = 0;  // the highest found without one (within voltage_tolerance)
  std::vector<ContactBranchPoint> branch;  // in order of decreasing voltage, pull-out last
  long solves = 0, newton_iterations = 0, relaxation_steps = 0;
  std::vector<Real> state;  // the structure at the pull-out voltage
};

// contact_state: the structure's unknowns (its first size() entries are read) resting on the
// dielectric near start_voltage. control: the index of y_c. The actuation must have a contact
// penalty; its voltage function is overwritten.
QuasiStaticPullOut trace_pull_out(ParallelPlateActuation& actuation, Index control,
                                  std::span<const Real> contact_state,
                                  const PullOutOptions& options);

// A state on the dielectric at `voltage` from a displacement-controlled guess (structure
// unknowns, then V^2; e.g. the quasi-static fold state): displacement control until the control
// unknown presses half a penetration in, then voltage control up to `voltage` in steps of
// 1/step_ratio. Works where the contact branch from the touching point rises in V to `voltage`
// (a lumped actuator); a membrane's folds first (SolverError), so a switch study takes its
// contact state from the dynamic approach instead.
std::vector<Real> press_onto_dielectric(ParallelPlateActuation& actuation, Index control,
                                        std::span<const Real> guess, Real voltage,
                                        const PullOutOptions& options);

}  // namespace rfmems

// Quasi-static pull-out (release): the lowest voltage at which a switch pulled in stays on the
// dielectric, from the static equilibrium in contact (the actuation's contact penalty,
// contact_penalty.hpp) under voltage control.
//
// Voltage control is regular on the contact branch: the penalty's stiffness V^2 A p1(g_c)
// phi'(s)/delta outweighs the electrostatic softening wherever a cell rests on the dielectric.
// KINSOL (exact Newton + KLU, line search) solves R(y) + V^2 q(y) = 0 at start_voltage (above
// the pull-in voltage, where only contact equilibria exist) from a guess pressed onto the
// dielectric, then at V_{k+1} = step_ratio V_k, each from the previous contact state, while the
// solution stays in contact (min gap < g_c). The first voltage without a contact equilibrium
// (Newton fails, or converges to a state off the dielectric: the unstable branch) and the last
// with one bracket the pull-out voltage; bisection, always from the last contact state, narrows
// the bracket to voltage_tolerance.
//
// For a lumped parallel-plate actuator (spring k, area A, gap g0 over a dielectric t_d, eps_r,
// contact gap g_c) the contact equilibrium k (g0 - g) = A V^2 (p1(g) - p_c) exists down to
//   V_PO = g_ec sqrt(2 k (g0 - g_c) / (eps0 A)),    g_ec = g_c + t_d / eps_r,
// (p_c -> 0 as the penetration -> 0), which test_contact_pull_out.cpp checks.
#pragma once
#include <span>
#include <vector>

#include "coupling/parallel_plate_actuation.hpp"

namespace rfmems {

struct PullOutOptions {
  Real start_voltage = 0;        // [V] a voltage above the pull-in voltage
  Real step_ratio = 0.9;         // descent V_{k+1} = step_ratio V_k
  Real voltage_tolerance = 0.01; // [V] on the pull-out voltage
  Real newton_tolerance = 1e-10; // KINSOL: ||F||_inf <= this x k_ref g0
  int max_newton_iterations = 50;
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
  long solves = 0, newton_iterations = 0;
  std::vector<Real> state;    // the structure at the pull-out voltage
};

// guess: a deflected structure (e.g. the quasi-static fold state); it is scaled so that the
// control unknown presses the dielectric before the first solve. control: the index of y_c.
// The actuation must have a contact penalty; its voltage function is overwritten.
QuasiStaticPullOut trace_pull_out(ParallelPlateActuation& actuation, Index control,
                                  std::span<const Real> guess, const PullOutOptions& options);

}  // namespace rfmems

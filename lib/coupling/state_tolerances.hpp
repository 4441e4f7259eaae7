// IDA's absolute tolerances per kind of unknown of a switch system (switch_system.hpp:
// StateKind), so that the local error test weighs errors by what they do to the motion.
//
// IDA weighs component i by 1 / (rtol |y_i| + atol_i). One scalar atol on unknowns in m, rad,
// m/s and Pa weighs none of them by its physics; from rest (|y| = 0) atol alone sets the
// test, and a tiny one makes IDA follow every small high-frequency bending mode a voltage step
// excites (docs/pull-in.md, "Work against error"). Scales that follow from one length tolerance d:
//
//   displacement   d [m]            an error of d in the gap is what the quantity of interest
//                                    (the pull-in time, the gap history) tolerates;
//   velocity       d * rate [m/s]    a velocity error that moves the structure by d in
//                                    1/rate: rate = omega_1 (the fundamental, whose motion
//                                    decides pull-in) weighs u and v/omega_1 alike, i.e. the
//                                    error in the first mode's energy norm;
//   pressure       d * p_a / g0 [Pa] an isothermal film (p g = const) answers a gap error d
//                                    with this pressure error;
//   quasi-static   given [rad]       the plate's rotations are algebraic (fixed by w); with
//                                    suppress_quasi_static they leave the error test (IDA's
//                                    suppressalg) and the value only scales Newton's test.
#pragma once
#include <vector>

#include "coupling/switch_system.hpp"
#include "solvers/ida_integrator.hpp"

namespace rfmems {

struct SwitchScene;

struct StateTolerances {
  Real displacement = 0;   // d [m]; 0: off (IdaOptions::atol on every unknown)
  Real velocity_rate = 0;  // [1/s]; 0: IdaOptions::atol on the velocities
  Real pressure = 0;       // [Pa]; 0: IdaOptions::atol on the pressures
  Real quasi_static = 0;   // [unit of the unknown]; 0: IdaOptions::atol
  bool suppress_quasi_static = false;
  bool enabled() const { return displacement > 0; }
};

// The per-component atols for a system with these kinds (unset scales: scalar_atol).
std::vector<Real> absolute_tolerances(const std::vector<StateKind>& kinds,
                                      const StateTolerances& tolerances, Real scalar_atol);

// The scales above for a scene, from d = `displacement` [m] and the velocity rate [1/s]: film
// pressures d p_a / g0 (none without a film), rotations d over the mean cell size of the
// structure's mesh, suppressed from the error test (the driver's solver.error_weights:
// per_kind and bench_pullin_work_error build theirs here).
StateTolerances per_kind_tolerances(const SwitchScene& scene, Real displacement,
                                    Real velocity_rate);

// `ida` with the state tolerances installed (unchanged if they are off, or the system does not
// classify its unknowns, or in fixed-step mode).
IdaOptions with_state_tolerances(IdaOptions ida, const SwitchSystem& system,
                                 const StateTolerances& tolerances);

}  // namespace rfmems

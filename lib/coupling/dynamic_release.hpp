// Dynamic release (pull-out): a switch pulled in by a step voltage rests on the dielectric
// (the actuation's contact penalty, contact_penalty.hpp), then the voltage drops to a hold
// value; IDA's release root (dynamic_pull_in.hpp: the smallest gap rising through
// contact_gap + lift) tells whether and when the structure lifts off.
//
//   approach:  step to `voltage` from rest, through touch-down, on in contact until the drop
//              (`delay` after touch-down, or at `drop_time`); the state there is stored;
//   hold:      from the stored state at the hold voltage (IDACalcIC makes the derivatives
//              consistent with the drop) until release or drop + window.
//
// The dynamic pull-out voltage is found by bisection on the hold voltage between one that
// releases within the window and one that holds, every run starting from the same stored
// state (the approach is integrated once).
#pragma once
#include "coupling/dynamic_pull_in.hpp"

namespace rfmems {

struct ReleaseOptions {
  Real voltage = 0;     // [V] the step that pulls the switch in
  Real delay = 0;       // [s] the drop, this long after touch-down...
  Real drop_time = -1;  // [s] ...or at this time (>= 0)
  Real window = 0;      // [s] a hold that has not released by drop + window holds
  Real lift = 0;        // [m] released when the smallest gap exceeds contact_gap + lift
};

struct ReleaseApproach {
  DynamicRun run;     // the approach (history; pull-in time)
  DynamicState drop;  // the state at the drop
};

// base: the dynamic options (IDA, contact gap, output interval); the system's actuation must
// have a contact penalty. SolverError if the step does not pull in before the drop.
ReleaseApproach approach_contact(SwitchSystem& system, Index control, const DynamicOptions& base,
                                 const ReleaseOptions& release);

// The run from the drop at the hold voltage: released, release_time (absolute), history.
DynamicRun run_hold(SwitchSystem& system, Index control, const DynamicState& drop,
                    Real hold_voltage, const DynamicOptions& base, const ReleaseOptions& release);

struct DynamicPullOut {
  Real voltage = 0;       // the lowest hold voltage found to hold (upper bracket end)
  Real released = 0;      // the highest found to release
  Real release_time = 0;  // at `released`, after the drop [s]
  int runs = 0;
  long steps = 0, residual_evals = 0;
};

// Bisection on the hold voltage in [low, high] (low must release, high must hold) until
// high - low <= tolerance. SolverError if the bracket is wrong.
DynamicPullOut find_dynamic_pull_out(SwitchSystem& system, Index control, const DynamicState& drop,
                                     Real low, Real high, Real tolerance,
                                     const DynamicOptions& base, const ReleaseOptions& release);

}  // namespace rfmems

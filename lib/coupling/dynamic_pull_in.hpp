// Dynamic pull-in: the transient response of a switch to a voltage waveform, with IDA
// (adaptive order and step) and the run's events (run_events.hpp):
//
//   contact:  min_gap(y) - contact_gap          falls through 0: touch-down, the pull-in time;
//                                                the run ends, or (with the actuation's
//                                                contact penalty, stop_at_contact false) goes
//                                                on with the structure resting on the
//                                                dielectric;
//   turning:  the control unknown retreated      from its extreme towards the electrode by
//             (two roots, turning_back.hpp)      turning_retreat of that excursion: the
//                                                structure turned back before touching, so
//                                                (for a step voltage, undamped or underdamped)
//                                                it will not pull in; the run ends early
//                                                unless told to go on (release studies);
//   settled:  at rest at a stable static        checked after every accepted step (with
//             equilibrium (settled_at_rest.hpp)  stop_at_turning and the fold's deflection
//                                                known): a damped creep below V_dyn that
//                                                never turns back has not pulled in;
//   past fold: beyond the unstable equilibrium    checked after every accepted step (with
//             of the step voltage, moving down   stop_at_turning, stop_past_fold and the
//             (past_unstable_equilibrium.hpp)    fold's branch known): pull-in is certain, the
//                                                run ends pulled in, without a touch-down
//                                                time (a creep past the fold of a damped
//                                                switch that end_time would cut short);
//   release:  min_gap(y) - release_gap           rises through 0 (armed with release_gap > 0):
//                                                the structure lifted off the dielectric, the
//                                                run ends and reports the release time.
//
// A run can start from a stored state (DynamicState: the state in contact where the voltage
// drops to a hold value, coupling/dynamic_release.hpp); IDACalcIC then makes the derivatives
// consistent with the new voltage.
//
// The dynamic pull-in voltage is found by bisection on the step voltage between a value that
// does not pull in and one that does, to a tolerance in volts. Without damping it is ~0.92 of
// the quasi-static one for a parallel-plate actuator with a linear spring (Nielson & Barbastathis
// 2006: the energy balance at the turning point), a little different for a membrane.
#pragma once
#include <functional>
#include <vector>

#include "coupling/coupling_settings.hpp"
#include "coupling/past_unstable_equilibrium.hpp"
#include "coupling/settled_at_rest.hpp"
#include "coupling/state_tolerances.hpp"
#include "coupling/switch_system.hpp"
#include "coupling/turning_back.hpp"
#include "physics/structure/free_response.hpp"
#include "solvers/ida_integrator.hpp"

namespace rfmems {

struct DynamicOptions {
  Real end_time = 0;                       // the run gives up (not pulled in) here (absolute time)
  Real contact_gap = 0;                    // touch-down when the smallest gap reaches this [m]
  bool stop_at_turning = true;             // end when the control unknown turns back (see above)
  Real turning_retreat = kTurningRetreat;  // the retreat that counts as turned back
                                           // (coupling/turning_back.hpp)
  Real settle_tolerance = kSettleTolerance;  // with stop_at_turning: end when settled at a
                                             // stable equilibrium (settled_at_rest.hpp; 0: off)
  // The quasi-static fold and its unstable branch (quasi_static_pull_in.hpp; unknown: neither
  // the settle rule, which needs the fold's deflection, nor the past-fold rule).
  FoldBranch fold;
  bool stop_past_fold = true;  // with stop_at_turning: end pulled in when past the unstable
                               // equilibrium (past_unstable_equilibrium.hpp; needs a voltage
                               // that does not fall)
  Real past_fold_margin = kPastFoldMargin;  // beyond it by this fraction of |x_fold|
  bool stop_at_contact = true;   // end at touch-down (false: go on in contact; needs a penalty)
  Real stop_after_contact = -1;  // >= 0 (with stop_at_contact false): end this long after
                                 // touch-down (where a release study drops the voltage)
  Real release_gap = 0;          // > 0: end when the smallest gap rises through this (release)
  Real output_interval = 0;      // > 0: record samples every this much (else only events)
  IdaOptions ida;
  // Error weights per kind of unknown (state_tolerances.hpp); off: ida.atol on every unknown.
  StateTolerances tolerances;
  // How the scene's models are stepped together (coupling_settings.hpp); run_dynamic is the
  // monolithic scheme, the field- and film-coupled runners read the scheme and its settings.
  CouplingOptions coupling;
};

// `options` with IDA's rtol and every absolute tolerance (scalar, per unknown, per kind of
// unknown) times `factor`; the velocity weights' rate is a ratio and stays. A run at factor
// 0.1 beside one at 1 estimates the latter's integration error (IDA's global error is roughly
// proportional to its tolerances).
DynamicOptions with_tolerances_scaled(DynamicOptions options, Real factor);

struct DynamicSample {
  Real t, control, min_gap, electrostatic_force, gas_force;
  Real contact_force = 0, voltage = 0;
};

// The integrator's state at time t (structure and film unknowns, and their derivatives).
struct DynamicState {
  Real t = 0;
  std::vector<Real> y, yp;
};

struct DynamicRun {
  bool pulled_in = false;
  Real pull_in_time = 0;   // time of (the first) touch-down (pulled_in; 0 if past_fold)
  bool past_fold = false;  // pulled in: ended past the unstable equilibrium, before contact
  int touch_downs = 0;     // contact root crossings downwards (bounces count again)
  bool released = false;
  Real release_time = 0;     // time of lift-off (released)
  Real turning_time = 0;     // time of the first turning point (0: none)
  bool settled = false;      // came to rest at a stable equilibrium (final_time: when)
  Real extreme_control = 0;  // the control unknown's most negative value
  Real final_time = 0;
  DynamicState final_state;
  IntegratorStats stats;
  std::vector<DynamicSample> history;
};

// The small-signal response of a run's history (physics/structure/free_response.hpp) in the
// control's deflection.
FreeResponse free_response(const std::vector<DynamicSample>& history);

// A run's two step rules, checked after every accepted step by the time loop (time_loop.hpp,
// run_events.hpp): settled at rest (no pull-in) and past the
// unstable equilibrium (pulled in).
struct EarlyEnds {
  SettledAtRest settle{0.0, 0.0};  // off
  PastUnstableEquilibrium past;    // off
  bool armed() const { return settle.armed() || past.armed(); }
  // After an accepted step at time t and voltage V with the control's deflection x and
  // velocity v and the gas and electrostatic forces: records settled or pulled in past the
  // fold in run (nothing once it has pulled in); true: the run ends.
  bool at_step(Real t, Real voltage, Real x, Real v, Real gas_force, Real electrostatic_force,
               DynamicRun& run);
};

// The rules: off without stop_at_turning or with the fold unknown; the past-fold rule also
// without stop_past_fold.
EarlyEnds early_ends(bool stop_at_turning, Real settle_tolerance, const FoldBranch& fold,
                     bool stop_past_fold, Real past_fold_margin);
EarlyEnds early_ends(const DynamicOptions& options);

// The monolithic scheme: the switch system in one IDA system, stepped by the time loop
// (time_loop.hpp). `voltage(t)` [V] is installed into the system's actuation; control indexes
// the structure. From rest at t = 0, or from `start`.
DynamicRun run_dynamic(SwitchSystem& system, Index control, std::function<Real(Real)> voltage,
                       const DynamicOptions& options, const DynamicState* start = nullptr);

struct DynamicPullIn {
  Real voltage = 0;              // the smallest voltage found to pull in (upper bracket end)
  Real lower = 0;                // the largest found not to
  Real pull_in_time = 0;         // at `voltage`, its touch-down (0: none by end_time)
  bool upper_past_fold = false;  // the bisection's run at `voltage` ended past the unstable
                                 // equilibrium (pull_in_time: from its step run again)
  int runs = 0;
  int settled_runs = 0;                // runs ended by the settle rule
  int past_fold_runs = 0;              // runs ended pulled in by the past-fold rule
  long steps = 0, residual_evals = 0;  // summed over the runs
};

// The shape of the applied voltage, scaled by its amplitude V:
//   step   V for t >= 0
//   ramp   V t / rise_time up to rise_time, then V
//   pulse  a step (or ramp) held until release_time, then hold_fraction V (a hold voltage;
//          0: switched off) - for release and hold studies
struct VoltageWaveform {
  enum class Kind { Step, Ramp, Pulse };
  Kind kind = Kind::Step;
  Real rise_time = 0;      // ramp (and the rise of a pulse); 0: a step
  Real release_time = 0;   // pulse
  Real hold_fraction = 0;  // pulse
  std::function<Real(Real)> at(Real amplitude) const;
};

// Bisection on the amplitude of the waveform (a step by default) in [low, high] (low must
// not pull in, high must) until high - low <= tolerance. SolverError if the bracket is wrong.
// An upper end that ended past the unstable equilibrium is run once more without that rule,
// for its touch-down time (counted in runs, steps and residual_evals).
DynamicPullIn find_dynamic_pull_in(SwitchSystem& system, Index control, Real low, Real high,
                                   Real tolerance, const DynamicOptions& options,
                                   const VoltageWaveform& waveform = {});

// The same bisection with any run: runner(amplitude) integrates from rest (e.g. a partitioned
// scheme, coupling/field_coupled_structure.hpp); end_time only for the message. to_contact: the
// same run without the past-fold rule (empty: an upper end past the fold keeps no time).
using PullInRunner = std::function<DynamicRun(Real amplitude)>;
DynamicPullIn find_dynamic_pull_in(const PullInRunner& runner, Real low, Real high, Real tolerance,
                                   Real end_time, const PullInRunner& to_contact = {});

}  // namespace rfmems

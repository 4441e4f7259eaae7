// A pull-in study of a switch scene (switch_scene.hpp), as the case file asks:
//
//   pull_in:
//     mode: quasi_static              # quasi_static | dynamic | transient
//     quasi_static:
//       points: 40                    # samples of the control deflection in (0, max_fraction g0]
//       max_fraction: 0.9
//       voltage_tolerance: 0.01 V     # on the fold voltage
//     dynamic:                        # a voltage waveform from rest, IDA with contact/turning
//     roots
//       waveform: {type: step}        # step (default) | ramp {rise_time} | pulse {rise_time,
//                                     # release_time, hold: fraction of the amplitude}
//       end_time: 50 us               # a run that has not touched down by then did not pull in
//       contact_gap: 0.1 um           # touch-down at this gap (default 2 % of the gap)
//       bracket: [150 V, 190 V]       # bisection bracket (default [0.8, 1.02] x the
//                                     # quasi-static V_PI, computed first)
//       tolerance: 0.5 V              # on the dynamic pull-in voltage
//       stop_at_turning: true         # a bisection run that turns back did not pull in
//                                     # (false: run to touch-down or end_time)
//       settle_tolerance: 1e-2        # settled, no pull-in: velocity, acceleration and film
//                                     # force below this fraction of the peak velocity, peak
//                                     # acceleration and electrostatic force, on the stable
//                                     # branch (settled_at_rest.hpp; 0: off)
//       past_fold_margin: 0.05        # pulled in (no touch-down time): beyond the unstable
//                                     # equilibrium of the step voltage by this fraction of
//                                     # the fold's deflection, moving towards the electrode;
//                                     # above V_qs once it moves (past_unstable_equilibrium.hpp)
//       turning_retreat: 0.02         # turned back: the control retreated from its extreme
//                                     # by this fraction of the excursion (turning_back.hpp;
//                                     # a higher mode's wiggle on a damped creep does not)
//       voltages: [170 V, 180 V]      # step voltages whose histories are recorded (default:
//                                     # 0.97 and 1.03 x the dynamic V_PI)
//       output_interval: 0.1 us       # sampling of the recorded histories
//       time_check: 0.1               # the upper end's step once more to contact at this
//                                     # fraction of the solver's tolerances: the pull-in
//                                     # time's error estimate (0: none; near the fold t_PI
//                                     # amplifies IDA's local errors 10-100x, BENCHMARKS 56)
//       small_signal: 0.3             # a step to this fraction of the quasi-static V_PI,
//                                     # recorded to end_time: damping ratio and frequency of
//                                     # the free response (0: none; default 0.3)
//       laplace_coupling: staggered   # laplace scenes: staggered (default; the field once per
//                                     # IDA step, gap-scaled lagged load) | implicit (the field
//                                     # in every residual call; laplace_dynamic_switch.hpp)
//     release:                        # optional, needs actuation.contact: after touch-down the
//                                     # voltage drops to a hold value (dynamic_release.hpp)
//       hold_voltage: 10 V            # the hold whose history is recorded
//       voltage: 180 V                # the step that pulls in (default 1.03 x the dynamic V_PI)
//       delay: 2 us                   # the drop, after touch-down (default 2 us), or
//       time: 20 us                   #   at this time
//       window: 20 us                 # a hold not released by drop + window holds (default 20 us)
//       lift: 0.19 um                 # released: the smallest gap above contact gap + lift
//                                     # (default 5 % of the gap)
//       tolerance: 0.5 V              # bisection on the hold: the dynamic pull-out (0: none)
//       bracket: [0 V, 40 V]          # default [0, voltage]
//     transient:                      # mode transient: one step voltage from rest, integrated
//       voltage: 180 V                #   by the coupling scheme (coupling_settings.hpp) to
//       end_time: 5 us                #   end_time or touch-down; no quasi-static curve
//       output_interval: 0.1 us       # monolithic sampling (default end_time / 500); the
//                                     # partitioned schemes sample at their macro steps
//       contact_gap: 0.1 um           # touch-down (default 2 % of the gap; with
//                                     # actuation.contact its gap); the run stops there
//   solver:                           # dynamic runs (IDA): rtol (default 1e-3), atol (default
//     rtol: 1e-3                      # 1e-4 x the gap) and max_order (default 2)
//     jacobian_refresh: 0.05          # refresh the Jacobian when c_j = alpha/h moves by this
//                                     #   fraction (IDASetDeltaCjLSetup; default 0: IDA's 0.25)
//
// With actuation.contact dynamic histories go on in contact after touch-down, and a release
// study also finds the quasi-static pull-out voltage on the contact branch from the pulled-in
// state of its approach (quasi_static_pull_out.hpp).
// Quasi-static: parallel_plate scenes by KINSOL under displacement control
// (quasi_static_pull_in.hpp), laplace scenes by the strongly coupled iteration
// (laplace_pull_in.hpp). Dynamic: parallel_plate scenes by one monolithic IDA system
// (switch_system.hpp); laplace scenes by the plane beam under the Laplace field recomputed per
// IDA step (laplace_dynamic_switch.hpp; step waveform, no gas, no contact), and the summary's
// pull_in.dynamic.electrostatics says which.
#pragma once
#include <string>
#include <vector>

#include "coupling/dynamic_pull_in.hpp"
#include "coupling/dynamic_release.hpp"
#include "coupling/laplace_dynamic_switch.hpp"
#include "coupling/partitioned_switch.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/quasi_static_pull_out.hpp"
#include "coupling/switch_scene.hpp"
#include "io/json_summary.hpp"
#include "io/result_writer.hpp"

namespace rfmems {

struct PullInSettings {
  bool dynamic = false;
  QuasiStaticOptions quasi_static;
  DynamicOptions run;                 // end_time, contact_gap, output_interval, ida
  Real bracket_low = 0, bracket_high = 0;  // 0: from the quasi-static V_PI
  Real tolerance = 0.5;
  std::vector<Real> voltages;         // empty: around the dynamic V_PI
  Real small_signal = 0.3;            // fraction of the quasi-static V_PI (0: none)
  Real time_check = 0.1;              // tolerance factor of the pull-in time's check (0: none)
  VoltageWaveform waveform;
  LaplaceCoupling laplace_coupling = LaplaceCoupling::Staggered;  // laplace scenes
  // pull_in.release
  bool release = false;
  ReleaseOptions release_options;     // voltage 0: from the dynamic V_PI
  Real hold_voltage = 0;
  Real release_tolerance = 0.5;       // 0: no bisection
  Real release_bracket_low = 0, release_bracket_high = 0;  // high 0: the default
  // pull_in.mode: transient, and root.coupling
  bool transient = false;
  Real transient_voltage = 0;
  DynamicOptions transient_run;  // end_time, contact_gap, output_interval, ida
  PartitionedOptions coupling;   // scheme Monolithic unless the case says otherwise
};

PullInSettings read_pull_in_settings(const CaseNode& root, const SwitchScene& scene);

struct PullInReport {
  QuasiStaticPullIn quasi_static;
  bool has_dynamic = false;
  std::string waveform;               // step, ramp or pulse
  DynamicPullIn dynamic;
  // The upper end's step to contact at time_check_factor x the tolerances (0: not run): its
  // pull-in time against dynamic.pull_in_time estimates the latter's integration error.
  Real time_check_factor = 0;
  DynamicRun time_check;
  std::vector<std::pair<Real, DynamicRun>> histories;  // (voltage, run)
  Real small_signal_voltage = 0;
  FreeResponse small_signal;
  long laplace_solves = 0;
  long dynamic_laplace_solves = 0;    // laplace scenes: field solves of the dynamic study
  std::string dynamic_coupling;       // laplace scenes: staggered | implicit
  bool has_pull_out = false;          // the scene has contact
  QuasiStaticPullOut pull_out;
  bool has_release = false;
  ReleaseApproach approach;           // the step before the drop
  Real release_voltage = 0, hold_voltage = 0;
  DynamicRun hold;                    // from the drop at hold_voltage
  bool has_dynamic_pull_out = false;
  DynamicPullOut dynamic_pull_out;
  bool has_transient = false;   // mode transient: only this run (no quasi-static curve)
  PartitionedOptions coupling;  // the scheme that ran it
  DynamicRun transient;         // history: monolithic at output_interval, partitioned
                                // at the macro steps
  long coupling_iterations = 0, macro_steps = 0;  // partitioned schemes
  double transient_wall_s = 0, transient_cpu_s = 0;
};

// Runs the study; writes the fold's fields (index 0), the curve (/pull_in/curve,
// pull_in_results.hpp), with contact the contact branch (/pull_in/contact_branch: abscissa
// voltage, values control, min_gap, contact_fraction) and the histories (/dynamic/V<k>,
// pull_in_results.hpp; the small-signal run is /dynamic/small_signal, the release
// /dynamic/release: the approach and the hold) into `writer`.
// Mode transient: only the run, /dynamic/transient, and the end state's fields (index 0).
PullInReport run_pull_in_study(SwitchScene& scene, const PullInSettings& settings,
                               ResultWriter& writer);

// The --json object's pull-in part.
Json pull_in_summary(const SwitchScene& scene, const PullInReport& report);

}  // namespace rfmems

// The pull-in study of a switch scene (switch_scene.hpp), one for every combination of models
// (scene_combinations.hpp), driven through the scene's coupling manager (coupling_manager.hpp),
// as the case file asks:
//
//   pull_in:
//     mode: dynamic                   # static | quasi_static | dynamic | transient | harmonic
//                                     # (the scene's allowed analyses: scene_combinations.hpp)
//     contact_gap: 0.1 um             # touch-down of every run at this gap (default 2 % of the
//                                     # gap, and no less than the field resolves: 1.5
//                                     # background cells of the immersed field); with
//                                     # actuation.contact its gap
//     static: {voltage: 50 V}         # static: the equilibrium at this voltage
//     quasi_static:
//       points: 40                    # samples of the control deflection in (0, max_fraction g0]
//       max_fraction: 0.9
//       voltage_tolerance: 0.01 V     # on the fold voltage
//       modes: 3                      # parallel_plate: the lowest modes at rest and at every
//                                     # stable point of the curve (bias_modes.hpp; default 0:
//                                     # none), the frequency against the DC bias
//     dynamic:                        # a voltage waveform from rest, with the events of
//                                     # dynamic_pull_in.hpp
//       waveform: {type: step}        # step (default) | ramp {rise_time} | pulse {rise_time,
//                                     # release_time, hold: fraction of the amplitude};
//                                     # parallel_plate only (the others: a step)
//       end_time: 50 us               # a run that has not touched down by then did not pull in
//       bracket: [150 V, 190 V]       # bisection bracket (default [0.8, 1.02] x the
//                                     # quasi-static V_PI, computed first)
//       tolerance: 0.5 V              # on the dynamic pull-in voltage (default 0.3 % of the
//                                     # quasi-static V_PI: a fixed voltage is coarse on a
//                                     # slender structure's few volts; the validity report
//                                     # warns above 1 %)
//       stop_at_turning: true         # a bisection run that turns back did not pull in
//                                     # (false: run to touch-down or end_time)
//       settle_tolerance: 1e-2        # settled, no pull-in: velocity, acceleration and gas
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
//                                     # 0.97 and 1.03 x the dynamic V_PI; []: none)
//       output_interval: 0.1 us       # sampling of the recorded histories (default end/500)
//       time_check: 0.1               # the upper end's step once more to contact at this
//                                     # fraction of the solver's tolerances: the pull-in
//                                     # time's error estimate (0: none; default 0.1, 0 with
//                                     # the esbgk gas, where it is one more long run; near the
//                                     # fold t_PI amplifies IDA's local errors 10-100x)
//       small_signal: 0.3             # a step to this fraction of the quasi-static V_PI,
//                                     # recorded to end_time: damping ratio and frequency of
//                                     # the free response (0: none; default 0.3)
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
//     transient:                      # mode transient: one step voltage from rest to end_time
//       voltage: 180 V                #   or touch-down, by the coupling scheme
//       end_time: 5 us                #   (coupling_settings.hpp); no quasi-static curve
//       output_interval: 0.1 us       # sampling (default end_time / 500)
//     harmonic:                       # mode harmonic (parallel_plate): the small-signal response
//       bias: 40 V                    #   to an AC voltage about this DC bias (below the
//       sweep: {from: 10 kHz, to: 1 MHz, points: 61}  # quasi-static V_PI, traced first),
//                                     #   or frequencies: [...] (io/frequency_sweep.hpp);
//                                     #   harmonic_under_bias.hpp
//   solver:                           # every run (IDA)
//     rtol: 1e-3                      # default 1e-3
//     atol: 0.375 nm                  # displacements (default 1e-4 x the gap; per_kind: rtol x
//                                     # the gap)
//     error_weights: scalar           # scalar | per_kind (state_tolerances.hpp; not with the
//     velocity_frequency: 1 MHz       #   immersed field, which weights the velocities by its
//                                     #   first bending period); per_kind: the velocities'
//                                     #   atol is 2 pi velocity_frequency x atol
//     max_order: 2                    # default 2
//     jacobian_refresh: 0.05          # refresh the Jacobian when c_j = alpha/h moves by this
//                                     #   fraction (IDASetDeltaCjLSetup; default 0: IDA's 0.25)
//     fixed_step: 0                   # > 0: IDA at this fixed step (no error test; cut to 1e-4
//                                     #   of it only after a failed Newton solve)
//
// Every section is checked whatever the mode, so that a case switched between modes by --set
// stays valid; the active mode's required keys must be there. With actuation.contact dynamic
// histories go on in contact after touch-down, and a release study also finds the quasi-static
// pull-out voltage on the contact branch from the pulled-in state of its approach
// (quasi_static_pull_out.hpp).
#pragma once
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "coupling/bias_modes.hpp"
#include "coupling/coupling_manager.hpp"
#include "coupling/dynamic_pull_in.hpp"
#include "coupling/dynamic_release.hpp"
#include "coupling/harmonic_under_bias.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/quasi_static_pull_out.hpp"
#include "coupling/switch_scene.hpp"
#include "io/json_summary.hpp"
#include "io/result_writer.hpp"

namespace rfmems {

// The bisection's default tolerance, a fraction of the quasi-static pull-in voltage.
constexpr Real kRelativeBisectionTolerance = 3e-3;

struct PullInSettings {
  Analysis analysis = Analysis::QuasiStatic;
  Real static_voltage = 0;  // static
  QuasiStaticOptions quasi_static;
  Index bias_modes = 0;                    // quasi_static.modes
  DynamicOptions run;                      // dynamic: end_time, contact_gap, output_interval, ida,
                                           // coupling
  Real bracket_low = 0, bracket_high = 0;  // 0: from the quasi-static V_PI
  Real tolerance = 0;                      // [V]; 0: kRelativeBisectionTolerance x V_qs
  bool histories = true;                   // false: voltages: []
  std::vector<Real> voltages;              // empty: around the dynamic V_PI
  Real small_signal = 0.3;                 // fraction of the quasi-static V_PI (0: none)
  Real time_check = 0.1;                   // tolerance factor of the pull-in time's check (0: none)
  VoltageWaveform waveform;
  // pull_in.release
  bool release = false;
  ReleaseOptions release_options;  // voltage 0: from the dynamic V_PI
  Real hold_voltage = 0;
  Real release_tolerance = 0.5;                            // 0: no bisection
  Real release_bracket_low = 0, release_bracket_high = 0;  // high 0: the default
  // pull_in.transient
  Real transient_voltage = 0;
  DynamicOptions transient_run;  // end_time, contact_gap, output_interval, ida, coupling
  // pull_in.harmonic
  Real harmonic_bias = 0;                  // [V]
  std::vector<Real> harmonic_frequencies;  // [Hz]
  // Bad input naming the case file and pull_in.harmonic.bias (the bias is checked against the
  // pull-in voltage once the curve is traced).
  std::function<void(const std::string& what)> reject_bias;
  std::FILE* progress = nullptr;  // a line per dynamic run (null: none)
};

PullInSettings read_pull_in_settings(const CaseNode& root, const SwitchScene& scene);

struct PullInReport {
  bool has_static = false;
  Real static_voltage = 0;
  SwitchStatic static_state;
  bool has_quasi_static = false;
  QuasiStaticPullIn quasi_static;
  std::vector<BiasedModes> bias_modes;  // quasi_static.modes > 0
  bool has_dynamic = false;
  std::string waveform;  // step, ramp or pulse
  DynamicPullIn dynamic;
  Real tolerance = 0;  // the bisection's [V]
  // The upper end's step to contact at time_check_factor x the tolerances (0: not run): its
  // pull-in time against dynamic.pull_in_time estimates the latter's integration error.
  Real time_check_factor = 0;
  DynamicRun time_check;
  std::vector<std::pair<Real, DynamicRun>> histories;  // (voltage, run)
  Real small_signal_voltage = 0;
  FreeResponse small_signal;
  bool has_pull_out = false;  // the scene has contact
  QuasiStaticPullOut pull_out;
  bool has_release = false;
  ReleaseApproach approach;  // the step before the drop
  Real release_voltage = 0, hold_voltage = 0;
  DynamicRun hold;  // from the drop at hold_voltage
  bool has_dynamic_pull_out = false;
  DynamicPullOut dynamic_pull_out;
  bool has_transient = false;  // mode transient: only this run (no quasi-static curve)
  DynamicRun transient;        // history: at output_interval
  double transient_wall_s = 0, transient_cpu_s = 0;
  bool has_harmonic = false;  // mode harmonic: the quasi-static curve, then this
  HarmonicUnderBias harmonic;
  Real contact_gap = 0;  // of the timed runs (dynamic, transient)
  Json counters;         // the coupling manager's (coupling_manager.hpp)
};

// Runs the study; writes the structure's fields (index 0: at the fold, the static state or the
// transient's end), the curve (/pull_in/curve, pull_in_results.hpp), the modes under bias
// (/pull_in/modes: abscissa voltage, values control_displacement and f1 ... fN [Hz]), with contact
// the contact branch (/pull_in/contact_branch: abscissa voltage, values control, min_gap,
// contact_fraction) and the histories (/dynamic/V<k>, pull_in_results.hpp; the small-signal
// run is /dynamic/small_signal, the release /dynamic/release: the approach and the hold; the
// transient /dynamic/transient; the harmonic response /pull_in/harmonic, its fields at index 0 the
// biased static state) into `writer`.
PullInReport run_pull_in_study(SwitchScene& scene, const PullInSettings& settings,
                               ResultWriter& writer);

// The summary's pull_in object: the scene's models, the coupling and what the study found.
Json pull_in_summary(const SwitchScene& scene, const PullInSettings& settings,
                     const PullInReport& report);

// The keys read_pull_in_settings reads: the study and IDA's settings (pull_in_study.keys.yaml;
// io/case_schema.hpp).
CaseSchema pull_in_case_keys();

}  // namespace rfmems

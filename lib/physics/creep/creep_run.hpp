// A creep run over hundreds or thousands of hours: integrates a CreepSystem from its
// elastic state at t = 0 to the end time with the implicit (IDA, adaptive BDF) or the explicit
// (forward Euler, fixed dt; the thesis's baseline) integrator, records a time series and the
// fields at the output times, stops at the end of the switch's life, and checkpoints.
//
// Lifetime. With a gap (CreepRunModel::min_gap: the smallest air gap g0 + w over the cells over
// the electrode), the run stops at the first of
//   - gap threshold:   min gap = threshold (0: touch-down, or a user gap): an IDA root on
//                      g1 = min_gap - threshold; explicit: linear interpolation between the
//                      two steps that bracket the crossing;
//   - collapse:        under a hold voltage the equilibrium disappears at a fold before the gap
//                      closes (creep-induced pull-in): the gap rate grows like 1/sqrt(t_f - t).
//                      Root g2 = min_gap + eps t d(min_gap)/dt (eps = collapse_fraction): the
//                      time the gap would take to close at its current rate has dropped below
//                      eps t, so t is the life to a relative error ~eps. Explicit: the same
//                      test with the rate of the last step;
//   - lost equilibrium: the integrator fails to find an equilibrium (past the fold before the
//                      collapse root fired): the last time reached, reported as such.
// The life is the time of the first event; the run records it (series row and fields).
//
// Checkpoint/restart, exact by construction. The output times t_k (fixed by the settings) cut
// the run into segments. Every segment starts from scratch: a fresh system (make_system) and a
// fresh integrator initialised with (t_k, y, y'), in the uninterrupted run as in a restarted
// one, so a run restarted from a checkpoint written at t_k repeats exactly the arithmetic of
// the run that never stopped (bit for bit; no factorisation, pivot order, Krylov or BDF history
// survives a segment). The checkpoint triggers (every N steps, every T wall seconds) only
// decide at which t_k a checkpoint is *written*, never where the integration restarts. The
// price: each segment's IDA starts again at order 1 with a small step (a few extra steps per
// output), and the system is rebuilt per output (its setup, not its solve).
#pragma once
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "io/checkpoint.hpp"
#include "physics/creep/creep_system.hpp"

namespace rfmems {

struct CreepRunSettings {
  enum class Integration { Implicit, Explicit };
  Integration integration = Integration::Implicit;
  Real explicit_dt = 3600;         // [s], explicit only
  Real rtol = 1e-6, atol = 1e-12;  // IDA (atol on the states: strains and metres)
  // Each segment's first IDA step: the last step of the previous segment (true), or IDA's own
  // estimate (false: restarts from a small step, ~10 more steps per segment).
  bool segment_initial_step_from_previous = true;
  bool krylov = true;              // IDA's linear solver: SPGMR with the system's
                                   // preconditioner (if it has one), else KLU
  std::vector<Real> output_times;  // > 0, increasing; the last one is the end time
  // Lifetime events (need CreepRunModel::min_gap).
  bool gap_threshold_event = false;
  Real gap_threshold = 0;  // [m]
  bool collapse_event = false;
  Real collapse_fraction = 1e-3;  // eps of the collapse root
  // Checkpoints (written at output times; 0: trigger off; no path: none).
  std::string checkpoint_path;
  long checkpoint_every_steps = 0;
  Real checkpoint_every_seconds = 0;
  std::string settings_hash;  // stored in checkpoints, checked on restart

  Real end_time() const { return output_times.empty() ? 0 : output_times.back(); }
  // Throws InputError for inconsistent settings.
  void validate() const;
};

// What the run needs of the model (the driver builds these from a case).
struct CreepRunModel {
  // A fresh system (called once per segment; see the banner).
  std::function<std::unique_ptr<CreepSystem>()> make_system;
  // Smallest air gap of a state [m]; null: no gap (no lifetime events).
  std::function<Real(std::span<const Real> state)> min_gap;
  // The gap's rate d(min_gap)/dt from (state, state'), for the collapse root; null: none.
  std::function<Real(std::span<const Real> state, std::span<const Real> state_dot)> min_gap_rate;
  // One row of the time series at (t, state), named by series_columns.
  std::vector<std::string> series_columns;
  std::function<std::vector<double>(CreepSystem&, Real t, std::span<const Real> state)> sample;
  // The fields kept for an output (written to the result file at the end and carried in
  // checkpoints).
  std::function<std::map<std::string, std::vector<double>>(CreepSystem&, Real t,
                                                           std::span<const Real> state)>
      output_fields;
  // Called after every segment (progress reports): time reached, last step, steps so far.
  std::function<void(Real t, Real last_step, long steps)> on_segment;
};

struct CreepOutput {
  Real time = 0;
  std::map<std::string, std::vector<double>> fields;
};

struct CreepRunResult {
  enum class End { EndTime, GapThreshold, Collapse, EquilibriumLost };
  End end = End::EndTime;
  Real final_time = 0;
  Real lifetime = std::numeric_limits<Real>::quiet_NaN();  // the event's time, if one ended it
  std::vector<Real> state, state_dot;                      // at final_time
  std::vector<Real> series_times;
  std::vector<std::vector<double>> series;  // rows of series_columns
  std::vector<CreepOutput> outputs;         // t = 0, the output times, the event
  long steps = 0;                           // integrator steps, all segments
  Real last_step = 0;                       // IDA's last step size
  long segments = 0;                        // integrated in this process
  int checkpoints_written = 0;
  bool restarted = false;
  Real restart_time = 0;
  std::string message;  // EquilibriumLost: the solver's

  bool life_reached() const { return end != End::EndTime; }
};

std::string to_string(CreepRunResult::End end);  // "end_time", "gap_threshold", ...

// Runs from t = 0 (restart == nullptr) or from a checkpoint of the same settings (its hash must
// equal settings.settings_hash, else InputError naming the file). `checkpoint_file` names the
// restart file in messages.
CreepRunResult run_creep(const CreepRunModel& model, const CreepRunSettings& settings,
                         const Checkpoint* restart = nullptr,
                         const std::string& checkpoint_file = "");

}  // namespace rfmems

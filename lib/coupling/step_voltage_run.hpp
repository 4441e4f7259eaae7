// What the field-coupled beams (laplace_dynamic_switch.hpp, immersed_switch.hpp) share in a
// step-voltage run from rest in IDA's one-step mode, where the field is exchanged after every
// step IDA accepts:
//
//   roots    g0 = min_gap(u) - contact_gap: falls through 0 at touch-down (the pull-in time;
//            the run ends); g1, g2 = the turning-back rule's (turning_back.hpp: the control
//            retreated from its extreme by options.turning_retreat of its excursion; no
//            pull-in for a step voltage), as run_dynamic's (dynamic_pull_in.hpp);
//   events   after each step, the extreme deflection, the touch-down and the first turning
//            recorded in the DynamicRun, and whether the run ends; then, on the step's record
//            (its forces at the accepted state), the settle rule (settled_at_rest.hpp: at rest
//            at a stable equilibrium, no pull-in) and the past-fold rule
//            (past_unstable_equilibrium.hpp: beyond the unstable equilibrium, pulled in), as
//            run_dynamic's;
//   history  one record per accepted step, kept as it is or resampled at output_interval:
//            cubic Hermite in the control's deflection and velocity, the other columns linear.
#pragma once
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "core/linear_functional.hpp"
#include "coupling/dynamic_pull_in.hpp"
#include "coupling/past_unstable_equilibrium.hpp"
#include "coupling/settled_at_rest.hpp"
#include "coupling/turning_back.hpp"
#include "solvers/ida_integrator.hpp"

namespace rfmems {

// The state after an accepted step (or at rest).
struct StepRecord {
  Real t, control, velocity, min_gap, electrostatic_force, gas_force;
};

class StepVoltageEvents {
 public:
  // turning_retreat: TurningBack's r; turning_after: extremes count from this time on (the
  // immersed beam's higher modes can flip the control's velocity in the first quarter period).
  // ends: the step rules (off by default; early_ends in dynamic_pull_in.hpp makes them).
  StepVoltageEvents(bool stop_at_turning, Real turning_retreat, Real turning_after = 0,
                    EarlyEnds ends = {})
      : stop_at_turning_(stop_at_turning),
        turning_(turning_retreat, turning_after),
        ends_(std::move(ends)) {}

  // Installs g0..g2 on ida: min_gap of the displacements (the state's first n entries), the
  // turning rule on the control's deflection and velocity, functionals of the state (one
  // unknown each, or a point value and its velocity). The events object must outlive the
  // integration.
  void set_roots(IdaIntegrator& ida, Index n, LinearFunctional control, LinearFunctional velocity,
                 Real contact_gap, std::function<Real(std::span<const Real>)> min_gap) const;

  // After a step that returned status at time t with the control's deflection control:
  // records the extreme, a touch-down and the first turning in run; true: the run ends.
  bool after_step(const IdaIntegrator& ida, IdaIntegrator::Status status, Real t, Real control,
                  DynamicRun& run);

  // Then, for a run that after_step did not end, on the accepted state's record at the step
  // voltage: records settled or pulled in past the fold in run; true: the run ends.
  bool after_record(const StepRecord& record, Real voltage, DynamicRun& run);

 private:
  bool stop_at_turning_;
  TurningBack turning_;
  EarlyEnds ends_;
};

// Fills run's final time, state and stats from ida and its history at voltage from records
// (every record for output_interval <= 0). through_final_time: uniform samples up to and
// including the final time (the immersed switch's), else before it; the last record closes
// the history either way.
void finish_step_voltage_run(const IdaIntegrator& ida, const std::vector<StepRecord>& records,
                             Real voltage, Real output_interval, bool through_final_time,
                             DynamicRun& run);

}  // namespace rfmems

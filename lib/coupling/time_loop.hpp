// The one time loop of every switch run, whichever scheme steps the models: the monolithic
// system (run_dynamic, dynamic_pull_in.hpp) and the partitioned schemes of the field-coupled
// structure (field_coupled_structure.hpp) differ only in what a step is and what is exchanged
// after it.
//
// From IDA's current state the loop steps towards the run's stop time, and after every accepted
// point (a step, a root):
//   1. the run's events (run_events.hpp): a root is touch-down, turning back or lift-off; at the
//      end time (or stop_after_contact past touch-down) the run ends;
//   2. the scheme's exchange (a partitioned scheme refreshes the field's load and advances the
//      gas; the monolithic system has none);
//   3. the step rules, settled at rest and past the unstable equilibrium (EarlyEnds);
//   4. history samples at the output times passed (the state from IDA's interpolating
//      polynomial, as its normal mode returns it) and where the run ends.
// A scheme without an exchange lets IDA run to each output time in its normal mode unless the
// step rules need every step (the same internal steps, fewer returns). Output times never cut
// a step: a fixed step stays fixed.
#pragma once
#include <functional>
#include <span>

#include "coupling/dynamic_pull_in.hpp"
#include "solvers/ida_integrator.hpp"

namespace rfmems {

// What the events watch at a state: the smallest gap, the control's deflection and velocity.
struct RunWatch {
  Real min_gap = 0, control = 0, velocity = 0;
};

// What the step rules weigh at a state: the voltage and the electrostatic and gas forces.
struct RunForces {
  Real voltage = 0, electrostatic = 0, gas = 0;
};

// A scheme's part in the loop.
struct TimeLoopScheme {
  // The events' inputs at a state (IDA's root functions and every accepted point).
  std::function<RunWatch(std::span<const Real> y, std::span<const Real> yp)> watch;
  // The step rules' inputs at IDA's current state, time t (after the exchange).
  std::function<RunForces(Real t, std::span<const Real> y)> forces;
  // The history sample at state y, time t within the last step (after its exchange).
  std::function<DynamicSample(Real t, std::span<const Real> y)> sample;
  // One coupled step towards t_stop, never beyond it; empty: one IDA step.
  std::function<IdaIntegrator::Status(Real t_stop)> step;
  // After every accepted point at time t; last: the run ends there, run: what it recorded so
  // far. Empty: nothing is exchanged.
  std::function<void(Real t, bool last, const DynamicRun& run)> exchange;
  Real turning_after = 0;  // the turning rule counts extremes from this time on
};

// Runs from IDA's current time (initialised and consistent) until an event ends the run or
// options.end_time; the run's events, samples, final state and IDA's counters.
DynamicRun run_time_loop(IdaIntegrator& ida, const DynamicOptions& options,
                         const TimeLoopScheme& scheme);

}  // namespace rfmems

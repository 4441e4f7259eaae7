// The events of every switch run, watched by its one time loop (time_loop.hpp): IDA's root
// functions on the smallest gap and the control's deflection x and velocity v,
//
//   g0 = min_gap - contact_gap   falls through 0: touch-down (the pull-in time); the run ends,
//                                or (stop_at_contact false, with a contact penalty) goes on,
//                                until stop_after_contact past it;
//   g1, g2                       the turning-back rule's (turning_back.hpp): the structure
//                                turned back before touching; the run ends unless told to go on;
//   g3 = min_gap - release_gap   rises through 0 (release_gap > 0): lift-off, the run ends;
//
// and, after every accepted step, the settle and past-fold rules (EarlyEnds). Each records
// what happened in the run's DynamicRun.
#pragma once
#include <span>
#include <vector>

#include "coupling/dynamic_pull_in.hpp"
#include "coupling/turning_back.hpp"

namespace rfmems {

class RunEvents {
 public:
  static constexpr int kRoots = 2 + TurningBack::kRoots;
  // turning_after: the turning rule counts extremes from this time on.
  explicit RunEvents(const DynamicOptions& options, Real turning_after = 0);

  void roots(Real min_gap, Real x, Real v, std::span<Real> g) const;
  // After IDA stopped at a root at time t with the control at x: records a touch-down, a
  // lift-off and the first turning in run; true: the run ends.
  bool at_root(Real t, Real x, const std::vector<int>& found, DynamicRun& run);
  // Where the run ends unless an event ends it first: end_time, or touch-down +
  // stop_after_contact once it has touched down (stop_at_contact false).
  Real stop_time() const { return stop_time_; }
  // The step rules are armed: the caller must stop after every accepted step (IDA's one-step
  // mode) and call at_step.
  bool step_rules_armed() const { return ends_.armed(); }
  // After an accepted step at time t and voltage V: records settled or pulled in past the fold
  // in run; true: the run ends.
  bool at_step(Real t, Real voltage, Real x, Real v, Real gas_force, Real electrostatic_force,
               DynamicRun& run) {
    return ends_.at_step(t, voltage, x, v, gas_force, electrostatic_force, run);
  }

 private:
  const DynamicOptions& options_;
  TurningBack turning_;
  EarlyEnds ends_;
  Real stop_time_;
};

}  // namespace rfmems

// Dynamic pull-in of a plane (2D) beam with the full electrostatic field: the beam's
// elastodynamics M u'' + K u = f(u) under the Maxwell traction of the Laplace field in a gap
// mesh that follows it (laplace_gap_field.hpp), integrated by IDA (BDF, adaptive order and
// step) in one-step mode, from rest under a step voltage V.
//
// Per accepted IDA step (Staggered): move the gap mesh to the beam's new bottom, solve
// Laplace, traction on the beam's bottom faces; that force is the reference of the next
// step's gap-scaled lagged load (gap_scaled_lagged_load.hpp), so inside a step the load
// follows the parallel-plate gap dependence (g_ref / g)^2 and the Jacobian carries the
// electrostatic softening. The staggering error is first order in the step. Implicit: the
// field is solved inside every residual call (the exact coupled residual; the scaled lagged
// load only in the Jacobian), the reference the staggered scheme is measured against; it costs
// a field solve per Newton iteration.
//
// Roots as run_dynamic (dynamic_pull_in.hpp): the smallest bottom-cell gap g0 + u_y,c reaching
// contact_gap (touch-down: the pull-in time; the run ends) and the control's velocity rising
// through zero after it moved down (turned back: no pull-in for a step voltage). The dynamic
// pull-in voltage is then find_dynamic_pull_in's bisection with run() as the runner.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "coupling/dynamic_pull_in.hpp"
#include "coupling/laplace_gap_field.hpp"
#include "coupling/scene_combinations.hpp"

namespace rfmems {

struct LaplaceStatic {
  std::vector<Real> u;
  Real control = 0;  // deflection of the control unknown [m]
  int iterations = 0;
};

// CPU seconds by physics, summed over runs since reset_times().
struct LaplaceSwitchTimes {
  double move = 0, field = 0, structure = 0;
  long field_solves = 0, structure_steps = 0;
};

class LaplaceDynamicSwitch {
 public:
  // beam: the plane elasticity operator (with density), its patch bottom_patch over the
  // electrode across gap; control: the reported unknown (a u_y).
  LaplaceDynamicSwitch(ElasticityOperator& beam, const std::string& bottom_patch, Real gap,
                       const ElectrodeExtent& electrode, Index control,
                       const LaplaceGapOptions& options = {});

  // A step voltage (options.coupling.scheme staggered or implicit, see above) from rest to
  // options.end_time, touch-down or (stop_at_turning) turning back, settling or passing the
  // unstable equilibrium (with options.fold; step_voltage_run.hpp). Uses end_time, contact_gap,
  // stop_at_turning, output_interval (> 0: the history resampled at it, cubic Hermite in the
  // control's deflection and velocity; else every step), ida and tolerances (per-kind atols:
  // displacement, velocity_rate).
  DynamicRun run(Real voltage, const DynamicOptions& options);

  // Static equilibrium K u = V^2 q(u) by fixed point (one KLU factorisation of K), to a
  // relative change of the control's deflection <= tolerance (below pull-in it contracts).
  LaplaceStatic solve_static(Real voltage, Real tolerance = 1e-10, int max_iterations = 200);

  LaplaceGapField& field() { return field_; }
  Index control() const { return control_; }
  const LaplaceSwitchTimes& times() const { return times_; }
  void reset_times() { times_ = {}; }

 private:
  ElasticityOperator& beam_;
  LaplaceGapField field_;
  Index control_;
  LaplaceSwitchTimes times_;
};

}  // namespace rfmems

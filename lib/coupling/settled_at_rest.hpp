// Whether a step response has come to rest at a stable static equilibrium of the applied
// voltage (no pull-in), so that the run can end early: the rule for strongly damped or
// overdamped switches (damping ratio near or above 1), which below V_dyn creep monotonically
// towards their equilibrium and never turn back (turning_back.hpp), shared by the dynamic
// runners as the turning rule is (run_dynamic in dynamic_pull_in.hpp).
//
// The structure's equation M a + F_gas(v) = F_el(u, V) - K u says that it is at a static
// equilibrium when inertia and damping have died out. Three conditions, each with the reason:
//
//   at rest      |v| <= s v_peak and |a| <= s a_peak: the control's velocity and
//                acceleration (the difference of v over the last accepted step) have decayed to
//                a fraction s of the run's peaks (for an exponential approach x - x_eq ~ -v tau,
//                the distance left is about s of the excursion). The acceleration is what an
//                underdamped swing's extreme fails: v = 0 and no film force there, but the
//                inertia M a carries the static imbalance;
//   balanced     |F_gas| <= s |F_el|: the film, which carries the difference of the
//                electrostatic and elastic forces while the structure creeps, has let go -
//                the static residual F_el - K u is small. This is what a slow passage just
//                above the fold fails: there no equilibrium exists, and the film carries at
//                least F_el(V^2 / V_qs^2 - 1) (about 6 % of F_el at 1.03 V_qs), while a
//                higher mode's wiggle can zero the control's velocity but not the film's
//                integrated force;
//   stable       |x| < |x_fold| and V <= V_qs: the control is on the stable branch of the
//                quasi-static curve (quasi_static_pull_in.hpp: under displacement control the
//                points before the fold are stable), not near the saddle beyond it, which an
//                underdamped run at V_dyn approaches with the velocity and film force dying;
//                and above the fold voltage there is no equilibrium to rest at (within 0.1 %
//                of V_qs the film's share, ~2 (V / V_qs - 1) of F_el, falls below s: a slow
//                passage there looked settled; docs/pull-in.md, "Bisection end rules").
//
// s = settle_tolerance (default 1e-2); the rule is off without the fold's deflection (0) or
// with s = 0. Checked after every step IDA accepts.
#pragma once

#include "core/types.hpp"

namespace rfmems {

// The default s (docs/pull-in.md, "Bisection end rules").
inline constexpr Real kSettleTolerance = 1e-2;

class SettledAtRest {
 public:
  // tolerance: s above; fold_control: the control's deflection at the quasi-static fold
  // (negative; 0: unknown, the rule never fires); fold_voltage: V_qs (0: unknown, no bound).
  SettledAtRest(Real tolerance, Real fold_control, Real fold_voltage = 0)
      : tolerance_(tolerance), fold_control_(fold_control), fold_voltage_(fold_voltage) {}

  bool armed() const { return tolerance_ > 0 && fold_control_ != 0; }

  // After an accepted step ending at t at voltage V with the control's deflection x and
  // velocity v and the gas and electrostatic forces on the structure: true when it has settled
  // (the first time only).
  bool at_step(Real t, Real x, Real v, Real gas_force, Real electrostatic_force, Real voltage = 0);

  bool settled() const { return settled_; }

 private:
  Real tolerance_, fold_control_, fold_voltage_;
  Real peak_velocity_ = 0, peak_acceleration_ = 0;
  Real last_t_ = 0, last_v_ = 0;  // the previous step's
  bool settled_ = false;
};

}  // namespace rfmems

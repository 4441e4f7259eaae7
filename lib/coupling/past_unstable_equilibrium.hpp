// Whether a step response has passed the unstable static equilibrium of the applied voltage
// (pull-in is then certain), so that the run can end early as pulled in: the rule for strongly
// damped or overdamped switches, whose runs between V_dyn and V_qs creep slowly past the fold
// and would otherwise be counted "no pull-in" at end_time, making the bisection's answer a
// figure of end_time (docs/pull-in.md, "Bisection end rules"). Shared by the dynamic runners as
// the turning and settle rules are (run_dynamic in dynamic_pull_in.hpp, the field-coupled
// beam, field_coupled_structure.hpp).
//
// The quasi-static curve (quasi_static_pull_in.hpp) gives, for V < V_qs, two equilibria of the
// control: the stable x_s(V) before the fold and the unstable x_u(V) beyond it. For one degree
// of freedom, m x'' + c x' = F_el(x, V) - k x with F_el - k x pushing towards the electrode at
// every x beyond x_u(V): once the control is beyond x_u(V) and moving towards the electrode, the
// net static force keeps accelerating it that way and the damping, which vanishes with the
// velocity, cannot reverse it - it touches down. Above V_qs no equilibrium exists at all: a
// dissipative system with nowhere to rest (the energy decreases, LaSalle) ends in contact, so a
// step above V_qs pulls in once it moves. The rule, after every accepted step at voltage V:
//
//     V > V_qs:   v < 0 and x < 0;
//     V <= V_qs:  v < 0 and x < x_k(V) - m |x_fold|,
//
// x_k(V) the first sample of the unstable branch, outwards from the fold, whose voltage is <= V
// (the curve's V falls monotonically beyond the fold, so x_u(V) lies between x_k and the
// sample before it: x_k is beyond x_u by at most one sample spacing, never short of it; a
// linear interpolation would fall short near the fold, where V is parabolic in x).
//
// The structure is not one degree of freedom: in a dynamic run its shape carries the higher
// modes and the film's pressure, so the control alone beyond the static x_u does not put the
// whole state past the saddle (a gas spring at a high squeeze number can store energy and push
// back). The margin m (pull_in.dynamic.past_fold_margin, a fraction of the fold's deflection;
// default 0.05) asks for the control to be that much further; a higher mode's share of the
// control's deflection (~1e-10 m on the damped plate, against |x_fold| ~ 6e-7 m) is far below
// it; on the underdamped default plate (zeta 0.012) the bisection's lower end, 0.2 % below
// V_dyn, turns back at 1.39 |x_fold|, short of x_u (between 1.42 and 1.47 |x_fold|) and 0.13
// |x_fold| short of the threshold (test_past_unstable_equilibrium). And a bisection checks its
// upper end: run again without the rule for its touch-down time, it must not turn back or
// settle (find_dynamic_pull_in). Above V_qs the margin is not needed: there is no
// equilibrium whatever the shape (V_qs is the sampled maximum, below the true fold voltage by
// less than the quasi-static voltage_tolerance).
//
// Valid for a voltage that does not fall afterwards (a step, a ramp: x_u moves towards rest as V
// grows); a pulse's drop can release it, so the bisection of a pulse does not arm it.
#pragma once
#include <vector>

#include "core/types.hpp"

namespace rfmems {

struct QuasiStaticPullIn;

// The default m (docs/pull-in.md, "Bisection end rules").
inline constexpr Real kPastFoldMargin = 0.05;

// The quasi-static fold and the unstable branch beyond it (the samples outwards from the fold).
struct FoldBranch {
  Real voltage = 0;  // V_qs (0: unknown)
  Real control = 0;  // the control's deflection at the fold (negative; 0: unknown)
  std::vector<Real> unstable_voltage, unstable_control;

  static FoldBranch of(const QuasiStaticPullIn& quasi_static);
  bool known() const { return voltage > 0 && control != 0; }
};

class PastUnstableEquilibrium {
 public:
  PastUnstableEquilibrium() = default;  // off
  // margin: m above (>= 0; negative: off).
  PastUnstableEquilibrium(const FoldBranch& fold, Real margin) : fold_(fold), margin_(margin) {}

  bool armed() const { return margin_ >= 0 && fold_.known(); }

  // The deflection beyond which a step to V has passed its unstable equilibrium (0 above V_qs;
  // -infinity below the curve's last sample: never).
  Real threshold(Real voltage) const;

  // After an accepted step at voltage V with the control's deflection x and velocity v: true
  // when it has passed (the first time only).
  bool at_step(Real voltage, Real x, Real v);

  bool past() const { return past_; }

 private:
  FoldBranch fold_;
  Real margin_ = -1;
  bool past_ = false;
};

}  // namespace rfmems

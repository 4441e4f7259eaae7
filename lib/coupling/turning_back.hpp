// Whether a step response has turned back from the electrode (no pull-in for a step voltage
// below dynamic pull-in), so that the run can end early: the rule every dynamic runner shares
// (run_dynamic in dynamic_pull_in.hpp, the field-coupled structure's, field_coupled_structure.hpp).
//
// The control's velocity changing sign is not enough: on a squeeze-film-damped switch the
// slow creep towards the fold carries the wiggles of weakly damped higher modes, each a zero
// of the velocity (cases/switch_plate_damped: "84 V does not pull in" while 76 V does,
// docs/pull-in.md, "Damped switches"). A turning counts once the control x (< 0 towards
// the electrode) has retreated from its extreme x_min by a fraction r of that excursion:
//
//     x - x_min >= r |x_min|.
//
// A higher mode's wiggle retreats by about its own amplitude (~1e-10 m on the damped plate,
// against excursions of 3e-8 to 7e-7 m); an underdamped fundamental swings back by up to its
// whole excursion, so r of a few per cent separates the two with a wide margin and the run
// ends a little after the extreme (the time reported is the extreme's).
//
// Two IDA root functions: g_v = the control's velocity (zero at every extreme; where it rises
// through 0 the control is at a local minimum, which updates x_min) and g_r = x - x_min - r
// |x_min| (rises through 0: turned back; -1 until the control has moved down). x_min changes
// only at a root return, where IDA evaluates the root functions afresh before going on, so g_r
// stays continuous within each step. A missed pair of velocity zeros (two inside one step)
// leaves x_min above the true extreme, which only delays the turning.
#pragma once
#include <span>

#include "core/types.hpp"

namespace rfmems {

// The default r: 2 % of the excursion (docs/pull-in.md, "Damped switches").
inline constexpr Real kTurningRetreat = 0.02;

class TurningBack {
 public:
  static constexpr int kRoots = 2;  // g_v, g_r

  // retreat: r above; armed_after: extremes before this time do not count (the immersed
  // beam's higher modes reverse the control in its first quarter period).
  explicit TurningBack(Real retreat, Real armed_after = 0)
      : retreat_(retreat), armed_after_(armed_after) {}

  // g_v and g_r into g[0], g[1] for the control's deflection x and velocity v.
  void roots(Real x, Real v, std::span<Real> g) const;

  // At a root return at time t with the control's deflection x and the flags IDA reports for
  // g_v and g_r (+1 rising, -1 falling, 0 none): true when the control has just turned back
  // (the first time only; turning_time() is then the time of the extreme).
  bool at_root(Real t, Real x, int velocity_root, int retreat_root);

  bool turned() const { return turned_; }
  Real turning_time() const { return turning_time_; }

 private:
  Real retreat_, armed_after_;
  Real extreme_ = 0, extreme_time_ = 0;  // x_min and when
  bool turned_ = false;
  Real turning_time_ = 0;
};

}  // namespace rfmems

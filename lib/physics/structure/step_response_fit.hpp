// The fundamental's damping ratio and frequency from a step response from rest: a least-
// squares fit (Levenberg-Marquardt, Eigen's unsupported NonLinearOptimization with a
// forward-difference Jacobian) of the damped oscillator's step response
//
//   x(t) = x_s + (x_0 - x_s) phi(t),   phi(0) = 1, phi'(0) = 0,
//   zeta < 1:  phi = exp(-zeta w t) (cos(w_d t) + zeta / sqrt(1 - zeta^2) sin(w_d t)),
//              w_d = w sqrt(1 - zeta^2);
//   zeta > 1:  phi = exp(-zeta w t) (cosh(s w t) + zeta / s sinh(s w t)), s = sqrt(zeta^2 - 1)
//              (zeta = 1: (1 + w t) exp(-w t); the two forms meet there continuously),
//
// in x_s, zeta and w to the whole history. Why a fit and not the extrema: the logarithmic
// decrement (free_response.hpp, LogDecrement) needs several swings of the fundamental; on a
// squeeze-film-damped switch (zeta ~ 0.5) there is one overshoot, and the extrema it finds
// belong to a weakly damped higher mode riding on the settled fundamental (0.016 at 937 kHz
// against 0.54, cases/switch_plate_damped, docs/pull-in.md, "Damped switches"). A higher
// mode of small amplitude only adds to the residual.
//
// The fit is started from a grid of damping ratios, each with the frequency that puts phi's
// first half-way point at the measured time of the half-rise, and from a starting guess
// (e.g. the log decrement's), and the smallest residual wins.
#pragma once
#include <span>

#include "core/types.hpp"

namespace rfmems {

struct StepResponseFit {
  bool fitted = false;         // false: too few samples or no motion
  Real damping_ratio = 0;      // zeta
  Real natural_frequency = 0;  // w / (2 pi) [Hz]
  Real damped_frequency = 0;   // w_d / (2 pi) [Hz]; 0 for zeta >= 1
  Real static_deflection = 0;  // x_s
  Real residual = 0;           // rms misfit / |x_s - x_0|
};

// phi above at time t for zeta and w.
Real step_response_shape(Real t, Real zeta, Real omega);

// Fits samples (t_i, x_i) (t_0 the step, x_0 the rest value); guess_zeta and guess_omega
// (> 0) add one starting point to the grid.
StepResponseFit fit_step_response(std::span<const Real> t, std::span<const Real> x,
                                  Real guess_zeta = 0, Real guess_omega = 0);

}  // namespace rfmems

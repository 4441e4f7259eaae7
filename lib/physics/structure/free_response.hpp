// The damping ratio and frequency of a structure's free response: a recorded step response
// x(t) from rest (a switch's control deflection under a small step voltage), by the logarithmic
// decrement of its extrema and by a fit of the damped oscillator's step response.
#pragma once
#include <span>

#include "core/types.hpp"

namespace rfmems {

// The logarithmic decrement of a recorded response x(t) (a step from rest): from the extrema
// e_k of x, the half-swings s_k = |e_{k+1} - e_k| decay as
// exp(-delta/2) per half period for x_eq + a exp(-zeta omega t) cos(omega_d t), so the
// logarithmic decrement delta = 2 ln(s_k / s_{k+1}) (averaged over the swings by a
// least-squares fit of ln s_k) gives zeta = delta / sqrt(4 pi^2 + delta^2), and the spacing
// of the extrema the damped frequency. Extrema are located by parabolas through the samples.
// Valid while the extrema are the fundamental's (light damping); a weakly damped higher mode
// on a heavily damped fundamental takes it over (free_response below).
struct LogDecrement {
  Real damping_ratio = 0;
  Real frequency = 0;  // damped [Hz]
  int swings = 0;      // half-swings used (0: fewer than 2, nothing measured)
};
LogDecrement log_decrement(std::span<const Real> t, std::span<const Real> x);

// The fundamental's small-signal response x(t) of a step from rest (below pull-in, for a
// switch): the damped oscillator's step response fitted to x
// (step_response_fit.hpp; the log decrement's figures are one of its starting points). Where
// the log decrement is valid - at least 4 half-swings whose spacing gives the fit's damped
// frequency within 2 %, so its extrema are the fundamental's - its zeta and frequency are
// reported instead: at light damping they are the less biased by higher modes (a higher mode
// of 1-2 % of the static deflection biases the fit's zeta 2-3x more, test_step_response_fit),
// as in docs/pull-in.md, "Work against error".
struct FreeResponse {
  bool fitted = false;              // false: too few samples or no motion, nothing measured
  bool from_log_decrement = false;  // damping_ratio and frequency are the log decrement's
  Real damping_ratio = 0;           // zeta
  Real frequency = 0;               // damped [Hz] (0: overdamped, zeta >= 1)
  Real natural_frequency = 0;       // undamped [Hz]
  Real residual = 0;                // the fit's rms misfit / |x_s - x_0|
  Real fit_damping_ratio = 0, fit_frequency = 0;  // the fit's zeta and damped frequency
  LogDecrement log_decrement;
};
FreeResponse free_response(std::span<const Real> t, std::span<const Real> x);

}  // namespace rfmems

// The output times of a structural transient and the loop that integrates through them, shared
// by the serial analysis (IdaIntegrator) and the distributed one (DistributedIdaIntegrator).
#pragma once
#include <algorithm>
#include <cmath>

#include "core/types.hpp"

namespace rfmems {

// Number of output intervals from 0 to end_time at spacing dt: k dt up to end_time, and a last,
// shorter interval if end_time is not a multiple of dt (to 1e-9 of dt). At least one.
inline long output_intervals(Real dt, Real end_time) {
  return std::max(1L, static_cast<long>(std::ceil(end_time / dt - 1e-9)));
}

// Advances `ida` to each output time k = 1 .. output_intervals(dt, end_time), calling
// emit(k, t) and then progress(t, ida.stats()) after each. Returns the number of intervals.
template <class Integrator, class Emit, class Progress>
long advance_through_outputs(Integrator& ida, Real dt, Real end_time, Emit&& emit,
                             Progress&& progress) {
  const long n = output_intervals(dt, end_time);
  for (long k = 1; k <= n; ++k) {
    const Real t = k == n ? end_time : static_cast<Real>(k) * dt;
    ida.advance(t);
    emit(static_cast<int>(k), t);
    progress(t, ida.stats());
  }
  return n;
}

}  // namespace rfmems

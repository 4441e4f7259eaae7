#include "coupling/bias_modes.hpp"

#include <algorithm>
#include <cmath>

namespace rfmems {

std::vector<BiasedModes> modes_along_curve(ParallelPlateActuation& actuation, Index control,
                                           const QuasiStaticPullIn& curve,
                                           std::span<const Real> mass, Index n_modes,
                                           const QuasiStaticOptions& options) {
  const Index n = actuation.size();
  std::vector<Real> state = displacement_control_start(actuation, curve);

  std::vector<BiasedModes> out;
  std::vector<Real> y(n, 0.0);
  auto add = [&](Real v2, Real displacement) {
    actuation.set_voltage_squared([v2](Real) { return v2; });
    out.push_back({std::sqrt(std::max(v2, 0.0)), displacement,
                   linearised_modes(actuation, mass, 0.0, y, n_modes).stats.modes});
  };
  add(0.0, 0.0);
  for (const PullInPoint& point : curve.curve) {
    if (!point.stable) continue;
    state = follow_displacement(actuation, control, state, {point.displacement}, options);
    y.assign(state.begin(), state.begin() + n);
    add(state[n], point.displacement);
  }
  return out;
}

Real lumped_gap_fraction(Real v) {
  Real lo = 2.0 / 3, hi = 1;
  for (int i = 0; i < 200; ++i) {
    const Real x = 0.5 * (lo + hi);
    // x^2 (1 - x) decreases on [2/3, 1]: above the target, the root lies to the right.
    (x * x * (1 - x) > 4.0 / 27 * v * v ? lo : hi) = x;
  }
  return 0.5 * (lo + hi);
}

}  // namespace rfmems

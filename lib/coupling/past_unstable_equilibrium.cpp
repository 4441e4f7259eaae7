#include "coupling/past_unstable_equilibrium.hpp"

#include <cmath>
#include <limits>

#include "coupling/quasi_static_pull_in.hpp"

namespace rfmems {

FoldBranch FoldBranch::of(const QuasiStaticPullIn& qs) {
  FoldBranch b;
  b.voltage = qs.pull_in_voltage;
  b.control = qs.pull_in_displacement;
  // The curve runs outwards (increasing |delta|); the unstable points are beyond the fold.
  for (const PullInPoint& p : qs.curve)
    if (!p.stable) {
      b.unstable_voltage.push_back(p.voltage);
      b.unstable_control.push_back(p.displacement);
    }
  return b;
}

Real PastUnstableEquilibrium::threshold(Real voltage) const {
  if (voltage > fold_.voltage) return 0.0;
  for (std::size_t k = 0; k < fold_.unstable_voltage.size(); ++k)
    if (fold_.unstable_voltage[k] <= voltage)
      return fold_.unstable_control[k] - margin_ * std::abs(fold_.control);
  return -std::numeric_limits<Real>::infinity();
}

bool PastUnstableEquilibrium::at_step(Real voltage, Real x, Real v) {
  if (!armed() || past_) return false;
  past_ = v < 0 && x < threshold(voltage);
  return past_;
}

}  // namespace rfmems

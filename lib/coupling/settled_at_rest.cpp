#include "coupling/settled_at_rest.hpp"

#include <algorithm>
#include <cmath>

namespace rfmems {

bool SettledAtRest::at_step(Real x, Real v, Real gas_force, Real electrostatic_force) {
  peak_velocity_ = std::max(peak_velocity_, std::abs(v));
  if (!armed() || settled_ || peak_velocity_ == 0) return false;
  settled_ = std::abs(v) <= tolerance_ * peak_velocity_ &&
             std::abs(gas_force) <= tolerance_ * std::abs(electrostatic_force) &&
             std::abs(x) < std::abs(fold_control_);
  return settled_;
}

}  // namespace rfmems

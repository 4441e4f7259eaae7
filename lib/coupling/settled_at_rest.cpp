#include "coupling/settled_at_rest.hpp"

#include <algorithm>
#include <cmath>

namespace rfmems {

bool SettledAtRest::at_step(Real t, Real x, Real v, Real gas_force, Real electrostatic_force,
                            Real voltage) {
  const Real a = t > last_t_ ? (v - last_v_) / (t - last_t_) : 0.0;
  last_t_ = t;
  last_v_ = v;
  peak_velocity_ = std::max(peak_velocity_, std::abs(v));
  peak_acceleration_ = std::max(peak_acceleration_, std::abs(a));
  if (!armed() || settled_ || peak_velocity_ == 0) return false;
  settled_ = std::abs(v) <= tolerance_ * peak_velocity_ &&
             std::abs(a) <= tolerance_ * peak_acceleration_ &&
             std::abs(gas_force) <= tolerance_ * std::abs(electrostatic_force) &&
             std::abs(x) < std::abs(fold_control_) &&
             (fold_voltage_ == 0 || voltage <= fold_voltage_);
  return settled_;
}

}  // namespace rfmems

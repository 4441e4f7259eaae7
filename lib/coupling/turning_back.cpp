#include "coupling/turning_back.hpp"

#include <cmath>

namespace rfmems {

void TurningBack::roots(Real x, Real v, std::span<Real> g) const {
  g[0] = v;
  g[1] = extreme_ < 0 ? x - extreme_ - retreat_ * std::abs(extreme_) : -1.0;
}

bool TurningBack::at_root(Real t, Real x, int velocity_root, int retreat_root) {
  // The retreat is from the extreme known before this return (a genuine earlier minimum).
  const bool now = retreat_root > 0 && extreme_ < 0 && !turned_;
  if (now) {
    turned_ = true;
    turning_time_ = extreme_time_;
  }
  if (velocity_root > 0 && t >= armed_after_ && x < extreme_) {
    extreme_ = x;
    extreme_time_ = t;
  }
  return now;
}

}  // namespace rfmems

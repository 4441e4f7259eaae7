// The first-order form of M y'' + R(t, y) = 0 (lumped M) for IDA, state Y = [y; v] (n + n):
//   F_y = y' - v,   F_v = M v' + R(t, y),
// Jacobian rows y: [c_j I, -I]; rows v: [dR/dy, c_j M]. One layout for the serial adaptor
// (core/structural_systems.hpp) and the distributed one (parallel/
// distributed_structural_systems.hpp): R's columns past the y block (a rank's ghosts) sit
// past the v block, columns [y; v; ghosts].
#pragma once
#include <span>
#include <vector>

#include "core/system_operator.hpp"

namespace rfmems {

class FirstOrderLayout {
 public:
  // stiffness: the n rows of dR/dy (sorted columns); mass: M's diagonal (n entries).
  FirstOrderLayout(const CsrPattern& stiffness, std::vector<Real> mass);

  Index n() const { return n_; }
  const CsrPattern& pattern() const { return pattern_; }
  // r = [y' - v; M v' + R] with r's v rows holding R(t, y) on entry.
  void complete_residual(std::span<const Real> y, std::span<const Real> yp,
                         std::span<Real> r) const;
  // The Jacobian's values from dR/dy's (stiffness pattern order).
  void jacobian(Real c_j, std::span<const Real> stiffness_values, std::span<Real> values) const;

 private:
  Index n_;
  std::vector<Real> mass_;
  CsrPattern pattern_;
  std::vector<Index> mass_position_;       // value index of (n + i, n + i)
  std::vector<Index> stiffness_position_;  // value index of each stiffness entry
};

}  // namespace rfmems

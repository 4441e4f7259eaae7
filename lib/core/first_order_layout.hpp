// The first-order form of M y'' + C y' + R(t, y) = 0 (lumped M, optional damping C = beta K,
// K = dR/dy) for IDA, state Y = [y; v] (n + n):
//   F_y = y' - v,   F_v = M v' + C v + R(t, y),
// Jacobian rows y: [c_j I, -I]; rows v: [dR/dy, c_j M + beta dR/dy]. One layout for the serial
// adaptor (core/structural_systems.hpp) and the distributed one (parallel/
// distributed_structural_systems.hpp): R's columns past the y block (a rank's ghosts, g of
// them) sit past the v block, columns [y; v; y ghosts], and with damping the ghosts' v after
// them, [y; v; y ghosts; v ghosts].
#pragma once
#include <span>
#include <vector>

#include "core/system_operator.hpp"

namespace rfmems {

class FirstOrderLayout {
 public:
  // stiffness: the n rows of dR/dy (sorted columns, ghosts numbered from n); mass: M's
  // diagonal (n entries); damping_time: beta (0: C = 0, no v columns from K); ghosts: g.
  FirstOrderLayout(const CsrPattern& stiffness, std::vector<Real> mass, Real damping_time = 0,
                   Index ghosts = 0);

  Index n() const { return n_; }
  Real damping_time() const { return beta_; }
  const CsrPattern& pattern() const { return pattern_; }
  // r = [y' - v; M v' + R] with r's v rows holding R(t, y) (+ C v) on entry.
  void complete_residual(std::span<const Real> y, std::span<const Real> yp,
                         std::span<Real> r) const;
  // The Jacobian's values from dR/dy's (stiffness pattern order).
  void jacobian(Real c_j, std::span<const Real> stiffness_values, std::span<Real> values) const;

 private:
  Index n_;
  std::vector<Real> mass_;
  Real beta_;
  CsrPattern pattern_;
  std::vector<Index> mass_position_;       // value index of (n + i, n + i)
  std::vector<Index> stiffness_position_;  // value index of each stiffness entry
  std::vector<Index> damping_position_;    // value index of each beta K entry (with damping;
                                           // -1 on the diagonal, which adds to the mass's)
  std::vector<Index> damping_diagonal_;    // per row: the stiffness entry of (i, i), or -1
};

}  // namespace rfmems

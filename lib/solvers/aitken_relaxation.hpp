// Aitken's Delta^2 update of a fixed-point relaxation factor (Irons & Tuck 1969; Kuettler &
// Wall 2008, eq. 44): with the residuals r_k = G(x_k) - x_k of two successive iterates,
//
//   omega_k = -omega_{k-1} r_{k-1} . (r_k - r_{k-1}) / |r_k - r_{k-1}|^2,
//
// the secant estimate of the step that annihilates the residual along the last change. The
// factor is returned unchanged when the residual did not change (no information).
#pragma once
#include <cstddef>
#include <span>

#include "core/types.hpp"

namespace rfmems {

inline Real aitken_factor(Real omega, std::span<const Real> residual,
                          std::span<const Real> residual_prev) {
  Real num = 0, den = 0;
  for (std::size_t i = 0; i < residual.size(); ++i) {
    const Real dr = residual[i] - residual_prev[i];
    num += residual_prev[i] * dr;
    den += dr * dr;
  }
  return den > 0 ? -omega * num / den : omega;
}

}  // namespace rfmems

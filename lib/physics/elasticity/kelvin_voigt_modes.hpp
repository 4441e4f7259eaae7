// Growth rate of a mode of M u'' + beta K u' + K u = 0 (Kelvin-Voigt damping C = beta K, as
// ElasticityOperator::damping_time): for an eigenvalue lambda of M^-1 K, u ~ exp(s t) with
//   s^2 + beta lambda s + lambda = 0
// (C and K share eigenvectors). Undamped, a complex lambda (the non-symmetric FV stiffness)
// gives one s with Re s = |Im sqrt(lambda)| > 0; damping adds about -beta Re(lambda) / 2.
#pragma once
#include <algorithm>
#include <complex>

#include "core/types.hpp"

namespace rfmems {

// max Re s of the two roots.
inline Real kelvin_voigt_growth_rate(std::complex<Real> lambda, Real beta) {
  const std::complex<Real> root = std::sqrt(beta * beta * lambda * lambda - 4.0 * lambda);
  return std::max((-beta * lambda + root).real(), (-beta * lambda - root).real()) / 2;
}

}  // namespace rfmems

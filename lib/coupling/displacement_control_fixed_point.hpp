// Displacement control of an electrostatically loaded structure by a relaxed fixed point (the
// field-coupled structure's quasi-static trace, field_coupled_structure.hpp): for a
// prescribed deflection delta = l(u) of the control functional l (one unknown, or a point value
// such as a beam's tip), iterate
//
//   z = K^-1 q(u)  (q the load per V^2 at u),  lambda = delta / l(z),
//   u <- u + omega (lambda z - u),  omega by Aitken's Delta^2 (aitken_relaxation.hpp),
//
// until ||lambda z - u||_inf <= tolerance |delta|; then l(u) = delta and V^2 = lambda.
#pragma once
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "core/linear_functional.hpp"
#include "core/types.hpp"
#include "solvers/aitken_relaxation.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

struct DisplacementControlResult {
  Real voltage_squared = 0;  // lambda of the last iterate
  int iterations = 0;        // the index of the last iteration (max_iterations: not converged)
  bool converged = false;
};

// u: the start on entry (e.g. the last solved state scaled to delta), the iterate on return.
// load_per_volt2(u) returns q(u) as a std::vector<Real> of u's length.
template <class LoadPerVolt2>
DisplacementControlResult relax_displacement_control(KluFactorization& stiffness,
                                                     LoadPerVolt2&& load_per_volt2,
                                                     const LinearFunctional& control, Real delta,
                                                     Real tolerance, int max_iterations,
                                                     std::vector<Real>& u) {
  const std::size_t n = u.size();
  std::vector<Real> residual_prev, residual(n);
  Real omega = 1.0;
  DisplacementControlResult out;
  for (; out.iterations < max_iterations; ++out.iterations) {
    std::vector<Real> z = load_per_volt2(u);
    stiffness.solve(z);
    out.voltage_squared = delta / control(z);
    Real largest = 0;
    for (std::size_t i = 0; i < n; ++i) {
      residual[i] = out.voltage_squared * z[i] - u[i];
      largest = std::max(largest, std::abs(residual[i]));
    }
    if (largest <= tolerance * std::abs(delta)) {
      for (std::size_t i = 0; i < n; ++i) u[i] += residual[i];
      out.converged = true;
      break;
    }
    if (!residual_prev.empty()) omega = aitken_factor(omega, residual, residual_prev);
    for (std::size_t i = 0; i < n; ++i) u[i] += omega * residual[i];
    residual_prev = residual;
  }
  return out;
}

}  // namespace rfmems

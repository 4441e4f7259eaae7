// Static equilibrium K u = f(u) of an electrostatically loaded structure at a given voltage by
// the plain fixed point u <- K^-1 f(u) from rest (the field-coupled structure,
// field_coupled_structure.hpp): below pull-in it contracts, by about the
// ratio of the electrostatic to the elastic stiffness. Converged when the control functional
// (a deflection) changes by <= tolerance of itself. The counterpart at a given displacement is
// displacement_control_fixed_point.hpp.
#pragma once
#include <cmath>
#include <span>
#include <vector>

#include "core/linear_functional.hpp"
#include "core/types.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

struct VoltageControlResult {
  std::vector<Real> u;  // the last iterate
  int iterations = 0;
  bool converged = false;
};

// stiffness: K factorised; load(u) returns f(u) as a std::vector<Real> of n entries.
template <class Load>
VoltageControlResult relax_voltage_control(KluFactorization& stiffness, Load&& load, Index n,
                                           const LinearFunctional& control, Real tolerance,
                                           int max_iterations) {
  VoltageControlResult out;
  out.u.assign(n, 0.0);
  for (int it = 0; it < max_iterations; ++it) {
    std::vector<Real> z = load(std::span<const Real>(out.u));
    stiffness.solve(z);
    const Real deflection = control(z);
    const Real change = std::abs(deflection - control(out.u));
    out.u = std::move(z);
    out.iterations = it + 1;
    if (change <= tolerance * std::abs(deflection)) {
      out.converged = true;
      break;
    }
  }
  return out;
}

}  // namespace rfmems

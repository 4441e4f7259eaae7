// Contact of the structure with the dielectric on the electrode, regularised by a smooth
// penalty pressure that pushes the structure back where its air gap g falls below the contact
// gap g_c (the standoff of the touching surfaces: roughness, dimples):
//
//   p_c(g, V) = V^2 p1(g_c) phi(s),     s = (g_c - g) / delta,
//   phi(s) = 0 (s <= 0),   s^2 (0 < s <= 1),   2 s - 1 (s > 1)
//
// with p1 the parallel-plate pressure per V^2 (parallel_plate.hpp: electrical gap
// g + t_d / eps_r, so in contact the dielectric's equivalent gap g_c + t_d / eps_r sets the
// force) and delta the penetration tolerance.
//
// Why scaled by V^2: the penalty then carries the electrostatic load it has to resist at any
// voltage. In contact the electrostatic pressure stays bounded near V^2 p1(g_c)
// (parallel_plate_actuation.hpp: the penetration does not thin the dielectric), so at rest
// V^2 p1(g_c) (1 + O(delta / g_ec)) = p_c + (the structure's lift) and phi(s) <= 1 + delta/g_ec:
// the penetration is at most delta (1 + delta / (2 g_ec)) whatever the voltage, with no
// stiffness to tune, and the contact stiffness 2 V^2 p1(g_c)/delta beats the (bounded)
// electrostatic softening at every depth past s = delta / g_ec. p_c and dp_c/dg are
// continuous (phi is C^1), so Newton and IDA see no kink; the regularisation moves the
// pull-out voltage of a lumped actuator by O((delta / g_ec)^2) (test_contact_pull_out.cpp).
// Without a voltage the penalty vanishes: then nothing presses the structure onto the
// dielectric but its own inertia (a voltage switched off during the approach: not modelled).
#pragma once
#include "core/types.hpp"

namespace rfmems {

struct ContactPenalty {
  Real gap = 0;          // g_c [m]: the air gap at which the surfaces touch
  Real penetration = 0;  // delta [m]; 0: no contact model

  bool enabled() const { return penetration > 0; }

  static Real shape(Real s) { return s <= 0 ? 0.0 : (s <= 1 ? s * s : 2 * s - 1); }
  static Real shape_derivative(Real s) { return s <= 0 ? 0.0 : (s <= 1 ? 2 * s : 2.0); }

  // p_c / V^2 at air gap g [Pa/V^2] (p1_contact = p1(g_c)), and its derivative in g.
  Real pressure_per_volt2(Real g, Real p1_contact) const {
    return enabled() ? p1_contact * shape((gap - g) / penetration) : 0.0;
  }
  Real pressure_per_volt2_derivative(Real g, Real p1_contact) const {
    return enabled() ? -p1_contact * shape_derivative((gap - g) / penetration) / penetration : 0.0;
  }
};

}  // namespace rfmems

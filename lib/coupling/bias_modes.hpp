// The structure's natural frequencies under a DC bias, along its quasi-static pull-in curve
// (quasi_static_pull_in.hpp): at rest and at every stable point of the curve, the structure and
// its parallel-plate actuation linearised about the biased equilibrium
// (physics/structure/modal_analysis.hpp, linearised_modes: the actuation's exact Jacobian, so
// the electrostatic softening -eps0 A V^2 / g^3 of each cell is in K), the lowest modes. The
// film is left out (its damping and spring act on the motion, not on the equilibrium).
//
// As the voltage nears the fold the first frequency falls to zero: the 1-DOF parallel-plate
// actuator has (f / f0)^2 = 1 - (8/27) v^2 / x^3 with v = V / V_PI and x = g / g0 from
// x^2 (1 - x) = (4/27) v^2 (lumped_gap_fraction), which the distributed plate follows to about
// 1 % (docs/modal.md, "Frequency against DC bias").
//
// The states are those of the curve, re-solved by displacement control (follow_displacement)
// from the static equilibrium at a tenth of the fold's voltage.
#pragma once
#include <span>
#include <vector>

#include "coupling/quasi_static_pull_in.hpp"
#include "physics/structure/modal_analysis.hpp"

namespace rfmems {

struct BiasedModes {
  Real voltage = 0;       // [V]
  Real displacement = 0;  // the control unknown's [m]
  std::vector<StructuralMode> modes;
};

// Rest first, then the stable points of `curve` in order. `mass`: the structure's modal mass
// (modal_mass). Leaves the actuation's voltage at the last state's.
std::vector<BiasedModes> modes_along_curve(ParallelPlateActuation& actuation, Index control,
                                           const QuasiStaticPullIn& curve,
                                           std::span<const Real> mass, Index n_modes,
                                           const QuasiStaticOptions& options);

// x = g / g0 of the 1-DOF parallel-plate actuator at v = V / V_PI <= 1 (x in [2/3, 1]).
Real lumped_gap_fraction(Real v);

}  // namespace rfmems

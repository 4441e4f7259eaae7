// The electrostatic hold load of a creeping switch: a voltage V held between the structure and
// the electrode below it, as a parallel-plate pressure on the structure's gap elements
// (physics/electrostatics/parallel_plate.hpp; the same law and conventions as
// physics/electrostatics/parallel_plate_actuation.hpp):
//
//   F_u += V^2 A_e sum_q a_q p1(g_q) n_e,   g_q = g0 + u_q(y)   (n_e: the unit vector of dof_e)
//
// at the elements' gap points (GapElement::points: a plate's w reconstruction at 3 x 3 Simpson
// points per quadrilateral, as the pull-in samples it; none: one point, u = y[dof_e]).
//
// The load grows as creep closes the gap (p1 ~ 1/g^2), which is what shortens a held switch's
// life; its tangent V^2 A_e p1'(g_e) (negative: electrostatic spring softening) makes the
// equilibrium rows of a creep system nonlinear in u.
#pragma once
#include <vector>

#include "core/types.hpp"
#include "physics/electrostatics/parallel_plate.hpp"
#include "physics/structure/structural_model.hpp"

namespace rfmems {

struct CreepHoldVoltage {
  std::vector<GapElement> elements;  // dof: the structural unknown along the gap axis
  Real initial_gap = 0;              // g0 [m], the air gap at u = 0
  ParallelPlateLaw law;
  Real voltage = 0;  // V [V], held constant
};

}  // namespace rfmems

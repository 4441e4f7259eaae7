// Quasi-static film pressure: the Reynolds balance with p' = 0 for a given gap and gap rate,
//   p g' A_c - sum_f flux_f(p) = 0,
// the small squeeze number limit (sigma = 12 mu_eff w L^2 / (p_a g^2) << 1), where the film
// is a pure viscous damper with force proportional to the gap rate. Solved by Newton's method
// from p = p_a with the exact pressure Jacobian and KLU. The first iteration is the Reynolds
// equation linearised about p_a,
//   p g' A_c = sum_f D(p_a, g) T_f (p_N - p_P),
// which is the classic incompressible damping model (Griffin 1966, Starr 1990, Blech 1983),
// p_a g' A_c on the left, up to the cross term (p - p_a) g' A_c of relative size
// (p - p_a)/p_a; further iterations solve the nonlinear quasi-static balance.
//
// Needs at least one Open edge (with Wall edges only the pressure level is undetermined and
// KLU reports a singular matrix: SolverError).
#pragma once
#include <span>
#include <vector>

#include "physics/gas/reynolds_film.hpp"

namespace rfmems {

// Newton iterations from p_a (1: the linearised Reynolds equation).
std::vector<Real> quasi_static_pressure(const ReynoldsFilm& film, std::span<const Real> gap,
                                        std::span<const Real> gap_rate, int newton_iterations = 1);

}  // namespace rfmems

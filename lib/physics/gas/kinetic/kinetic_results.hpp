// What a steady kinetic run (rfmems-gas) writes and reports, from its scene and its solve:
//   - the macroscopic fields of every cell, gathered on the root into the result file:
//     density (kg/m^3), velocity (m/s), temperature (K), pressure (Pa), heat_flux (W/m^2),
//     stress (viscous, Pa, Voigt xx yy zz yz xz xy), and /solver/residual, the ratio
//     ||r|| / ||r_0|| after each iteration;
//   - the summary: collision model, mesh and partition, velocity grid, initial state, the
//     reference state (p0, T0, rho0, mu0, v0, H, delta, Kn, U, dT; kinetic_reference.hpp),
//     solver (type requested, method that ran and what its iterations are, the hand-over when
//     COMET gave the solve to the sequential solver, converged, iterations, residuals,
//     seconds), per force patch the force (N, or N/m in 2D) and heat flow (W, W/m) of the gas
//     on it, its area, heat flux and shear stress and their normalised values P and q*
//     (kinetic_reference.hpp), per patch the net mass outflow (a steady state passes as much
//     in as out) and the total mass.
// Every rank calls both (the gathers and reductions are collective); only the root writes.
#pragma once
#include <span>

#include "io/json_summary.hpp"
#include "io/result_writer.hpp"
#include "physics/gas/kinetic/kinetic_case.hpp"
#include "physics/gas/kinetic/kinetic_solve_result.hpp"

namespace rfmems {

// writer: the root's (null on the other ranks). The macros are those of the final state
// (KineticOperator::update_collision(f) after the solve).
void write_kinetic_results(ResultWriter* writer, const KineticScene& scene,
                           const KineticSolveResult& result);

// The summary above for the state f at the end of the solve.
Json kinetic_summary(const KineticScene& scene, const KineticSolveResult& result,
                     std::span<const Real> f);

}  // namespace rfmems

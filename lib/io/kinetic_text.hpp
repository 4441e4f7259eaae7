// The text rfmems-gas prints after a run, from its JSON summary
// (physics/gas/kinetic/kinetic_results.hpp):
//
//   <name> (esbgk, Kn = 0.1, 1600 cells x 1000 velocities): sequential solver converged in
//   130 sweeps (residual ratio 9.87e-07, 12.3 s)
//     reference: p0 = ... Pa, T0, rho0, mu0, v0 = sqrt(2 R T0), H; delta = p0 H / (mu0 v0),
//     Kn = sqrt(pi) / (2 delta) (physics/gas/kinetic/kinetic_reference.hpp)
//     wall top: force [f_x, f_y, f_z] N/m, heat flow q W/m
//       shear stress tau Pa, P = -p_xy v0 / (p0 U)      (where a wall velocity defines it)
//       heat flux q W/m^2, q* = q / (p0 v0 dT / T0)      (where a temperature difference does)
// A COMET run that handed the solve to the sequential solver says so before "sequential
// solver converged in N sweeps".
#pragma once
#include <string>

#include "io/json_summary.hpp"

namespace rfmems {

std::string kinetic_text(const Json& summary);

}  // namespace rfmems

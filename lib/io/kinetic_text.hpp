// The text rfmems-gas prints after a run, from its JSON summary
// (physics/gas/kinetic/kinetic_results.hpp):
//
//   <name> (esbgk, Kn = 0.1, 1600 cells x 1000 velocities): sequential solver converged in
//   130 iterations (residual ratio 9.87e-07, 12.3 s)
//     wall top: force [f_x, f_y, f_z] N/m, heat flow q W/m
#pragma once
#include <string>

#include "io/json_summary.hpp"

namespace rfmems {

std::string kinetic_text(const Json& summary);

}  // namespace rfmems

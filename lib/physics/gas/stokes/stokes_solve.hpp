// The Stokes saddle-point system (stokes_operator.hpp) solved by sparse LU (KLU through
// lib/solvers), after scaling rows and columns to O(1) entries: momentum rows / mu, pressure
// columns * mu / h, continuity rows / h (KLU's threshold pivoting otherwise compares entries of
// sizes mu, h and 1). Nested-dissection ordering: 4.5x less CPU than AMD on the damping
// case's 240k unknowns (klu_factorization.hpp).
#pragma once
#include <vector>

#include "physics/gas/stokes/stokes_operator.hpp"

namespace rfmems {

// The unknowns x (SI: face velocities, cell pressures) of A x = b.
std::vector<Real> solve_stokes(const StokesOperator& op);

}  // namespace rfmems

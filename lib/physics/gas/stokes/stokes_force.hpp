// Forces on the walls of a Stokes solution (stokes_operator.hpp), per unit depth, from the
// same edge forces the momentum equations are made of. Each control volume's gas feels the
// forces on its edges; the force on a block or side is minus the sum over the edges across
// it, and on the wall edge of a face of known normal velocity (where the traction is not a
// cell-centre stress) it is the reaction that closes that half volume's balance. The pressure
// at the wall is thereby extrapolated from the cell centre with the momentum balance itself,
// and the forces on all walls and sides sum to the body force to round-off (interior edges
// cancel pairwise).
#pragma once
#include <span>

#include "physics/gas/stokes/stokes_operator.hpp"

namespace rfmems {

// The force of the gas on a block or a side [N/m].
Point2 boundary_force(const StokesOperator& op, std::span<const Real> x, const Across& on);

// The volume flow out of the domain through a side [m^2/s].
Real side_outflow(const StokesOperator& op, std::span<const Real> x, Side side);

}  // namespace rfmems

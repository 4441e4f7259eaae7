// Grid transfers of COMET's full-approximation-scheme multigrid between a FaceGraph level and
// its agglomerated coarse level (fv/agglomeration.hpp), for cell-major blocks of `block`
// values per cell (the N distribution values of a cell).
//
//   restrict_solution:  f_C = sum_{c in C} V_c f_c / V_C   (volume-weighted mean: a
//                       cell-centred FV unknown is a cell average, so the coarse average of a
//                       field is conserved: sum_C V_C f_C = sum_c V_c f_c)
//   restrict_residual:  r_C = sum_{c in C} r_c            (an FV residual is a cell integral:
//                       the coarse cell's balance is the sum of its fine cells' balances)
//   prolong_correction: f_c += e_C(c)                     (injection, piecewise constant: the
//                       thesis's choice; first-order upwind has no smoother interpolant to
//                       honour, and injection keeps R_sol P = identity)
// Distributed levels (fv/agglomeration.hpp): all three act on owned cells only (a fine cell is
// owned exactly when its coarse cell is); the caller refreshes the ghosts afterwards with the
// level's exchange (coarse ghosts after a restriction, fine ghosts after a correction).
#pragma once
#include <span>

#include "fv/agglomeration.hpp"

namespace rfmems {

void restrict_solution(const FaceGraph& fine, const Agglomeration& a, Index block,
                       std::span<const Real> fine_values, std::span<Real> coarse_values);
void restrict_residual(const Agglomeration& a, Index block, std::span<const Real> fine_values,
                       std::span<Real> coarse_values);
// fine_values[c] += coarse_correction[coarse_of_fine[c]], per block entry.
void prolong_correction(const Agglomeration& a, Index block,
                        std::span<const Real> coarse_correction, std::span<Real> fine_values);

}  // namespace rfmems

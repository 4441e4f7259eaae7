// The sequential (source-iteration) solver of the steady discrete-velocity BGK / ESBGK
// equation: the baseline of the literature (thesis Fig. 5.2) that COMET beats.
//
// One iteration:
//   1. with the collision term lagged (f_eq and nu of the previous iterate) and the boundary
//      face values lagged (they depend on the owner's other ordinates), each ordinate's
//      spatial system  sum_f (c_k.S_f)^+ f_ck + (c_k.S_f)^- f_k,up + V_c nu_c f_ck
//                      = V_c nu_c f_eq,ck
//      is lower triangular in a downwind order of the cells (downwind_ordering.hpp), so one
//      sweep in that order solves it exactly (Gauss-Seidel on the closing edge of a cycle);
//   2. the moments, equilibria (warm-started Newton) and nu are updated from the new f, and
//      the full steady residual r(f) of kinetic_operator.hpp is evaluated.
// In a closed domain (op.is_closed()) the sweeps do not conserve mass (collision and boundary
// values are lagged) and the steady state is defined only up to its mass, so after each sweep
// f is scaled to the initial total mass (KineticOperator::restore_mass): every solver pins
// the mass this way, so they agree on the steady state.
// Stops when ||r||_2 / ||r_0||_2 <= tolerance. Source iteration converges in O(1) iterations
// in the free-molecular regime and slowly in the near-continuum (the spectral radius tends to
// 1 as Kn -> 0): the motivation for COMET.
#pragma once
#include <functional>
#include <span>

#include "core/types.hpp"
#include "physics/gas/kinetic/downwind_ordering.hpp"
#include "physics/gas/kinetic/kinetic_operator.hpp"
#include "physics/gas/kinetic/kinetic_solve_result.hpp"

namespace rfmems {

struct SequentialOptions {
  Real tolerance = 1e-6;  // on ||r|| / ||r_0||
  int max_iterations = 200000;
  // Stop as soon as the contraction rate forecasts that max_iterations will not reach the
  // tolerance (solvers/convergence_forecast.hpp); false runs to the cap.
  bool stop_when_hopeless = true;
  // Called after every iteration with (iteration, ratio); return false to stop.
  std::function<bool(int, Real)> monitor;
};

// One sweep over every group, with the collision term lagged (the sequential iteration), and
// optionally the implicit time term b V (f - h) of a backward-difference step (b = alpha / dt,
// h the history part; b = 0: the steady equation):
//   f_ck = (b V h_ck + V nu f_eq,ck + V s_ck - sum (c.S)^- f_up - D_ck)
//          / (b V + sum (c.S)^+ + V nu),
// D_ck the operator's lagged second-order correction (0 with first-order transport), s_ck
// its body-force source (0 without one; lagged with f_eq); f_up of a periodic face whose
// partner is the cell's own is f_ck itself, implicitly,
// cells in downwind order so upwind neighbours already hold this sweep's values; ghost cells
// are skipped (they come from their owners).
void downwind_sweep(const KineticOperator& op, const std::vector<DownwindGroup>& groups,
                    std::span<Real> f, Real b = 0, std::span<const Real> h = {});

// Iterates f (length op.size(), the initial state on entry) to the steady state.
KineticSolveResult solve_sequential(KineticOperator& op, std::span<Real> f,
                                    const SequentialOptions& options = {});

}  // namespace rfmems

// Pseudo-transient continuation (Kelley & Keyes, SIAM J. Numer. Anal. 35, 1998; Coffey, Kelley
// & Keyes, SIAM J. Sci. Comput. 25, 2003) of a static system F(y) = 0: backward-Euler steps of
// the damped pseudo-flow D y' = -F(y),
//
//   F(y_k) + D (y_k - y_{k-1}) / dtau_k = 0,
//
// each solved by Newton (KINSOL, line search), with D the structure's stiffness diagonal at
// rest (so dtau is dimensionless: dtau = 1 damps each unknown by its own spring) and dtau grown
// by switched evolution relaxation, dtau_{k+1} = dtau_k ||F(y_{k-1})|| / ||F(y_k)|| (at least
// x1.5 and at most x10 a step; halved when the residual more than doubles), until ||F(y)||_inf
// reaches the tolerance; a pseudo-step Newton cannot solve is retried with dtau / 4.
//
// Why: the contact branch of a plate pulled onto a dielectric is fold-rich. On a mesh whose
// cells are not much smaller than the electrostatic boundary layer at the contact edge
// ((D_plate / (V^2 eps0 / g_ec^3))^(1/4), ~7 um at 180 V on the default switch), each cell
// that lifts off or touches down is a small fold of the voltage-controlled equilibrium, so
// Newton from the last equilibrium at the next voltage finds no solution near it (or a saddle).
// The pseudo-flow follows the structure's own (overdamped) motion from the last state and
// settles on the nearest stable equilibrium, through those local snaps, as a very slow
// voltage sweep would; a released structure flows off the dielectric.
#pragma once
#include <span>
#include <vector>

#include "core/system_operator.hpp"

namespace rfmems {

struct PseudoTransientOptions {
  Real tolerance = 0;     // on ||F||_inf (absolute, F's units)
  Real initial_step = 1;  // dtau_0
  Real max_step = 1e12;   // dtau cap (beyond it the step is a Newton solve of F = 0)
  int max_steps = 2000;   // pseudo-steps
  int max_newton_iterations = 30;
};

struct PseudoTransientStats {
  bool converged = false;
  int steps = 0, rejected = 0;
  long newton_iterations = 0;
  Real residual = 0;  // ||F(y)||_inf at the end
};

// Relaxes y (in place) to F(y) = 0 (system: a static SystemOperator, evaluated at t = 0 with
// y' = 0). pseudo_mass: D, one positive entry per unknown.
PseudoTransientStats relax_pseudo_transient(SystemOperator& system, std::span<Real> y,
                                            std::span<const Real> pseudo_mass,
                                            const PseudoTransientOptions& options);

}  // namespace rfmems

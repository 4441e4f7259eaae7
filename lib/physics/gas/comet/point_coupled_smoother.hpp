// COMET's point-coupled Gauss-Seidel sweep (thesis ch. 5) on one level: cell by cell,
// one Newton step on all N ordinates of the cell together with its macroscopic unknowns,
// with the neighbours' latest values frozen (Gauss-Seidel), for the steady equation
//     r_c(f) = s_c,   r_ck = a_k f_ck + in_k - V nu (f_eq,ck - f_ck)        (kinetic_operator.hpp)
// (s = 0 on the finest level, the FAS source on coarse levels). a_k = sum_f (c_k.S_f)^+ is the
// outgoing upwind coefficient, in_k = sum_f (c_k.S_f)^- f_upwind the incoming flux.
//
// The cell's Newton matrix is the arrowhead of eq. 5.38 (arrowhead_system.hpp):
//   D_k = a_k + V nu,   B_k = -V nu d f_eq,k / dX,   [C E] = the moment rows of X,
// with X, the macroscopic unknowns coupled to the ordinates, chosen by CometCoupling:
//   Velocity  (thesis): X = u; rows rho u - sum_k w_k c_k f_k = 0, rho and temperature
//             (covariance) held fixed in df_eq/du (equilibrium_velocity_derivative).
//   Conserved (default): X = U = sum_k w_k psi_k f_k, psi = (1, xi, |xi|^2) (mass, momentum,
//             energy); rows U - sum_k w_k psi_k f_k = 0; df_eq/dU exact for BGK, with the
//             ESBGK anisotropy lagged (equilibrium_moment_derivative.hpp). The collision term
//             then drops out of the cell's five conservation laws exactly, so a cell's mass,
//             momentum and energy follow the transport balance in one step however large
//             V nu is: the lagged density and temperature of the thesis variant make the
//             point solve a relaxation whose rate falls like the cell Knudsen number.
// After each cell's step its macroscopic state, equilibrium (warm-started Newton) and nu are
// refreshed at once (KineticOperator::update_collision(cell)), instead of once per sweep as in
// the thesis: the next cells see the latest collision terms, at the same cost.
//
// Boundary cells (thesis): the incoming ordinates on a boundary face are not coupled to the
// cell's outgoing ordinates in the matrix (that would destroy the arrowhead); their face values
// are refreshed from the cell's current f before its solve (lagged by one visit), so they are
// coupled to u, v, w (or U) only through the equilibrium. `cell_newton_iterations` > 1 repeats
// the step (and the refresh) per visit.
//
// On a tensor-product velocity grid (equilibrium_tensor_kernel.hpp) the conserved coupling's
// arrowhead is solved without forming B: with d f_eq,k / dU = f_eq,k phi_k^T Y (Y = J^-1 dm/dU,
// P x 5, from the Gram matrix the equilibrium's Newton stored), C = -w psi^T and E = I,
//     S = I - V nu H Y,  H = sum_k w (f_eq,k / d_k) psi_k phi_k^T,  g = sum_k w psi_k y_k,
//     dU = S^-1 g,       df_k = y_k + (f_eq,k / d_k) phi_k . (V nu Y dU),   y = D^-1 (-r),
// H and g by nested moment sums: ~15 operations per ordinate instead of ~120 for forming
// d f_eq / dU and the generic O(M^2 N) Schur complement; the same algebra, so the cell's five
// conservation laws still hold to round-off after the step.
//
// A step that would make an ordinate non-positive is damped (f_k + theta df_k >= 0.1 f_k):
// counted in damped_steps(); none occur in the verification cases.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "physics/gas/comet/arrowhead_system.hpp"
#include "physics/gas/comet/equilibrium_moment_derivative.hpp"
#include "physics/gas/kinetic/kinetic_operator.hpp"

namespace rfmems {

enum class CometCoupling { Velocity, Conserved };

// "velocity" / "conserved"; InputError otherwise.
CometCoupling comet_coupling_from_name(const std::string& name);
const char* comet_coupling_name(CometCoupling coupling);

class PointCoupledSmoother {
 public:
  // The operator must outlive the smoother.
  PointCoupledSmoother(KineticOperator& op, CometCoupling coupling, int cell_newton_iterations = 1);

  // One Gauss-Seidel pass over the owned cells, in index order (forward) or reverse, solving
  // r(f) = source (empty source: 0). The operator's collision cache must be current for f on
  // entry (update_collision(f) or residual(f)); it is current again on exit.
  void sweep(std::span<Real> f, std::span<const Real> source, bool forward);

  // The point solve of one owned cell (what sweep does per cell).
  void solve_cell(Index c, std::span<Real> f, std::span<const Real> source);

  // An implicit time step's term b V_c f_c on every cell (b = alpha / dt of backward Euler or
  // BDF2; the history b V h goes in the source): D_k = a_k + V nu + b V, r_ck += b V f_ck.
  // Default 0 (the steady equation). The arrowhead algebra is unchanged, so the cell's
  // conservation laws still hold after its step (lib/ibm/immersed_kinetic_gas.hpp).
  void set_time_coefficient(Real b) { time_coefficient_ = b; }

  long cell_updates() const { return cell_updates_; }
  long damped_steps() const { return damped_steps_; }

 private:
  template <int M>
  void newton_step(Index c, std::span<Real> f, std::span<const Real> source, ArrowheadSystem<M>& a);
  // The conserved coupling's step on a tensor-product grid: the same arrowhead solve with its
  // blocks never formed (see the .cpp), P = 5 (BGK) or 10 (ESBGK) equilibrium coefficients.
  template <int P>
  void conserved_tensor_step(Index c, std::span<Real> f, std::span<const Real> source);
  // Cell c's terms of r_c: its distribution, its equilibrium, the outgoing coefficients a_k,
  // V nu and the time term's b V; the incoming flux in_k is left in in_.
  struct CellTerms {
    std::span<Real> fc;
    std::span<const Real> feq;
    const Real* out;
    Real vnu, bv;
  };
  CellTerms cell_terms(Index c, std::span<Real> f);
  // Applies step_ to cell c's f, damped to keep every ordinate positive.
  void apply_step(std::span<Real> fc);

  KineticOperator& op_;
  CometCoupling coupling_;
  int newton_iterations_;
  std::vector<Real> outgoing_;  // a_k per owned cell, cell-major
  std::vector<Real> in_, step_, dfeq_;
  EquilibriumMomentDerivative conserved_derivative_;
  ArrowheadSystem<3> velocity_system_;
  ArrowheadSystem<5> conserved_system_;
  Real time_coefficient_ = 0;
  long cell_updates_ = 0;
  long damped_steps_ = 0;
};

}  // namespace rfmems

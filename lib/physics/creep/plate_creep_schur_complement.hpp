// The exact solve of the plate creep Jacobian J z = r by the Schur complement on the plate
// unknowns (the linear solve of every IDA Newton iteration; PlateCreepSystem's preconditioner).
//
// With the state [y | q] (plate | creep points) the Jacobian J = dF/dy + c_j dF/dy' is
//
//   J = [ K  P ]     K = dF_y/dy  (plate stiffness + hold-voltage tangent; 3 unknowns/cell)
//       [ G  D ]     P = dF_y/dq  (plastic moment sources: beta rows <- eps_p of the M_p
//                                  reconstruction stencils)
//                    G = dF_q/dy  (each point's rate <- the rotations of its cell's curvature
//                                  stencil)
//                    D = dF_q/dq  (block diagonal, 4 x 4 per point: c_j I - dg/dq)
//
// A direct LU of J fills in (each moment row reaches ~20 cells x 21 points of q) and cost 92 %
// of an implicit creep run in klu_refactor. Eliminating the local blocks first leaves the
// plate-sized Schur complement
//
//   S = K - P D^-1 G,   z_q' = D^-1 r_q,  z_y = S^-1 (r_y - P z_q'),  z_q = z_q' - D^-1 G z_y,
//
// exact (no approximation). Its blocks factor through the per-cell plastic moment: P acts as
// B_rk M_p(k) with M_p(k) = C sum_i w_i z_i eps_p(k, i), and G of point (k, i) as
// -(dg/dkappa)_i L_k with kappa_k = L_k beta (the curvature stencil), so
//
//   P D^-1 G = sum_{r,k} B_rk H_k L_k,    H_k = -C sum_i w_i z_i [D_ki^-1 (dg/dkappa)_i]_{eps_p}
//
// (3 x 3 per cell) and S has the stencil of the sources composed with the curvature stencils
// (~50 cells per beta row). S's pattern is built once: KLU (COLAMD ordering) analyses it once
// and refactors the numbers at a setup.
//
// Relaxation of a residual stress (PlateCreepSystem, "Relaxation of the residual stress"):
// K becomes the y-y block of J (the plate's stiffness and the relaxed membrane force's w-w
// part, which depends on q), and P gains P_m = dF_w/dq of the relaxed membrane force: the w
// row of each face cell of face f gets +-a_c w_i (C^T b_f)^T on eps_p(c, i), b_f from the
// slope at the state. Like H_k, P_m D^-1 G factors through the cell:
//   P_m D^-1 G = -sum_f +-a_c (C^T b_f)^T Z_c L_c,   Z_c = sum_i w_i [D_ci^-1 (dg/dkappa)_i]_eps_p
// (the zeroth moment where H_k takes the first), so S's w rows gain the rotations of the face
// cells' curvature stencils, and the solve subtracts P_m z_q' (the relaxation term applied to
// z_q' at the setup's slopes).
//
// Lagged factors (refactor_tolerance > 0): the per-point blocks D^-1, E and H are cheap and
// always rebuilt exactly; only the refactorisation of S (~0.5 s on 81 x 21 cells, the bulk of
// a run) is skipped while ||S_old^-1 (S - S_old)|| (four power iterations with the old
// factors, ~1/20 of a refactorisation) is below the tolerance. The solve is then exact but for
// S_old^-1 in place of S^-1: a preconditioner for GMRES, which absorbs the difference in a
// few more iterations.
#pragma once
#include <Eigen/Dense>
#include <memory>
#include <span>
#include <vector>

#include "core/system_operator.hpp"
#include "physics/creep/plate_creep_system.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

class PlateCreepSchurComplement {
 public:
  explicit PlateCreepSchurComplement(const PlateCreepSystem& system);
  // Builds S at the state for J = dF/dy + c_j dF/dy' (c_j > 0) and factorises it unless the
  // lagged factors are still within the refactor tolerance.
  void setup(Real t, Real c_j, std::span<const Real> state);
  // 0 (default): refactorise at every setup (the exact inverse of J).
  void set_refactor_tolerance(Real tolerance) { refactor_tolerance_ = tolerance; }
  long factorizations() const { return factorizations_; }
  // The last estimate of ||S_old^-1 (S - S_old)|| (0 before any).
  Real last_lag_estimate() const { return last_lag_estimate_; }
  // z = J^-1 r (z may not alias r).
  void solve(std::span<const Real> r, std::span<Real> z);
  // The Schur complement's pattern (3 unknowns per cell).
  const CsrPattern& pattern() const { return pattern_; }

 private:
  bool lagged_factors_suffice();
  using Mat4 = Eigen::Matrix4d;
  using Mat43 = Eigen::Matrix<Real, 4, 3>;

  const PlateCreepSystem& system_;
  CsrPattern pattern_;
  std::vector<Index> plate_position_;  // structural tangent entry -> S value index
  // Per source block (r, k), per curvature stencil cell s of k, the 2 x 2 positions of
  // (beta rows of r, beta columns of s) in S's values, row-major.
  std::vector<Index> coupling_position_;
  std::vector<Index> coupling_offset_;  // per source block: start in coupling_position_
  std::vector<Real> values_, factored_values_;
  std::unique_ptr<KluFactorization> lu_;
  Real refactor_tolerance_ = 0;
  long factorizations_ = 0;
  Real last_lag_estimate_ = 0;
  // Per point: D^-1 and E = D^-1 dg/dkappa; per cell: H_k.
  std::vector<Mat4> d_inverse_;
  std::vector<Mat43> e_;
  std::vector<Eigen::Matrix3d> h_;
  std::vector<Real> tangent_, rhs_, moment_;
  // The relaxation of a residual stress (PlateCreepSystem::relaxes_membrane()): the y-y block
  // of J (pattern_ position in J -> in S), per membrane face and face cell the S positions of
  // its w rows' rotation columns (owner, neighbour or -1), per cell Z_k = sum_i w_i [E_ki]_eps_p,
  // and the state of the setup (P_m depends on its slopes).
  std::vector<std::pair<Index, Index>> tangent_position_;
  std::vector<Index> membrane_position_;
  std::vector<Eigen::Matrix3d> membrane_z_;
  std::vector<Real> state_, relaxation_;
  Real t_ = 0;
};

}  // namespace rfmems

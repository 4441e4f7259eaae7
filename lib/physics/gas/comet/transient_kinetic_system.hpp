// The semi-discrete (transient) discrete-velocity BGK / ESBGK equation as a SystemOperator for
// IDA (thesis eq. 5.7 with the time derivative kept):
//
//   F_ck(t, f, f') = V_c f'_ck + r_ck(f) = 0,     r: KineticOperator's steady residual
//
// (upwind transport + collision with the equilibrium and nu of the current f). Every unknown
// is differential. The system is solved matrix-free: IDA's Krylov solver (SPGMR) forms
// Jacobian-vector products by differences of F, and this class supplies the preconditioner,
// COMET's point block per cell (point_coupled_smoother.hpp, thesis eq. 5.38) with the
// neighbours frozen:
//
//   P_c = diag(c_j V + sum_f (c_k . S_f)^+ + V nu) - V nu (d f_eq / dU) (dU / df),
//
// U the five conserved moments (equilibrium_moment_derivative.hpp), dU/df_k = w_k psi_k. It is
// a diagonal plus a rank-5 term, inverted in O(5 N) per cell by the Sherman-Morrison-Woodbury
// form of the arrowhead solve:  z = y - Z (I + C Z)^-1 C y,  y = D^-1 r,  Z = D^-1 B.
// Exact for a cell's own block of the BGK Jacobian at equilibrium (nu frozen, boundary
// couplings lagged); ESBGK's anisotropic target is lagged as in COMET.
//
// Storage: per owned cell D^-1 (N), Z (5 N) and the 5 x 5 LU of I + C Z, refreshed at every
// preconditioner setup (IDA calls it rarely: once per several steps).
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "core/system_operator.hpp"
#include "physics/gas/comet/equilibrium_moment_derivative.hpp"
#include "physics/gas/kinetic/kinetic_operator.hpp"

namespace rfmems {

class TransientKineticSystem : public SystemOperator {
 public:
  explicit TransientKineticSystem(KineticOperator& op);

  Index size() const override { return op_.size(); }
  std::vector<Real> differential_components() const override;
  void residual(Real t, std::span<const Real> f, std::span<const Real> fp,
                std::span<Real> r) override;
  // Matrix-free: no assembled Jacobian (use IdaOptions::LinearSolver::Spgmr).
  const CsrPattern& jacobian_pattern() const override;
  void jacobian(Real t, Real c_j, std::span<const Real> f, std::span<const Real> fp,
                std::span<Real> values) override;

  bool has_preconditioner() const override { return true; }
  void preconditioner_setup(Real t, Real c_j, std::span<const Real> f,
                            std::span<const Real> fp) override;
  void preconditioner_solve(std::span<const Real> r, std::span<Real> z) override;

  KineticOperator& kinetic() { return op_; }
  long preconditioner_setups() const { return setups_; }

 private:
  using Mat5 = Eigen::Matrix<Real, 5, 5>;
  KineticOperator& op_;
  EquilibriumMomentDerivative derivative_;
  std::vector<Real> scratch_;                           // N, per-cell residual pieces
  std::vector<Real> inverse_diagonal_;                  // n_owned x N
  std::vector<Real> z_;                                 // n_owned x 5N: Z = D^-1 B
  std::vector<Eigen::PartialPivLU<Mat5>> capacitance_;  // I + C Z per owned cell
  std::vector<Real> weighted_basis_;                    // 5 N: C = w_k psi_k (same for every cell)
  long setups_ = 0;
};

}  // namespace rfmems

// The exact solve of a creep Jacobian J z = r by the Schur complement on the structural
// unknowns, formed numerically from J's own entries: the preconditioner of the plate creep
// system over the von Karman plate, whose structure (w, beta, u, v) the hand-factored
// PlateCreepSchurComplement does not cover.
//
// With the state [y | q] (structural | creep points) the Jacobian is
//
//   J = [ K  P ]     K = dF_y/dy,  P = dF_y/dq,  G = dF_q/dy,
//       [ G  D ]     D = dF_q/dq   block diagonal: one block x block matrix per point
//
// and the solve eliminates the points first:
//
//   S = K - P D^-1 G,   z_q' = D^-1 r_q,   z_y = S^-1 (r_y - P z_q'),   z_q = z_q' - D^-1 G z_y.
//
// The points come in groups (a cell's points through the thickness) whose columns of P reach
// the same structural rows R_g and whose rows of G reach the same structural columns C_g, so
// P D^-1 G = sum_g P_g (D_g^-1 G_g) with dense P_g (R_g x m) and G_g (m x C_g), m the group's
// states; S has K's pattern widened by every R_g x C_g. A direct LU of J fills in (each q row
// of the von Karman plate reaches ~100 structural columns, and the moment and membrane rows
// the states of ~25 cells); S is the size of the structure. Its pattern is built once and
// refactorised by KLU (COLAMD) at each setup: the inverse of J, exact but for round-off.
#pragma once
#include <Eigen/Dense>
#include <memory>
#include <span>
#include <vector>

#include "core/system_operator.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

class PointBlockSchurComplement {
 public:
  // J's pattern: the first n_structural unknowns are structural, the rest groups of
  // group_size states, each group a sequence of blocks of `block` states (a point's) whose q
  // rows have no q columns outside their own block. Throws std::logic_error otherwise.
  PointBlockSchurComplement(const CsrPattern& pattern, Index n_structural, Index group_size,
                            int block);
  ~PointBlockSchurComplement();
  // Forms and factorises S from J's values (in the pattern above).
  void setup(std::span<const Real> values);
  // z = J^-1 r (z may not alias r).
  void solve(std::span<const Real> r, std::span<Real> z);
  const CsrPattern& pattern() const { return pattern_; }
  long factorizations() const { return factorizations_; }

 private:
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  Index ns_, m_, n_groups_;
  int block_;
  // Per group: the structural rows of P_g and columns of G_g (sorted), J's positions of P_g
  // (R x m, -1: structural zero), of G_g (m x C) and of the point blocks, and S's positions of
  // R x C.
  std::vector<std::vector<Index>> rows_, cols_;
  std::vector<std::vector<Index>> p_position_, g_position_, d_position_, s_position_;
  std::vector<std::pair<Index, Index>> k_position_;  // J's y-y entries: (J, S) positions
  CsrPattern pattern_;
  std::vector<Real> values_;
  std::unique_ptr<KluFactorization> lu_;
  long factorizations_ = 0;
  // The setup's factors: per group P_g and X_g = D_g^-1 G_g, per point D^-1.
  std::vector<Matrix> p_, x_;
  std::vector<Matrix> d_inverse_;
  std::vector<Real> rhs_;
};

}  // namespace rfmems

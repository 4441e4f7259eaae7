// The per-cell Newton matrix of COMET (thesis eq. 5.38), stored compactly and solved in O(N).
//
// Unknowns of one cell: the N distribution values f_1..f_N and M macroscopic unknowns X
// (thesis: M = 3, the velocity u, v, w; COMET here also offers M = 5, the conserved moments,
// see comet_smoother.hpp). The matrix is an "arrowhead":
//
//     A = [ D  B ]     D  N x N diagonal  dR_k/df_k (outgoing upwind coefficient + V nu)
//         [ C  E ]     B  N x M           dR_k/dX    (-V nu df_eq,k/dX)
//                      C  M x N           d(moment rows)/df_k
//                      E  M x M           d(moment rows)/dX
//
// and A x = b is solved by eliminating the f block: with Z = D^-1 B and y = D^-1 b_f,
//     (E - C Z) x_X = b_X - C y,     x_f = y - Z x_X,
// i.e. one M x M Schur complement: ~(M^2 + 2M) N multiply-adds and N divisions, no N x N
// storage. D must have no zero entry and the Schur complement must be non-singular
// (SolverError otherwise).
//
// Storage: per ordinate k the entries B(k, 0..M-1) at b[Mk..] and C(0..M-1, k) at c[Mk..], so
// one pass over k touches contiguous memory.
#pragma once
#include <span>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

template <int M>
class ArrowheadSystem {
 public:
  using VecM = Eigen::Matrix<Real, M, 1>;
  using MatM = Eigen::Matrix<Real, M, M>;

  ArrowheadSystem() = default;
  explicit ArrowheadSystem(Index n) { resize(n); }
  void resize(Index n);
  Index n_ordinates() const { return static_cast<Index>(d_.size()); }

  Real& d(Index k) { return d_[k]; }
  Real& b(Index k, int j) { return b_[M * k + j]; }
  Real& c(int i, Index k) { return c_[M * k + i]; }
  MatM& e() { return e_; }
  Real d(Index k) const { return d_[k]; }
  Real b(Index k, int j) const { return b_[M * k + j]; }
  Real c(int i, Index k) const { return c_[M * k + i]; }
  const MatM& e() const { return e_; }
  // Raw rows for assembly loops: B(k, .) and C(., k); all of B (row-major N x M).
  Real* b_row(Index k) { return &b_[M * k]; }
  Real* c_column(Index k) { return &c_[M * k]; }
  std::span<Real> b_data() { return b_; }

  // Solves A [x_f; x_X] = [rhs_f; rhs_X]. x_f may alias rhs_f.
  void solve(std::span<const Real> rhs_f, const VecM& rhs_x, std::span<Real> x_f, VecM& x_x) const;
  // y = A x (tests, residual checks).
  void multiply(std::span<const Real> x_f, const VecM& x_x, std::span<Real> y_f, VecM& y_x) const;

 private:
  std::vector<Real> d_, b_, c_;
  MatM e_ = MatM::Zero();
};

extern template class ArrowheadSystem<3>;
extern template class ArrowheadSystem<5>;

}  // namespace rfmems

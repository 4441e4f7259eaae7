#include "physics/gas/comet/arrowhead_system.hpp"

#include <cmath>

#include "core/error.hpp"

namespace rfmems {

template <int M>
void ArrowheadSystem<M>::resize(Index n) {
  d_.assign(n, 0.0);
  b_.assign(M * n, 0.0);
  c_.assign(M * n, 0.0);
  e_.setZero();
}

template <int M>
void ArrowheadSystem<M>::solve(std::span<const Real> rhs_f, const VecM& rhs_x, std::span<Real> x_f,
                               VecM& x_x) const {
  const Index n = n_ordinates();
  // Pass 1: Schur complement S = E - C D^-1 B and g = b_X - C D^-1 b_f.
  MatM s = e_;
  VecM g = rhs_x;
  for (Index k = 0; k < n; ++k) {
    if (d_[k] == 0.0) throw SolverError("ArrowheadSystem: zero diagonal entry");
    const Real inv = 1.0 / d_[k];
    const Real y = rhs_f[k] * inv;
    const Real* bk = &b_[M * k];
    const Real* ck = &c_[M * k];
    for (int i = 0; i < M; ++i) {
      g[i] -= ck[i] * y;
      const Real ci = ck[i] * inv;
      for (int j = 0; j < M; ++j) s(i, j) -= ci * bk[j];
    }
  }
  const Eigen::FullPivLU<MatM> lu(s);
  if (!std::isfinite(s.sum()) || !lu.isInvertible())
    throw SolverError("ArrowheadSystem: singular Schur complement");
  const VecM xx = lu.solve(g);
  // Pass 2: x_f = D^-1 (b_f - B x_X).
  for (Index k = 0; k < n; ++k) {
    const Real* bk = &b_[M * k];
    Real acc = rhs_f[k];
    for (int j = 0; j < M; ++j) acc -= bk[j] * xx[j];
    x_f[k] = acc / d_[k];
  }
  x_x = xx;
}

template <int M>
void ArrowheadSystem<M>::multiply(std::span<const Real> x_f, const VecM& x_x, std::span<Real> y_f,
                                  VecM& y_x) const {
  const Index n = n_ordinates();
  VecM yx = e_ * x_x;
  for (Index k = 0; k < n; ++k) {
    const Real* bk = &b_[M * k];
    const Real* ck = &c_[M * k];
    Real acc = d_[k] * x_f[k];
    for (int i = 0; i < M; ++i) {
      yx[i] += ck[i] * x_f[k];
      acc += bk[i] * x_x[i];
    }
    y_f[k] = acc;
  }
  y_x = yx;
}

template class ArrowheadSystem<3>;
template class ArrowheadSystem<5>;

}  // namespace rfmems

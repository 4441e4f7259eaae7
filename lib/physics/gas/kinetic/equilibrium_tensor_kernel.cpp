#include "physics/gas/kinetic/equilibrium_tensor_kernel.hpp"

namespace rfmems {
namespace {

constexpr int monomial(int p, int q, int r) { return (p * 5 + q) * 5 + r; }

// The ESBGK basis as monomial exponents (p, q, r); BGK's fifth function is the sum of 4..6.
constexpr int kExponents[10][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 0},
                                   {0, 2, 0}, {0, 0, 2}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}};

// Basis function b of the M-function basis as a list of ESBGK functions (all coefficients 1).
struct Terms {
  int n;
  int index[3];
};
constexpr Terms basis_terms(int M, int b) {
  if (M == 5 && b == 4) return {3, {4, 5, 6}};
  return {1, {b, 0, 0}};
}

// a (M coefficients) in the 10-function basis.
std::array<Real, 10> to_full_basis(const Real* a, int M) {
  std::array<Real, 10> b{};
  if (M == 5) {
    for (int i = 0; i < 4; ++i) b[i] = a[i];
    b[4] = b[5] = b[6] = a[4];
  } else {
    for (int i = 0; i < 10; ++i) b[i] = a[i];
  }
  return b;
}

}  // namespace

EquilibriumTensorKernel::EquilibriumTensorKernel(const VelocityGrid& grid) {
  n_ = grid.size();
  n1_ = grid.n[0];
  n2_ = grid.n[1];
  n3_ = grid.n[2];
  if (n_ == 0 || Index(n1_) * n2_ * n3_ != n_ || static_cast<Index>(grid.w.size()) != n_) return;
  const Real inv_s = 1.0 / grid.reference_speed;
  x_.resize(n1_);
  y_.resize(n2_);
  z_.resize(n3_);
  for (int i = 0; i < n1_; ++i) x_[i] = grid.c[grid.index(i, 0, 0)][0] * inv_s;
  for (int j = 0; j < n2_; ++j) y_[j] = grid.c[grid.index(0, j, 0)][1] * inv_s;
  for (int l = 0; l < n3_; ++l) z_[l] = grid.c[grid.index(0, 0, l)][2] * inv_s;
  wx_ = grid.axis_weight[0];
  wy_ = grid.axis_weight[1];
  wz_ = grid.axis_weight[2];
  if (static_cast<int>(wx_.size()) != n1_ || static_cast<int>(wy_.size()) != n2_ ||
      static_cast<int>(wz_.size()) != n3_)
    return;
  // The ordinates must be exactly the product of the axes, and the weights of theirs.
  for (int i = 0; i < n1_; ++i)
    for (int j = 0; j < n2_; ++j)
      for (int l = 0; l < n3_; ++l) {
        const Index k = grid.index(i, j, l);
        const Vec3 xi = grid.c[k] * inv_s;
        if (xi[0] != x_[i] || xi[1] != y_[j] || xi[2] != z_[l] ||
            grid.w[k] != wx_[i] * wy_[j] * wz_[l])
          return;
      }
  // Weighted powers w_i v_i^p: the nested sums carry the weights with the powers.
  auto powers = [](const std::vector<Real>& v, const std::vector<Real>& w,
                   std::array<std::vector<Real>, 5>& p) {
    for (auto& e : p) e.resize(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Real v2 = v[i] * v[i];
      p[0][i] = w[i];
      p[1][i] = w[i] * v[i];
      p[2][i] = w[i] * v2;
      p[3][i] = w[i] * v2 * v[i];
      p[4][i] = w[i] * v2 * v2;
    }
  };
  powers(x_, wx_, xp_);
  powers(y_, wy_, yp_);
  powers(z_, wz_, zp_);
  for (int p = 0; p < 5; ++p) {
    xs_[p].resize(n1_);
    ys_[p].resize(n2_);
    zs_[p].resize(n3_);
  }
  ea_.resize(Index(n1_) * n2_);
  eb_.resize(Index(n1_) * n3_);
  ec_.resize(Index(n2_) * n3_);
  valid_ = true;
}

void EquilibriumTensorKernel::exponential(const Real* a, int n_coefficients, Real* f) const {
  const std::array<Real, 10> b = to_full_basis(a, n_coefficients);
  for (int i = 0; i < n1_; ++i) {
    const Real x = x_[i];
    const Real base = b[0] + x * (b[1] + x * b[4]);
    const Real ry = b[2] + b[7] * x;
    for (int j = 0; j < n2_; ++j) ea_[i * n2_ + j] = base + y_[j] * (ry + y_[j] * b[5]);
    const Real rz = b[3] + b[8] * x;
    for (int l = 0; l < n3_; ++l) eb_[i * n3_ + l] = z_[l] * (rz + z_[l] * b[6]);
  }
  for (int j = 0; j < n2_; ++j)
    for (int l = 0; l < n3_; ++l) ec_[j * n3_ + l] = b[9] * y_[j] * z_[l];
  for (std::vector<Real>* t : {&ea_, &eb_, &ec_}) {
    Eigen::Map<Eigen::ArrayXd> m(t->data(), static_cast<Index>(t->size()));
    m = m.exp();
  }
  for (int i = 0; i < n1_; ++i)
    for (int j = 0; j < n2_; ++j) {
      const Real A = ea_[i * n2_ + j];
      const Real* B = &eb_[i * n3_];
      const Real* C = &ec_[j * n3_];
      Real* out = f + (Index(i) * n2_ + j) * n3_;
      for (int l = 0; l < n3_; ++l) out[l] = A * B[l] * C[l];
    }
}

template <int D>
void EquilibriumTensorKernel::nested_moments(const Real* g,
                                             const std::array<std::vector<Real>, 5>& xp,
                                             const std::array<std::vector<Real>, 5>& yp,
                                             const std::array<std::vector<Real>, 5>& zp,
                                             MonomialMoments& mu) const {
  constexpr int P = D + 1;
  for (int p = 0; p < P; ++p)
    for (int q = 0; p + q < P; ++q)
      for (int r = 0; p + q + r < P; ++r) mu[monomial(p, q, r)] = 0;
  for (int i = 0; i < n1_; ++i) {
    Real s[P][P] = {};
    for (int j = 0; j < n2_; ++j) {
      const Real* gl = g + (Index(i) * n2_ + j) * n3_;
      Real t[P] = {};
      for (int l = 0; l < n3_; ++l) {
        const Real v = gl[l];
        for (int r = 0; r < P; ++r) t[r] += v * zp[r][l];
      }
      for (int q = 0; q < P; ++q) {
        const Real yq = yp[q][j];
        for (int r = 0; q + r < P; ++r) s[q][r] += yq * t[r];
      }
    }
    for (int p = 0; p < P; ++p) {
      const Real x = xp[p][i];
      for (int q = 0; p + q < P; ++q)
        for (int r = 0; p + q + r < P; ++r) mu[monomial(p, q, r)] += x * s[q][r];
    }
  }
}

Real EquilibriumTensorKernel::weighted_sum(const Real* g) const {
  Real sum = 0;
  for (int i = 0; i < n1_; ++i)
    for (int j = 0; j < n2_; ++j) {
      const Real* gl = g + (Index(i) * n2_ + j) * n3_;
      Real t = 0;
      for (int l = 0; l < n3_; ++l) t += gl[l] * wz_[l];
      sum += wx_[i] * wy_[j] * t;
    }
  return sum;
}

template <int D>
void EquilibriumTensorKernel::monomial_moments(const Real* g, MonomialMoments& mu) const {
  nested_moments<D>(g, xp_, yp_, zp_, mu);
}

void EquilibriumTensorKernel::central_moments(const Real* g, Real& rho, Vec3& u, Mat3& P,
                                              Vec3& q) const {
  MonomialMoments mu;
  nested_moments<1>(g, xp_, yp_, zp_, mu);
  rho = mu[monomial(0, 0, 0)];
  u = Vec3(mu[monomial(1, 0, 0)], mu[monomial(0, 1, 0)], mu[monomial(0, 0, 1)]) / rho;
  auto shifted = [](const std::vector<Real>& axis, const std::vector<Real>& w, Real shift,
                    std::array<std::vector<Real>, 5>& p) {
    for (std::size_t i = 0; i < axis.size(); ++i) {
      const Real v = axis[i] - shift;
      p[0][i] = w[i];
      p[1][i] = w[i] * v;
      p[2][i] = w[i] * v * v;
      p[3][i] = w[i] * v * v * v;
    }
  };
  shifted(x_, wx_, u[0], xs_);
  shifted(y_, wy_, u[1], ys_);
  shifted(z_, wz_, u[2], zs_);
  nested_moments<3>(g, xs_, ys_, zs_, mu);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      int e[3] = {0, 0, 0};
      ++e[a];
      ++e[b];
      P(a, b) = mu[monomial(e[0], e[1], e[2])];
    }
  for (int a = 0; a < 3; ++a) {
    Real sum = 0;
    for (int b = 0; b < 3; ++b) {
      int e[3] = {0, 0, 0};
      ++e[a];
      e[b] += 2;
      sum += mu[monomial(e[0], e[1], e[2])];
    }
    q[a] = 0.5 * sum;
  }
}

template <int M>
void EquilibriumTensorKernel::basis_moments(const Real* g, Eigen::Matrix<Real, M, 1>& G,
                                            Eigen::Matrix<Real, M, M>* J) const {
  MonomialMoments mu;
  if (J)
    monomial_moments<4>(g, mu);
  else
    monomial_moments<2>(g, mu);
  auto moment_of = [&](int e1, int e2) {
    const int* a = kExponents[e1];
    const int* b = kExponents[e2];
    return mu[monomial(a[0] + b[0], a[1] + b[1], a[2] + b[2])];
  };
  for (int b = 0; b < M; ++b) {
    const Terms tb = basis_terms(M, b);
    Real sum = 0;
    for (int t = 0; t < tb.n; ++t) sum += moment_of(tb.index[t], 0);
    G[b] = sum;
  }
  if (!J) return;
  for (int b = 0; b < M; ++b)
    for (int c = 0; c <= b; ++c) {
      const Terms tb = basis_terms(M, b), tc = basis_terms(M, c);
      Real sum = 0;
      for (int s = 0; s < tb.n; ++s)
        for (int t = 0; t < tc.n; ++t) sum += moment_of(tb.index[s], tc.index[t]);
      (*J)(b, c) = (*J)(c, b) = sum;
    }
}

template <int M>
void EquilibriumTensorKernel::conserved_product_moments(const Real* g,
                                                        Eigen::Matrix<Real, 5, M>& H) const {
  MonomialMoments mu;
  monomial_moments<4>(g, mu);
  for (int b = 0; b < 5; ++b)
    for (int c = 0; c < M; ++c) {
      const Terms tb = basis_terms(5, b), tc = basis_terms(M, c);
      Real sum = 0;
      for (int s = 0; s < tb.n; ++s)
        for (int t = 0; t < tc.n; ++t) {
          const int* e1 = kExponents[tb.index[s]];
          const int* e2 = kExponents[tc.index[t]];
          sum += mu[monomial(e1[0] + e2[0], e1[1] + e2[1], e1[2] + e2[2])];
        }
      H(b, c) = sum;
    }
}

template <int M, int K>
void EquilibriumTensorKernel::basis_combination(const Real* g, const Eigen::Matrix<Real, M, K>& Y,
                                                Real* out) const {
  // Y in the 10-function basis, column by column.
  Real y10[K][10];
  for (int j = 0; j < K; ++j) {
    Real col[M];
    for (int b = 0; b < M; ++b) col[b] = Y(b, j);
    const std::array<Real, 10> full = to_full_basis(col, M);
    for (int b = 0; b < 10; ++b) y10[j][b] = full[b];
  }
  for (int i = 0; i < n1_; ++i) {
    const Real x = x_[i];
    for (int j = 0; j < n2_; ++j) {
      const Real y = y_[j];
      // phi . Y(:, col) = c0 + z (c1 + z c2) at (x, y).
      Real c0[K], c1[K], c2[K];
      for (int col = 0; col < K; ++col) {
        const Real* b = y10[col];
        c0[col] = b[0] + x * (b[1] + x * b[4] + y * b[7]) + y * (b[2] + y * b[5]);
        c1[col] = b[3] + b[8] * x + b[9] * y;
        c2[col] = b[6];
      }
      const Index k0 = (Index(i) * n2_ + j) * n3_;
      for (int l = 0; l < n3_; ++l) {
        const Real z = z_[l];
        const Real gk = g[k0 + l];
        Real* o = out + K * (k0 + l);
        for (int col = 0; col < K; ++col) o[col] = gk * (c0[col] + z * (c1[col] + z * c2[col]));
      }
    }
  }
}

template void EquilibriumTensorKernel::monomial_moments<2>(const Real*, MonomialMoments&) const;
template void EquilibriumTensorKernel::monomial_moments<4>(const Real*, MonomialMoments&) const;
template void EquilibriumTensorKernel::basis_moments<5>(const Real*, Eigen::Matrix<Real, 5, 1>&,
                                                        Eigen::Matrix<Real, 5, 5>*) const;
template void EquilibriumTensorKernel::basis_moments<10>(const Real*, Eigen::Matrix<Real, 10, 1>&,
                                                         Eigen::Matrix<Real, 10, 10>*) const;
template void EquilibriumTensorKernel::conserved_product_moments<5>(
    const Real*, Eigen::Matrix<Real, 5, 5>&) const;
template void EquilibriumTensorKernel::conserved_product_moments<10>(
    const Real*, Eigen::Matrix<Real, 5, 10>&) const;
template void EquilibriumTensorKernel::basis_combination<5, 1>(const Real*,
                                                               const Eigen::Matrix<Real, 5, 1>&,
                                                               Real*) const;
template void EquilibriumTensorKernel::basis_combination<10, 1>(const Real*,
                                                                const Eigen::Matrix<Real, 10, 1>&,
                                                                Real*) const;
template void EquilibriumTensorKernel::basis_combination<5, 3>(const Real*,
                                                               const Eigen::Matrix<Real, 5, 3>&,
                                                               Real*) const;
template void EquilibriumTensorKernel::basis_combination<10, 3>(const Real*,
                                                                const Eigen::Matrix<Real, 10, 3>&,
                                                                Real*) const;
template void EquilibriumTensorKernel::basis_combination<5, 5>(const Real*,
                                                               const Eigen::Matrix<Real, 5, 5>&,
                                                               Real*) const;
template void EquilibriumTensorKernel::basis_combination<10, 5>(const Real*,
                                                                const Eigen::Matrix<Real, 10, 5>&,
                                                                Real*) const;

}  // namespace rfmems

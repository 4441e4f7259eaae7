#include "physics/gas/kinetic/velocity_quadrature.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace rfmems {
namespace {

constexpr int kMaxPoints = 200;

// The symmetric Jacobi matrix of the orthonormal recurrence
// sqrt(beta_{k+1}) q_{k+1} = (x - alpha_k) q_k - sqrt(beta_k) q_{k-1}.
Eigen::MatrixXd jacobi_matrix(const std::vector<Real>& alpha, const std::vector<Real>& beta) {
  const int n = static_cast<int>(alpha.size());
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
  for (int k = 0; k < n; ++k) J(k, k) = alpha[k];
  for (int k = 1; k < n; ++k) J(k, k - 1) = J(k - 1, k) = std::sqrt(beta[k]);
  return J;
}

// Gauss rule of a weight with moderate weights (Gauss-Legendre): nodes, and weights
// beta_0 v_0^2 from the eigenvectors.
void gauss_rule(const std::vector<Real>& alpha, const std::vector<Real>& beta, std::vector<Real>& x,
                std::vector<Real>& w) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(jacobi_matrix(alpha, beta));
  const int n = static_cast<int>(alpha.size());
  x.resize(n);
  w.resize(n);
  for (int i = 0; i < n; ++i) {
    x[i] = es.eigenvalues()[i];
    w[i] = beta[0] * es.eigenvectors()(0, i) * es.eigenvectors()(0, i);
  }
}

// Gauss rule of a weight exp(-x^2) s(x) (s = 1 on its support) with the recurrence alpha, beta
// (beta_0 = its integral): nodes, and lambda_i exp(x_i^2) by the Christoffel formula on
// q_k(x) exp(-x^2 / 2), which the recurrence carries without overflow.
void exponential_weight_rule(const std::vector<Real>& alpha, const std::vector<Real>& beta,
                             std::vector<Real>& x, std::vector<Real>& w) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(jacobi_matrix(alpha, beta),
                                                          Eigen::EigenvaluesOnly);
  const int n = static_cast<int>(alpha.size());
  x.resize(n);
  w.resize(n);
  for (int i = 0; i < n; ++i) {
    const Real xi = es.eigenvalues()[i];
    Real q_prev = 0, q = std::exp(-0.5 * xi * xi) / std::sqrt(beta[0]);
    Real sum = q * q;
    for (int k = 0; k + 1 < n; ++k) {
      const Real next = ((xi - alpha[k]) * q - (k > 0 ? std::sqrt(beta[k]) * q_prev : 0.0)) /
                        std::sqrt(beta[k + 1]);
      q_prev = q;
      q = next;
      sum += q * q;
    }
    x[i] = xi;
    w[i] = 1 / sum;
  }
}

// Mirror-symmetric to the last bit: x_{n-1-i} = -x_i, equal weights.
void symmetrise(VelocityAxis& a) {
  const int n = static_cast<int>(a.x.size());
  for (int i = 0; i < n / 2; ++i) {
    const int j = n - 1 - i;
    const Real x = 0.5 * (a.x[j] - a.x[i]), w = 0.5 * (a.w[i] + a.w[j]);
    a.x[i] = -x;
    a.x[j] = x;
    a.w[i] = a.w[j] = w;
  }
  if (n % 2 == 1) a.x[n / 2] = 0;
}

void check_points(int n, const char* rule) {
  if (n < 2 || n > kMaxPoints)
    throw InputError(std::string("velocity grid: ") + rule + " needs 2 to " +
                     std::to_string(kMaxPoints) + " points per direction, got " +
                     std::to_string(n));
}

}  // namespace

const std::vector<std::string>& velocity_rule_names() {
  static const std::vector<std::string> names = {"uniform", "gauss_hermite", "half_range_hermite",
                                                 "sinh_stretched"};
  return names;
}

VelocityRule velocity_rule_from_name(const std::string& name) {
  const auto& names = velocity_rule_names();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) throw InputError("velocity grid: unknown type '" + name + "'");
  return static_cast<VelocityRule>(it - names.begin());
}

const char* velocity_rule_name(VelocityRule rule) {
  return velocity_rule_names()[static_cast<std::size_t>(rule)].c_str();
}

bool velocity_rule_is_truncated(VelocityRule rule) {
  return rule == VelocityRule::Uniform || rule == VelocityRule::SinhStretched;
}

VelocityAxis uniform_axis(int n, Real extent) {
  check_points(n, "uniform");
  if (!(extent > 0)) throw InputError("velocity grid: the extent must be > 0");
  VelocityAxis a;
  const Real dc = 2 * extent / n;
  for (int i = 0; i < n; ++i) {
    a.x.push_back(-extent + (i + 0.5) * dc);
    a.w.push_back(dc);
  }
  symmetrise(a);
  return a;
}

VelocityAxis gauss_hermite_axis(int n) {
  check_points(n, "gauss_hermite");
  std::vector<Real> alpha(n, 0.0), beta(n);
  beta[0] = std::sqrt(M_PI);
  for (int k = 1; k < n; ++k) beta[k] = 0.5 * k;
  VelocityAxis a;
  exponential_weight_rule(alpha, beta, a.x, a.w);
  symmetrise(a);
  return a;
}

VelocityAxis half_range_hermite_axis(int n) {
  check_points(n, "half_range_hermite");
  if (n % 2 != 0)
    throw InputError("velocity grid: half_range_hermite needs an even number of points, got " +
                     std::to_string(n));
  const int m = n / 2;
  // exp(-x^2) on [0, L] by 40 panels of 20-point Gauss-Legendre.
  std::vector<Real> gl_alpha(20, 0.0), gl_beta(20), gl_x, gl_w;
  gl_beta[0] = 2;
  for (int k = 1; k < 20; ++k) gl_beta[k] = Real(k) * k / (4.0 * k * k - 1);
  gauss_rule(gl_alpha, gl_beta, gl_x, gl_w);
  const Real L = 10 + 2 * std::sqrt(Real(m));
  constexpr int kPanels = 40;
  const Real h = L / kPanels;
  std::vector<Real> t, mu;
  for (int p = 0; p < kPanels; ++p)
    for (int i = 0; i < 20; ++i) {
      const Real x = h * (p + 0.5 * (gl_x[i] + 1));
      t.push_back(x);
      mu.push_back(0.5 * h * gl_w[i] * std::exp(-x * x));
    }
  // Discretised Stieltjes procedure, orthonormal form.
  const std::size_t M = t.size();
  std::vector<Real> alpha(m), beta(m), q_prev(M, 0.0), q(M), r(M);
  beta[0] = 0;
  for (Real v : mu) beta[0] += v;
  for (std::size_t j = 0; j < M; ++j) q[j] = 1 / std::sqrt(beta[0]);
  for (int k = 0; k < m; ++k) {
    Real a = 0;
    for (std::size_t j = 0; j < M; ++j) a += mu[j] * t[j] * q[j] * q[j];
    alpha[k] = a;
    if (k + 1 == m) break;
    Real b = 0;
    for (std::size_t j = 0; j < M; ++j) {
      r[j] = (t[j] - a) * q[j] - (k > 0 ? std::sqrt(beta[k]) * q_prev[j] : 0.0);
      b += mu[j] * r[j] * r[j];
    }
    beta[k + 1] = b;
    for (std::size_t j = 0; j < M; ++j) {
      q_prev[j] = q[j];
      q[j] = r[j] / std::sqrt(b);
    }
  }
  std::vector<Real> x, w;
  exponential_weight_rule(alpha, beta, x, w);
  VelocityAxis a;
  for (int i = m - 1; i >= 0; --i) {
    a.x.push_back(-x[i]);
    a.w.push_back(w[i]);
  }
  for (int i = 0; i < m; ++i) {
    a.x.push_back(x[i]);
    a.w.push_back(w[i]);
  }
  return a;
}

VelocityAxis sinh_stretched_axis(int n, Real extent, Real stretch) {
  check_points(n, "sinh_stretched");
  if (!(extent > 0) || !(stretch > 0))
    throw InputError("velocity grid: the extent and the stretch must be > 0");
  VelocityAxis a;
  const Real ds = 2.0 / n, scale = extent / std::sinh(stretch);
  for (int i = 0; i < n; ++i) {
    const Real s = -1 + (i + 0.5) * ds;
    a.x.push_back(scale * std::sinh(stretch * s));
    a.w.push_back(scale * stretch * std::cosh(stretch * s) * ds);
  }
  symmetrise(a);
  return a;
}

VelocityAxis velocity_axis(VelocityRule rule, int n, Real extent, Real stretch) {
  switch (rule) {
    case VelocityRule::Uniform:
      return uniform_axis(n, extent);
    case VelocityRule::GaussHermite:
      return gauss_hermite_axis(n);
    case VelocityRule::HalfRangeHermite:
      return half_range_hermite_axis(n);
    case VelocityRule::SinhStretched:
      return sinh_stretched_axis(n, extent, stretch);
  }
  throw InputError("velocity grid: unknown rule");
}

}  // namespace rfmems

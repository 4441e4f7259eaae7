#include "physics/gas/kinetic/equilibrium.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "physics/gas/kinetic/equilibrium_tensor_kernel.hpp"

namespace rfmems {
namespace {

template <int M>
using VecM = Eigen::Matrix<Real, M, 1>;
template <int M>
using MatM = Eigen::Matrix<Real, M, M>;

template <int M>
VecM<M> basis(const Vec3& xi) {
  VecM<M> phi;
  phi[0] = 1;
  phi[1] = xi[0];
  phi[2] = xi[1];
  phi[3] = xi[2];
  if constexpr (M == 5) {
    phi[4] = xi.squaredNorm();
  } else {
    phi[4] = xi[0] * xi[0];
    phi[5] = xi[1] * xi[1];
    phi[6] = xi[2] * xi[2];
    phi[7] = xi[0] * xi[1];
    phi[8] = xi[0] * xi[2];
    phi[9] = xi[1] * xi[2];
  }
  return phi;
}

// Identifies the grid a per-thread cache was built for (its ordinates' storage, size, scale,
// end and middle points and their weights): every cell of a solve uses the same grid.
struct GridKey {
  const Vec3* key = nullptr;
  Index n = 0;
  Vec3 first = Vec3::Zero(), middle = Vec3::Zero(), last = Vec3::Zero();
  Real w_first = 0, w_middle = 0;
  Real s = 0;
  bool matches(const VelocityGrid& grid) const {
    return key == grid.c.data() && n == grid.size() && s == grid.reference_speed && n > 0 &&
           first == grid.c.front() && middle == grid.c[n / 2] && last == grid.c.back() &&
           w_first == grid.w.front() && w_middle == grid.w[n / 2];
  }
  void set(const VelocityGrid& grid) {
    key = grid.c.data();
    n = grid.size();
    s = grid.reference_speed;
    if (n > 0) {
      first = grid.c.front();
      middle = grid.c[n / 2];
      last = grid.c.back();
      w_first = grid.w.front();
      w_middle = grid.w[n / 2];
    }
  }
};

// The basis evaluated at every ordinate, Phi (N x M), and the weights: G, J and f_eq become
// matrix-vector products (vectorised exp, GEMM-like J = Phi^T diag(v) Phi). The path for
// grids that are not a tensor product (the uniform grid takes equilibrium_tensor_kernel.hpp).
template <int M>
struct BasisMatrix {
  Eigen::Matrix<Real, Eigen::Dynamic, M> phi;
  Eigen::ArrayXd w;
  GridKey key;
};

template <int M>
const BasisMatrix<M>& basis_matrix(const VelocityGrid& grid) {
  thread_local BasisMatrix<M> cache;
  if (cache.key.matches(grid)) return cache;
  const Index n = grid.size();
  cache.phi.resize(n, M);
  cache.w.resize(n);
  const Real inv_s = 1.0 / grid.reference_speed;
  for (Index k = 0; k < n; ++k) {
    cache.phi.row(k) = basis<M>(grid.c[k] * inv_s).transpose();
    cache.w[k] = grid.w[k];
  }
  cache.key.set(grid);
  return cache;
}

// The tensor-product kernel of the grid (valid() false if the grid is not one) and scratch
// vectors of N values, per thread.
struct TensorKernelCache {
  EquilibriumTensorKernel kernel;
  std::vector<Real> values;    // exp(a . phi) at the last point evaluated
  std::vector<Real> accepted;  // ... at the current Newton iterate (tensor_newton)
  GridKey key;
};

TensorKernelCache& tensor_kernel(const VelocityGrid& grid) {
  thread_local TensorKernelCache cache;
  if (cache.key.matches(grid)) return cache;
  cache.kernel = EquilibriumTensorKernel(grid);
  cache.values.assign(grid.size(), 0.0);
  cache.accepted.assign(grid.size(), 0.0);
  cache.key.set(grid);
  return cache;
}

// Target moments in the scaled variables (xi = c / s).
template <int M>
VecM<M> target_moments(const EquilibriumTarget& t, Real s) {
  const Vec3 u = t.u / s;
  const Mat3 second = t.rho * (u * u.transpose() + t.covariance / (s * s));
  VecM<M> m;
  m[0] = t.rho;
  m.template segment<3>(1) = t.rho * u;
  if constexpr (M == 5) {
    m[4] = second.trace();
  } else {
    m[4] = second(0, 0);
    m[5] = second(1, 1);
    m[6] = second(2, 2);
    m[7] = second(0, 1);
    m[8] = second(0, 2);
    m[9] = second(1, 2);
  }
  return m;
}

// d m / d u_j (SI u) at fixed rho and covariance.
template <int M>
Eigen::Matrix<Real, M, 3> target_velocity_derivative(const EquilibriumTarget& t, Real s) {
  const Vec3 u = t.u / s;
  Eigen::Matrix<Real, M, 3> d = Eigen::Matrix<Real, M, 3>::Zero();
  for (int j = 0; j < 3; ++j) {
    d(1 + j, j) = t.rho / s;
    if constexpr (M == 5) {
      d(4, j) = 2 * t.rho * u[j] / s;
    } else {
      // d(rho u_a u_b)/du_j = rho (delta_aj u_b + u_a delta_bj) / s
      auto second = [&](int a, int b) {
        return t.rho * ((a == j ? u[b] : 0.0) + (b == j ? u[a] : 0.0)) / s;
      };
      d(4, j) = second(0, 0);
      d(5, j) = second(1, 1);
      d(6, j) = second(2, 2);
      d(7, j) = second(0, 1);
      d(8, j) = second(0, 2);
      d(9, j) = second(1, 2);
    }
  }
  return d;
}

// G(a) = sum w phi exp(a . phi) - m, and optionally J = sum w phi phi^T exp(a . phi).
template <int M>
VecM<M> newton_residual(const VecM<M>& a, const VecM<M>& m, const VelocityGrid& grid, MatM<M>* J) {
  TensorKernelCache& T = tensor_kernel(grid);
  if (T.kernel.valid()) {
    T.kernel.exponential(a.data(), M, T.values.data());
    VecM<M> G;
    T.kernel.basis_moments<M>(T.values.data(), G, J);
    return G - m;
  }
  const BasisMatrix<M>& B = basis_matrix<M>(grid);
  const Eigen::ArrayXd v = B.w * (B.phi * a).array().exp();
  if (J) J->noalias() = B.phi.transpose() * (B.phi.array().colwise() * v).matrix();
  return B.phi.transpose() * v.matrix() - m;
}

template <int M>
VecM<M> continuous_start(const EquilibriumTarget& t, Real s) {
  const Mat3 lambda = t.covariance / (s * s);  // scaled covariance
  Eigen::LLT<Mat3> llt(lambda);
  if (llt.info() != Eigen::Success)
    throw RecoverableError("equilibrium: covariance not positive definite");
  const Mat3 A = llt.solve(Mat3::Identity());
  const Vec3 u = t.u / s;
  // f in SI per (m/s)^3: n0 = rho / ((2 pi)^(3/2) sqrt(det Lambda_SI)).
  const Real det_si = t.covariance.determinant();
  const Real n0 = t.rho / (std::pow(2 * std::numbers::pi, 1.5) * std::sqrt(det_si));
  VecM<M> a;
  a[0] = std::log(n0) - 0.5 * u.dot(A * u);
  a.template segment<3>(1) = A * u;
  if constexpr (M == 5) {
    a[4] = -0.5 * A.trace() / 3;  // BGK: A = I / theta
  } else {
    a[4] = -0.5 * A(0, 0);
    a[5] = -0.5 * A(1, 1);
    a[6] = -0.5 * A(2, 2);
    a[7] = -A(0, 1);
    a[8] = -A(0, 2);
    a[9] = -A(1, 2);
  }
  return a;
}

// Phi(a) = sum_k w_k exp(a . phi_k) - a . m is strictly convex with gradient G and Hessian J,
// so Newton with a backtracking (Armijo) line search on Phi converges from any start (the
// dual of the discrete entropy minimisation, Mieussens 2000). Returns false if it did not.
template <int M>
Real dual_objective(const VecM<M>& a, const VecM<M>& m, const VelocityGrid& grid) {
  TensorKernelCache& T = tensor_kernel(grid);
  if (T.kernel.valid()) {
    T.kernel.exponential(a.data(), M, T.values.data());
    return T.kernel.weighted_sum(T.values.data()) - a.dot(m);
  }
  const BasisMatrix<M>& B = basis_matrix<M>(grid);
  return (B.w * (B.phi * a).array().exp()).sum() - a.dot(m);
}

// Newton's method with the Jacobian kept while it contracts well (a chord step costs one pass
// over the grid, a new Jacobian three to five): it is refreshed when a step reduces |G| by less
// than 10x or fails to reduce it. J / have_jacobian: in, a Jacobian to start with (the cell's
// previous solve); out, the last one computed.
template <int M>
bool newton(VecM<M>& a, const VecM<M>& m, const VelocityGrid& grid, EquilibriumSolveInfo& info,
            MatM<M>& J, bool& have_jacobian) {
  constexpr int max_iterations = 100;
  const Real scale = 1.0 / m[0];
  Eigen::LDLT<MatM<M>> ldlt;
  bool current = have_jacobian;  // iterate with J until it stops contracting
  if (current) {
    ldlt.compute(J);
    if (ldlt.info() != Eigen::Success) current = false;
  }
  VecM<M> G = newton_residual<M>(a, m, grid, nullptr);
  Real norm = G.cwiseAbs().maxCoeff() * scale;
  for (int it = 0; it < max_iterations; ++it) {
    info.iterations = it;
    info.residual = norm;
    if (!std::isfinite(norm)) return false;
    if (norm < 1e-14) return true;
    const bool fresh = !current;
    if (fresh) {
      newton_residual<M>(a, m, grid, &J);
      ldlt.compute(J);
      if (ldlt.info() != Eigen::Success) return false;
      current = have_jacobian = true;
    }
    const VecM<M> step = ldlt.solve(G);
    VecM<M> trial = a - step;
    VecM<M> G_trial = newton_residual<M>(trial, m, grid, nullptr);
    Real trial_norm = G_trial.cwiseAbs().maxCoeff() * scale;
    const bool decrease = std::isfinite(trial_norm) && trial_norm < norm;
    if (decrease) {
      if (trial_norm > 0.1 * norm) current = false;
      const Real step_size = step.cwiseAbs().maxCoeff();
      a = trial;
      G = G_trial;
      norm = trial_norm;
      // A full Newton step this small leaves |G| ~ step^2: round-off.
      if (fresh && step_size < 1e-10) {
        info.iterations = it + 1;
        info.residual = norm;
        return norm < 1e-11;
      }
      continue;
    }
    // No decrease from a point already at |G| ~ round-off: that is the floor.
    if (norm < 1e-12) return true;
    if (!fresh) {  // an old Jacobian: retry with a new one
      current = false;
      continue;
    }
    // Far from the root: backtracking on the convex Phi along the Newton direction.
    const Real phi0 = dual_objective<M>(a, m, grid);
    const Real slope = G.dot(step);  // > 0: -step is a descent direction of Phi
    Real t = 0.5;
    for (int ls = 0; ls < 40; ++ls, t *= 0.5) {
      trial = a - t * step;
      const Real phi = dual_objective<M>(trial, m, grid);
      if (std::isfinite(phi) && phi <= phi0 - 1e-4 * t * slope) break;
    }
    G_trial = newton_residual<M>(trial, m, grid, nullptr);
    trial_norm = G_trial.cwiseAbs().maxCoeff() * scale;
    if (!std::isfinite(trial_norm)) return false;
    a = trial;
    G = G_trial;
    norm = trial_norm;
    current = false;
  }
  info.iterations = max_iterations;
  info.residual = norm;
  return norm < 1e-11;
}

// Newton on a tensor-product grid (equilibrium_tensor_kernel.hpp), where the Jacobian costs
// little more than G (5 against 3 operations per ordinate, one exponential table either way):
// full Newton, each evaluation gives G and J at the same point, so the iteration converges
// quadratically (the chord steps above only linearly: 4-6 evaluations per warm-started solve in
// a COMET sweep). State at the iterate a: its moments Ma = sum w phi exp(a . phi), J(a) and the
// values exp(a . phi) (T.accepted, values_current). With have_state the caller supplies Ma and
// J at a (stored with the coefficients by the last solve), so a warm start takes its first step
// without an evaluation: G(a) = Ma - m. The stopping rules are those of newton().
template <int M>
bool tensor_newton(VecM<M>& a, const VecM<M>& m, TensorKernelCache& T, const VelocityGrid& grid,
                   EquilibriumSolveInfo& info, MatM<M>& J, VecM<M>& Ma, bool have_state,
                   bool& values_current) {
  constexpr int max_iterations = 100;
  const Real scale = 1.0 / m[0];
  auto evaluate = [&](const VecM<M>& point, VecM<M>& moments, MatM<M>& jacobian) {
    T.kernel.exponential(point.data(), M, T.values.data());
    T.kernel.basis_moments<M>(T.values.data(), moments, &jacobian);
  };
  values_current = false;
  if (!have_state) {
    evaluate(a, Ma, J);
    std::swap(T.values, T.accepted);
    values_current = true;
  }
  VecM<M> G = Ma - m;
  Real norm = G.cwiseAbs().maxCoeff() * scale;
  Eigen::LDLT<MatM<M>> ldlt;
  VecM<M> M_trial;
  MatM<M> J_trial;
  auto accept = [&](const VecM<M>& trial, const VecM<M>& G_trial, Real trial_norm) {
    a = trial;
    G = G_trial;
    Ma = M_trial;
    J = J_trial;
    std::swap(T.values, T.accepted);
    values_current = true;
    norm = trial_norm;
  };
  for (int it = 0; it < max_iterations; ++it) {
    info.iterations = it;
    info.residual = norm;
    if (!std::isfinite(norm)) return false;
    if (norm < 1e-14) return true;
    ldlt.compute(J);
    if (ldlt.info() != Eigen::Success) return false;
    const VecM<M> step = ldlt.solve(G);
    VecM<M> trial = a - step;
    evaluate(trial, M_trial, J_trial);
    VecM<M> G_trial = M_trial - m;
    Real trial_norm = G_trial.cwiseAbs().maxCoeff() * scale;
    if (std::isfinite(trial_norm) && trial_norm < norm) {
      accept(trial, G_trial, trial_norm);
      // A full Newton step this small leaves |G| ~ step^2: round-off.
      if (step.cwiseAbs().maxCoeff() < 1e-10) {
        info.iterations = it + 1;
        info.residual = norm;
        return norm < 1e-11;
      }
      continue;
    }
    // No decrease from a point already at |G| ~ round-off: that is the floor.
    if (norm < 1e-12) return true;
    // Far from the root: backtracking on the convex Phi along the Newton direction.
    const Real phi0 = dual_objective<M>(a, m, grid);
    const Real slope = G.dot(step);
    Real t = 0.5;
    for (int ls = 0; ls < 40; ++ls, t *= 0.5) {
      trial = a - t * step;
      const Real phi = dual_objective<M>(trial, m, grid);
      if (std::isfinite(phi) && phi <= phi0 - 1e-4 * t * slope) break;
    }
    evaluate(trial, M_trial, J_trial);
    G_trial = M_trial - m;
    trial_norm = G_trial.cwiseAbs().maxCoeff() * scale;
    if (!std::isfinite(trial_norm)) return false;
    accept(trial, G_trial, trial_norm);
  }
  info.iterations = max_iterations;
  info.residual = norm;
  return norm < 1e-11;
}

// Newton from the continuous Maxwellian did not reach the discrete moments either.
[[noreturn]] void not_converged(const EquilibriumTarget& target, const EquilibriumSolveInfo& info) {
  throw SolverError(
      "discrete equilibrium: Newton did not converge (rho = " + std::to_string(target.rho) +
      ", |G|/rho = " + std::to_string(info.residual) + ")");
}

// The converged coefficients a, and the Jacobian J of the moments in them where it is current
// (null: none kept).
template <int M>
void store_coefficients(EquilibriumCoefficients& coefficients, const VecM<M>& a, const MatM<M>* J) {
  coefficients.size = M;
  coefficients.a.fill(0);
  for (int i = 0; i < M; ++i) coefficients.a[i] = a[i];
  coefficients.has_jacobian = J != nullptr;
  if (J) Eigen::Map<MatM<M>>(coefficients.jacobian.data()) = *J;
}

// The tensor-grid solve: warm start from the coefficients with their stored moments and
// Jacobian (while those are still of a), else the continuous start. f_eq (if not empty): the
// values of the new coefficients, written only if they changed.
template <int M>
EquilibriumSolveInfo solve_tensor(const EquilibriumTarget& target, const VelocityGrid& grid,
                                  TensorKernelCache& T, EquilibriumCoefficients& coefficients,
                                  std::span<Real> f_eq) {
  const Real s = grid.reference_speed;
  const VecM<M> m = target_moments<M>(target, s);
  EquilibriumSolveInfo info;
  VecM<M> a, Ma;
  MatM<M> J;
  bool values_current = false;
  bool warm = coefficients.size == M;
  if (warm) {
    for (int i = 0; i < M; ++i) a[i] = coefficients.a[i];
    const bool have_state = coefficients.has_moments && coefficients.moments_at == coefficients.a;
    if (have_state) {
      J = Eigen::Map<const MatM<M>>(coefficients.jacobian.data());
      for (int i = 0; i < M; ++i) Ma[i] = coefficients.moments[i];
    }
    if (!tensor_newton<M>(a, m, T, grid, info, J, Ma, have_state, values_current)) warm = false;
  }
  if (!warm) {
    a = continuous_start<M>(target, s);
    if (!tensor_newton<M>(a, m, T, grid, info, J, Ma, false, values_current))
      not_converged(target, info);
  }
  store_coefficients<M>(coefficients, a, &J);
  coefficients.moments.fill(0);
  for (int i = 0; i < M; ++i) coefficients.moments[i] = Ma[i];
  coefficients.moments_at = coefficients.a;
  coefficients.has_moments = true;
  if (!f_eq.empty() && values_current)
    std::copy(T.accepted.begin(), T.accepted.end(), f_eq.begin());
  info.values_written = values_current;
  return info;
}

template <int M>
EquilibriumSolveInfo solve(const EquilibriumTarget& target, const VelocityGrid& grid,
                           EquilibriumCoefficients& coefficients) {
  const Real s = grid.reference_speed;
  const VecM<M> m = target_moments<M>(target, s);
  EquilibriumSolveInfo info;
  VecM<M> a;
  MatM<M> J;
  bool warm = coefficients.size == M;
  bool have_jacobian = warm && coefficients.has_jacobian;
  if (warm) {
    for (int i = 0; i < M; ++i) a[i] = coefficients.a[i];
    if (have_jacobian) J = Eigen::Map<const MatM<M>>(coefficients.jacobian.data());
    if (!newton<M>(a, m, grid, info, J, have_jacobian)) warm = false;
  }
  if (!warm) {
    a = continuous_start<M>(target, s);
    have_jacobian = false;
    if (!newton<M>(a, m, grid, info, J, have_jacobian)) not_converged(target, info);
  }
  store_coefficients<M>(coefficients, a, have_jacobian ? &J : nullptr);
  coefficients.has_moments = false;
  return info;
}

template <int M>
void velocity_derivative(const EquilibriumCoefficients& coefficients,
                         const EquilibriumTarget& target, const VelocityGrid& grid,
                         std::span<const Real> f_eq, std::span<Real> df_du) {
  (void)coefficients;
  const TensorKernelCache& T = tensor_kernel(grid);
  if (T.kernel.valid()) {
    VecM<M> G;
    MatM<M> J;
    T.kernel.basis_moments<M>(f_eq.data(), G, &J);
    const Eigen::Matrix<Real, M, 3> da_du =
        Eigen::LDLT<MatM<M>>(J).solve(target_velocity_derivative<M>(target, grid.reference_speed));
    T.kernel.basis_combination<M, 3>(f_eq.data(), da_du, df_du.data());
    return;
  }
  const Real inv_s = 1.0 / grid.reference_speed;
  MatM<M> J = MatM<M>::Zero();
  for (Index k = 0; k < grid.size(); ++k) {
    const VecM<M> phi = basis<M>(grid.c[k] * inv_s);
    J.template selfadjointView<Eigen::Lower>().rankUpdate(phi, grid.w[k] * f_eq[k]);
  }
  J = J.template selfadjointView<Eigen::Lower>();
  const Eigen::Matrix<Real, M, 3> da_du =
      Eigen::LDLT<MatM<M>>(J).solve(target_velocity_derivative<M>(target, grid.reference_speed));
  for (Index k = 0; k < grid.size(); ++k) {
    const VecM<M> phi = basis<M>(grid.c[k] * inv_s);
    const Eigen::RowVector3d d = f_eq[k] * (phi.transpose() * da_du);
    for (int j = 0; j < 3; ++j) df_du[3 * k + j] = d[j];
  }
}

}  // namespace

EquilibriumTarget equilibrium_target(const MacroState& m, const KineticGas& gas) {
  EquilibriumTarget t;
  t.rho = m.rho;
  t.u = m.u;
  const Real RT = gas.R * m.T;
  if (gas.model == CollisionModel::Bgk) {
    t.covariance = RT * Mat3::Identity();
  } else {
    const Mat3 theta = m.pressure_tensor / m.rho;
    t.covariance = (RT / gas.prandtl) * Mat3::Identity() + (1 - 1 / gas.prandtl) * theta;
  }
  return t;
}

EquilibriumTarget maxwellian_target(Real rho, const Vec3& u, Real T, const KineticGas& gas) {
  return {rho, u, gas.R * T * Mat3::Identity()};
}

EquilibriumCoefficients continuous_coefficients(const EquilibriumTarget& target,
                                                CollisionModel model, const VelocityGrid& grid) {
  EquilibriumCoefficients c;
  if (model == CollisionModel::Bgk) {
    const VecM<5> a = continuous_start<5>(target, grid.reference_speed);
    for (int i = 0; i < 5; ++i) c.a[i] = a[i];
    c.size = 5;
  } else {
    const VecM<10> a = continuous_start<10>(target, grid.reference_speed);
    for (int i = 0; i < 10; ++i) c.a[i] = a[i];
    c.size = 10;
  }
  return c;
}

EquilibriumSolveInfo solve_equilibrium(const EquilibriumTarget& target, CollisionModel model,
                                       const VelocityGrid& grid,
                                       EquilibriumCoefficients& coefficients) {
  return solve_equilibrium(target, model, grid, coefficients, std::span<Real>());
}

EquilibriumSolveInfo solve_equilibrium(const EquilibriumTarget& target, CollisionModel model,
                                       const VelocityGrid& grid,
                                       EquilibriumCoefficients& coefficients,
                                       std::span<Real> f_eq) {
  if (!(target.rho > 0)) throw RecoverableError("discrete equilibrium: non-positive density");
  TensorKernelCache& T = tensor_kernel(grid);
  if (T.kernel.valid())
    return model == CollisionModel::Bgk ? solve_tensor<5>(target, grid, T, coefficients, f_eq)
                                        : solve_tensor<10>(target, grid, T, coefficients, f_eq);
  EquilibriumSolveInfo info = model == CollisionModel::Bgk ? solve<5>(target, grid, coefficients)
                                                           : solve<10>(target, grid, coefficients);
  if (!f_eq.empty()) {
    evaluate_equilibrium(coefficients, grid, f_eq);
    info.values_written = true;
  }
  return info;
}

EquilibriumCoefficients equilibrium(const EquilibriumTarget& target, CollisionModel model,
                                    const VelocityGrid& grid) {
  EquilibriumCoefficients c;
  solve_equilibrium(target, model, grid, c);
  return c;
}

void evaluate_equilibrium(const EquilibriumCoefficients& coefficients, const VelocityGrid& grid,
                          std::span<Real> f_eq) {
  const TensorKernelCache& T = tensor_kernel(grid);
  if (T.kernel.valid()) {
    T.kernel.exponential(coefficients.a.data(), coefficients.size, f_eq.data());
    return;
  }
  Eigen::Map<Eigen::VectorXd> out(f_eq.data(), grid.size());
  if (coefficients.size == 5) {
    const VecM<5> a = Eigen::Map<const VecM<5>>(coefficients.a.data());
    out = (basis_matrix<5>(grid).phi * a).array().exp().matrix();
  } else {
    const VecM<10> a = Eigen::Map<const VecM<10>>(coefficients.a.data());
    out = (basis_matrix<10>(grid).phi * a).array().exp().matrix();
  }
}

void equilibrium_velocity_derivative(const EquilibriumCoefficients& coefficients,
                                     const EquilibriumTarget& target, const VelocityGrid& grid,
                                     std::span<const Real> f_eq, std::span<Real> df_du) {
  if (coefficients.size == 5)
    velocity_derivative<5>(coefficients, target, grid, f_eq, df_du);
  else
    velocity_derivative<10>(coefficients, target, grid, f_eq, df_du);
}

MacroState cell_moments(std::span<const Real> f_cell, const VelocityGrid& grid,
                        const KineticGas& gas) {
  const TensorKernelCache& T = tensor_kernel(grid);
  if (!T.kernel.valid()) return moments(f_cell, grid, gas);
  MacroState m;
  Real rho;
  Vec3 u, q;
  Mat3 P;
  T.kernel.central_moments(f_cell.data(), rho, u, P, q);
  if (!(rho > 0)) throw RecoverableError("kinetic moments: non-positive density");
  const Real s = grid.reference_speed;
  m.rho = rho;
  m.u = s * u;
  m.pressure_tensor = (s * s) * P;
  m.p = m.pressure_tensor.trace() / 3;
  m.T = m.p / (rho * gas.R);
  m.stress = -(m.pressure_tensor - m.p * Mat3::Identity());
  m.heat_flux = (s * s * s) * q;
  return m;
}

void sample_maxwellian(Real rho, const Vec3& u, Real T, const KineticGas& gas,
                       const VelocityGrid& grid, std::span<Real> f) {
  const Real two_RT = 2 * gas.R * T;
  const Real n0 = rho / std::pow(std::numbers::pi * two_RT, 1.5);
  for (Index k = 0; k < grid.size(); ++k)
    f[k] = n0 * std::exp(-(grid.c[k] - u).squaredNorm() / two_RT);
}

}  // namespace rfmems

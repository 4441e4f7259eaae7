#include "physics/gas/comet/equilibrium_moment_derivative.hpp"

#include "core/error.hpp"

namespace rfmems {

Eigen::Matrix<Real, 5, 1> conserved_moments(const VelocityGrid& grid, std::span<const Real> f) {
  Eigen::Matrix<Real, 5, 1> U = Eigen::Matrix<Real, 5, 1>::Zero();
  for (Index k = 0; k < grid.size(); ++k) U += grid.w[k] * f[k] * conserved_basis(grid, k);
  return U;
}

namespace {

// dm/dU (P x 5) from the moments G of f_eq (= those of f): the identity for BGK (phi = psi);
// for ESBGK the second moments Q = m m^T / rho + p I + A with A held fixed.
template <int P>
Eigen::Matrix<Real, P, 5> target_derivative(const Eigen::Matrix<Real, P, 1>& G) {
  Eigen::Matrix<Real, P, 5> dm = Eigen::Matrix<Real, P, 5>::Zero();
  if constexpr (P == 5) {
    dm.setIdentity();
  } else {
    const Real rho = G[0];
    const Vec3 mom = G.template segment<3>(1);
    const Real m2 = mom.squaredNorm();
    for (int i = 0; i < 4; ++i) dm(i, i) = 1.0;
    const int row[3][3] = {{4, 7, 8}, {7, 5, 9}, {8, 9, 6}};
    for (int a = 0; a < 3; ++a)
      for (int b = a; b < 3; ++b) {
        const int r = row[a][b];
        const Real delta = a == b ? 1.0 : 0.0;
        dm(r, 0) = -mom[a] * mom[b] / (rho * rho) + delta * m2 / (3 * rho * rho);
        for (int l = 0; l < 3; ++l)
          dm(r, 1 + l) = ((a == l ? mom[b] : 0.0) + (b == l ? mom[a] : 0.0)) / rho -
                         delta * 2 * mom[l] / (3 * rho);
        dm(r, 4) = delta / 3;
      }
  }
  return dm;
}

}  // namespace

EquilibriumMomentDerivative::EquilibriumMomentDerivative(CollisionModel model,
                                                         const VelocityGrid& grid)
    : model_(model), kernel_(grid) {
  const Index n = grid.size();
  const int P = model == CollisionModel::Bgk ? 5 : 10;
  phi_.resize(n, P);
  w_.resize(n);
  const Real inv_s = 1.0 / grid.reference_speed;
  for (Index k = 0; k < n; ++k) {
    const Vec3 xi = grid.c[k] * inv_s;
    w_[k] = grid.w[k];
    phi_(k, 0) = 1.0;
    phi_.row(k).segment<3>(1) = xi.transpose();
    if (P == 5) {
      phi_(k, 4) = xi.squaredNorm();
    } else {
      phi_(k, 4) = xi[0] * xi[0];
      phi_(k, 5) = xi[1] * xi[1];
      phi_(k, 6) = xi[2] * xi[2];
      phi_(k, 7) = xi[0] * xi[1];
      phi_(k, 8) = xi[0] * xi[2];
      phi_(k, 9) = xi[1] * xi[2];
    }
  }
  weighted_.resize(n, P);
}

template <int P>
Eigen::Matrix<Real, P, 5> EquilibriumMomentDerivative::basis_coefficients(
    const Eigen::Matrix<Real, P, 1>& G, const Eigen::Matrix<Real, P, P>& J) {
  const Eigen::LDLT<Eigen::Matrix<Real, P, P>> ldlt(J);
  if (ldlt.info() != Eigen::Success)
    throw RecoverableError("equilibrium_conserved_derivative: moment matrix not positive definite");
  return ldlt.solve(target_derivative<P>(G));
}

template Eigen::Matrix<Real, 5, 5> EquilibriumMomentDerivative::basis_coefficients<5>(
    const Eigen::Matrix<Real, 5, 1>&, const Eigen::Matrix<Real, 5, 5>&);
template Eigen::Matrix<Real, 10, 5> EquilibriumMomentDerivative::basis_coefficients<10>(
    const Eigen::Matrix<Real, 10, 1>&, const Eigen::Matrix<Real, 10, 10>&);

template <int P>
void EquilibriumMomentDerivative::evaluate_tensor(std::span<const Real> f_eq, std::span<Real> df_dU,
                                                  Real scale) {
  Eigen::Matrix<Real, P, 1> G;
  Eigen::Matrix<Real, P, P> J;
  kernel_.basis_moments<P>(f_eq.data(), G, &J);
  const Eigen::Matrix<Real, P, 5> Y = scale * basis_coefficients<P>(G, J);
  kernel_.basis_combination<P, 5>(f_eq.data(), Y, df_dU.data());
}

void EquilibriumMomentDerivative::evaluate(std::span<const Real> f_eq, std::span<Real> df_dU,
                                           Real scale) {
  if (kernel_.valid()) {
    if (phi_.cols() == 5)
      evaluate_tensor<5>(f_eq, df_dU, scale);
    else
      evaluate_tensor<10>(f_eq, df_dU, scale);
    return;
  }
  const Index n = phi_.rows();
  const int P = static_cast<int>(phi_.cols());
  const Eigen::Map<const Eigen::VectorXd> feq(f_eq.data(), n);
  // weighted = diag(w f_eq) phi;  J = phi^T weighted;  moments of f_eq = weighted^T 1.
  weighted_.noalias() = (w_.cwiseProduct(feq)).asDiagonal() * phi_;
  const Eigen::MatrixXd J = phi_.transpose() * weighted_;
  const Eigen::VectorXd G = weighted_.colwise().sum().transpose();
  // dm/dU (P x 5): identity for BGK (phi = psi); for ESBGK the second moments
  // Q = m m^T / rho + p I + A with A held fixed.
  Eigen::MatrixXd dm;
  if (P == 5)
    dm = target_derivative<5>(Eigen::Matrix<Real, 5, 1>(G));
  else
    dm = target_derivative<10>(Eigen::Matrix<Real, 10, 1>(G));
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(J);
  if (ldlt.info() != Eigen::Success)
    throw RecoverableError("equilibrium_conserved_derivative: moment matrix not positive definite");
  const Eigen::MatrixXd Y = scale * ldlt.solve(dm);  // P x 5
  // df/dU = diag(f_eq) phi Y, row-major N x 5.
  Eigen::Map<Eigen::Matrix<Real, Eigen::Dynamic, 5, Eigen::RowMajor>> out(df_dU.data(), n, 5);
  out.noalias() = feq.asDiagonal() * (phi_ * Y);
  (void)model_;
}

void equilibrium_conserved_derivative(CollisionModel model, const VelocityGrid& grid,
                                      std::span<const Real> f_eq, std::span<Real> df_dU) {
  EquilibriumMomentDerivative(model, grid).evaluate(f_eq, df_dU);
}

}  // namespace rfmems

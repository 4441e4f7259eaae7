#include "physics/gas/comet/equilibrium_moment_derivative.hpp"

#include "core/error.hpp"

namespace rfmems {
namespace {

using Vec5 = Eigen::Matrix<Real, 5, 1>;
using Vec10 = Eigen::Matrix<Real, 10, 1>;

Vec10 es_basis(const Vec3& xi) {
  Vec10 phi;
  phi << 1.0, xi[0], xi[1], xi[2], xi[0] * xi[0], xi[1] * xi[1], xi[2] * xi[2], xi[0] * xi[1],
      xi[0] * xi[2], xi[1] * xi[2];
  return phi;
}

template <int P, class Basis>
void derivative(const VelocityGrid& grid, std::span<const Real> f_eq,
                const Eigen::Matrix<Real, P, 5>& dm_dU, Basis basis, std::span<Real> df_dU,
                const Eigen::Matrix<Real, P, P>& J) {
  const Eigen::LDLT<Eigen::Matrix<Real, P, P>> ldlt(J);
  if (ldlt.info() != Eigen::Success)
    throw RecoverableError("equilibrium_conserved_derivative: moment matrix not positive definite");
  const Eigen::Matrix<Real, P, 5> Y = ldlt.solve(dm_dU);
  const Real inv_s = 1.0 / grid.reference_speed;
  for (Index k = 0; k < grid.size(); ++k) {
    const Eigen::Matrix<Real, 1, 5> d = f_eq[k] * (basis(grid.c[k] * inv_s).transpose() * Y);
    for (int j = 0; j < 5; ++j) df_dU[5 * k + j] = d[j];
  }
}

}  // namespace

Eigen::Matrix<Real, 5, 1> conserved_moments(const VelocityGrid& grid, std::span<const Real> f) {
  Vec5 U = Vec5::Zero();
  for (Index k = 0; k < grid.size(); ++k) U += grid.w[k] * f[k] * conserved_basis(grid, k);
  return U;
}

void equilibrium_conserved_derivative(CollisionModel model, const VelocityGrid& grid,
                                      std::span<const Real> f_eq, std::span<Real> df_dU) {
  const Real inv_s = 1.0 / grid.reference_speed;
  if (model == CollisionModel::Bgk) {
    Eigen::Matrix<Real, 5, 5> J = Eigen::Matrix<Real, 5, 5>::Zero();
    for (Index k = 0; k < grid.size(); ++k)
      J.selfadjointView<Eigen::Lower>().rankUpdate(conserved_basis(grid, k), grid.w[k] * f_eq[k]);
    J = J.selfadjointView<Eigen::Lower>();
    derivative<5>(grid, f_eq, Eigen::Matrix<Real, 5, 5>::Identity(),
                  [](const Vec3& xi) {
                    Vec5 p;
                    p << 1.0, xi[0], xi[1], xi[2], xi.squaredNorm();
                    return p;
                  },
                  df_dU, J);
    return;
  }
  Eigen::Matrix<Real, 10, 10> J = Eigen::Matrix<Real, 10, 10>::Zero();
  Vec5 U = Vec5::Zero();
  for (Index k = 0; k < grid.size(); ++k) {
    const Vec3 xi = grid.c[k] * inv_s;
    J.selfadjointView<Eigen::Lower>().rankUpdate(es_basis(xi), grid.w[k] * f_eq[k]);
    U += grid.w[k] * f_eq[k] * conserved_basis(grid, k);
  }
  J = J.selfadjointView<Eigen::Lower>();
  // dm/dU: m = (rho, m, Q_xx, Q_yy, Q_zz, Q_xy, Q_xz, Q_yz), Q = m m^T/rho + p I + A.
  const Real rho = U[0];
  const Vec3 mom = U.segment<3>(1);
  const Real m2 = mom.squaredNorm();
  Eigen::Matrix<Real, 10, 5> dm = Eigen::Matrix<Real, 10, 5>::Zero();
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
  derivative<10>(grid, f_eq, dm, es_basis, df_dU, J);
}

}  // namespace rfmems

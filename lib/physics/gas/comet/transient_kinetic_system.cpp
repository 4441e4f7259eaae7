#include "physics/gas/comet/transient_kinetic_system.hpp"

#include <stdexcept>

namespace rfmems {

TransientKineticSystem::TransientKineticSystem(KineticOperator& op)
    : op_(op), derivative_(op.gas().model, op.grid()) {
  const Index N = op_.n_ordinates();
  scratch_.resize(N);
  weighted_basis_.resize(5 * N);
  for (Index k = 0; k < N; ++k) {
    const Eigen::Matrix<Real, 5, 1> psi = conserved_basis(op_.grid(), k);
    for (int j = 0; j < 5; ++j) weighted_basis_[5 * k + j] = op_.grid().w[k] * psi[j];
  }
}

std::vector<Real> TransientKineticSystem::differential_components() const {
  return std::vector<Real>(size(), 1.0);
}

void TransientKineticSystem::residual(Real, std::span<const Real> f, std::span<const Real> fp,
                                      std::span<Real> r) {
  op_.residual(f, r);
  const Index N = op_.n_ordinates();
  for (Index c = 0; c < op_.n_owned_cells(); ++c) {
    const Real V = op_.graph().cell_volume[c];
    for (Index k = 0; k < N; ++k) r[c * N + k] += V * fp[c * N + k];
  }
}

const CsrPattern& TransientKineticSystem::jacobian_pattern() const {
  static const CsrPattern none;
  return none;
}

void TransientKineticSystem::jacobian(Real, Real, std::span<const Real>, std::span<const Real>,
                                      std::span<Real>) {
  throw std::logic_error(
      "TransientKineticSystem is matrix-free: integrate it with the Krylov (SPGMR) solver");
}

void TransientKineticSystem::preconditioner_setup(Real, Real c_j, std::span<const Real> f,
                                                  std::span<const Real>) {
  ++setups_;
  op_.update_boundary_values(f);
  op_.update_collision(f);
  const Index N = op_.n_ordinates(), nc = op_.n_owned_cells();
  inverse_diagonal_.resize(nc * N);
  z_.resize(nc * 5 * N);
  capacitance_.resize(nc);
  std::vector<Real>& out = scratch_;
  for (Index c = 0; c < nc; ++c) {
    const Real V = op_.graph().cell_volume[c];
    const Real vnu = V * op_.collision_frequency(c);
    op_.outgoing_coefficients(c, out);
    Real* d_inv = inverse_diagonal_.data() + c * N;
    Real* z = z_.data() + c * 5 * N;
    // B = -V nu d f_eq / dU, then Z = D^-1 B in place.
    derivative_.evaluate(op_.equilibrium(c), std::span<Real>(z, 5 * N), -vnu);
    Mat5 capacitance = Mat5::Identity();
    for (Index k = 0; k < N; ++k) {
      d_inv[k] = 1.0 / (c_j * V + out[k] + vnu);
      for (int j = 0; j < 5; ++j) z[5 * k + j] *= d_inv[k];
      for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) capacitance(i, j) += weighted_basis_[5 * k + i] * z[5 * k + j];
    }
    capacitance_[c].compute(capacitance);
  }
}

void TransientKineticSystem::preconditioner_solve(std::span<const Real> r, std::span<Real> z_out) {
  const Index N = op_.n_ordinates(), nc = op_.n_owned_cells();
  std::fill(z_out.begin(), z_out.end(), 0.0);
  for (Index c = 0; c < nc; ++c) {
    const Real* d_inv = inverse_diagonal_.data() + c * N;
    const Real* z = z_.data() + c * 5 * N;
    Real* y = z_out.data() + c * N;
    Eigen::Matrix<Real, 5, 1> cy = Eigen::Matrix<Real, 5, 1>::Zero();
    for (Index k = 0; k < N; ++k) {
      y[k] = d_inv[k] * r[c * N + k];
      for (int i = 0; i < 5; ++i) cy[i] += weighted_basis_[5 * k + i] * y[k];
    }
    const Eigen::Matrix<Real, 5, 1> x = capacitance_[c].solve(cy);
    for (Index k = 0; k < N; ++k)
      for (int j = 0; j < 5; ++j) y[k] -= z[5 * k + j] * x[j];
  }
}

}  // namespace rfmems

#include "physics/creep/material_point_creep.hpp"

namespace rfmems {

MaterialPointCreep::MaterialPointCreep(const CreepLaw& law, std::function<Mat3(Real t)> stress)
    : law_(law), stress_(std::move(stress)) {
  law_.validate();
  for (Index i = 0; i < 7; ++i) {
    for (Index j = 0; j < 7; ++j) pattern_.col_idx.push_back(j);
    pattern_.row_ptr.push_back(pattern_.nnz());
  }
}

Eigen::Matrix<Real, 7, 1> MaterialPointCreep::pack(const CreepRate& r) {
  const Mat3& d = r.strain_rate;
  Eigen::Matrix<Real, 7, 1> v;
  v << d(0, 0), d(1, 1), d(2, 2), d(1, 2), d(0, 2), d(0, 1), r.effective_rate;
  return v;
}

std::vector<Real> MaterialPointCreep::rates(Real t, std::span<const Real> y) const {
  const auto g = pack(law_.rate(stress_(t), y[kEff]));
  return std::vector<Real>(g.data(), g.data() + 7);
}

void MaterialPointCreep::residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                                  std::span<Real> r) {
  const std::vector<Real> g = rates(t, y);
  for (int i = 0; i < 7; ++i) r[i] = yp[i] - g[i];
}

void MaterialPointCreep::jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real>,
                                  std::span<Real> values) {
  const auto dg = pack(law_.rate_hardening_derivative(stress_(t), y[kEff]));
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)
      values[7 * i + j] = (i == j ? c_j : 0.0) - (j == kEff ? dg[i] : 0.0);
}

}  // namespace rfmems

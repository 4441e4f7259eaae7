#include "coupling/displacement_control_system.hpp"

#include <algorithm>
#include <cmath>

namespace rfmems {

DisplacementControlSystem::DisplacementControlSystem(ParallelPlateActuation& act, Index control,
                                                     Real k_ref)
    : act_(act), n_(act.size()), control_(control), k_ref_(k_ref), q_(n_) {
  // Rows 0..n-1: the structure's stiffness row plus the column n (q); row n: (n, control).
  const CsrPattern& k = act_.stiffness_pattern();
  pattern_.row_ptr.assign(1, 0);
  for (Index i = 0; i < n_; ++i) {
    for (Index p = k.row_ptr[i]; p < k.row_ptr[i + 1]; ++p)
      pattern_.col_idx.push_back(k.col_idx[p]);
    pattern_.col_idx.push_back(n_);
    pattern_.row_ptr.push_back(static_cast<Index>(pattern_.col_idx.size()));
  }
  pattern_.col_idx.push_back(control_);
  pattern_.row_ptr.push_back(static_cast<Index>(pattern_.col_idx.size()));
  k_values_.resize(k.nnz());
}

void DisplacementControlSystem::residual(Real t, std::span<const Real> y, std::span<const Real>,
                                         std::span<Real> r) {
  const Real lambda = y[n_];
  act_.set_voltage_squared([lambda](Real) { return lambda; });
  act_.internal_residual(t, y.subspan(0, n_), r.subspan(0, n_));
  r[n_] = k_ref_ * (y[control_] - delta_);
}

void DisplacementControlSystem::jacobian(Real t, Real, std::span<const Real> y,
                                         std::span<const Real>, std::span<Real> values) {
  const Real lambda = y[n_];
  act_.set_voltage_squared([lambda](Real) { return lambda; });
  act_.stiffness(t, y.subspan(0, n_), k_values_);
  act_.residual_per_volt2(y.subspan(0, n_), q_);
  const CsrPattern& k = act_.stiffness_pattern();
  Index out = 0;
  for (Index i = 0; i < n_; ++i) {
    for (Index p = k.row_ptr[i]; p < k.row_ptr[i + 1]; ++p) values[out++] = k_values_[p];
    values[out++] = q_[i];
  }
  values[out] = k_ref_;
}

Real DisplacementControlSystem::load_scale(std::span<const Real> y) {
  act_.residual_per_volt2(y.subspan(0, n_), q_);
  Real largest = 0;
  for (const Real qi : q_) largest = std::max(largest, std::abs(qi));
  return std::abs(y[n_]) * largest;
}

}  // namespace rfmems

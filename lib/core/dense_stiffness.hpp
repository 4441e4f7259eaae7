// The stiffness dR/dy of a structural operator at y, as a dense matrix: for modal analyses of
// small meshes (eigenvalues of M^-1 K in benchmarks and tests).
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "core/system_operator.hpp"

namespace rfmems {

inline Eigen::MatrixXd dense_stiffness(SecondOrderOperator& op, Real t = 0,
                                       std::vector<Real> y = {}) {
  const Index n = op.size();
  if (y.empty()) y.assign(n, 0.0);
  const CsrPattern& pattern = op.stiffness_pattern();
  std::vector<Real> values(pattern.nnz(), 0.0);
  op.stiffness(t, y, values);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (Index i = 0; i < n; ++i)
    for (Index k = pattern.row_ptr[i]; k < pattern.row_ptr[i + 1]; ++k)
      K(i, pattern.col_idx[k]) = values[k];
  return K;
}

}  // namespace rfmems

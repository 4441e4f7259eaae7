// Finite-difference check of an analytic Jacobian: every column of dF/dy (and dF/dy') by
// central differences, compared entry by entry with the CSR values, including the entries
// outside the pattern (which must be zero).
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/system_operator.hpp"

namespace rfmems::test_support {

struct JacobianCheck {
  double max_abs_difference = 0;  // max |J_fd - J_analytic|
  double max_abs_entry = 0;       // max |J_analytic|
  double relative() const { return max_abs_difference / max_abs_entry; }
};

inline JacobianCheck check_jacobian(SystemOperator& op, double t, double c_j,
                                    const std::vector<double>& y, const std::vector<double>& yp,
                                    double step) {
  const Index n = op.size();
  const CsrPattern& pattern = op.jacobian_pattern();
  std::vector<double> values(pattern.nnz(), 0.0);
  op.jacobian(t, c_j, y, yp, values);
  JacobianCheck result;
  for (double v : values) result.max_abs_entry = std::max(result.max_abs_entry, std::abs(v));

  std::vector<double> yy = y, yyp = yp, rp(n), rm(n), column(n);
  for (Index j = 0; j < n; ++j) {
    // dF/dy_j + c_j dF/dy'_j by central differences.
    yy[j] = y[j] + step;
    op.residual(t, yy, yp, rp);
    yy[j] = y[j] - step;
    op.residual(t, yy, yp, rm);
    yy[j] = y[j];
    for (Index i = 0; i < n; ++i) column[i] = (rp[i] - rm[i]) / (2 * step);
    if (c_j != 0) {
      yyp[j] = yp[j] + step;
      op.residual(t, y, yyp, rp);
      yyp[j] = yp[j] - step;
      op.residual(t, y, yyp, rm);
      yyp[j] = yp[j];
      for (Index i = 0; i < n; ++i) column[i] += c_j * (rp[i] - rm[i]) / (2 * step);
    }
    for (Index i = 0; i < n; ++i) {
      Index pos = pattern.find(i, j);
      double analytic = pos >= 0 ? values[pos] : 0.0;
      result.max_abs_difference = std::max(result.max_abs_difference, std::abs(column[i] - analytic));
    }
  }
  return result;
}

}  // namespace rfmems::test_support

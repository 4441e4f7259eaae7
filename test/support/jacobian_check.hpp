// Finite-difference check of an analytic Jacobian: every column of dF/dy (and dF/dy') by
// central differences, compared entry by entry with the CSR values, including the entries
// outside the pattern (which must be zero).
#pragma once
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/system_operator.hpp"

namespace rfmems::test_support {

struct JacobianCheck {
  double max_abs_difference = 0;  // max |J_fd - J_analytic|
  double max_abs_entry = 0;       // max |J_analytic|
  // max over rows of max_j |J_fd - J_analytic| / max_j |J_analytic| (for systems whose rows
  // have different units, e.g. forces and film mass fluxes).
  double max_row_relative = 0;
  // max over entries of |J_fd - J_analytic| / (|J_analytic| + 1e-6 max_j |J_analytic| of the
  // row): every entry checked on its own scale (small coupling entries next to large ones).
  double max_entry_relative = 0;
  Index worst_row = -1;                              // where max_row_relative occurs
  Index worst_entry_row = -1, worst_entry_col = -1;  // where max_entry_relative occurs
  double relative() const { return max_abs_difference / max_abs_entry; }
};

// A state to check at: n values uniform in [-scale, scale] from a generator seeded with seed.
inline std::vector<double> random_state(Index n, unsigned seed, double scale) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-scale, scale);
  std::vector<double> y(n);
  for (double& v : y) v = value(rng);
  return y;
}

// The analytic J = dF/dy + c_j dF/dy' in the operator's CSR pattern.
inline std::vector<double> analytic_jacobian(SystemOperator& op, double t, double c_j,
                                             const std::vector<double>& y,
                                             const std::vector<double>& yp) {
  std::vector<double> values(op.jacobian_pattern().nnz(), 0.0);
  op.jacobian(t, c_j, y, yp, values);
  return values;
}

// Calls visit(i, j, fd, analytic) for every entry of the n x n matrix, in column order: fd the
// central difference of dF_i/dy_j + c_j dF_i/dy'_j with step steps[j] (for y_j and y'_j),
// analytic the CSR value (0 outside the pattern).
template <class Visit>
void for_each_jacobian_entry(SystemOperator& op, double t, double c_j, const std::vector<double>& y,
                             const std::vector<double>& yp, const std::vector<double>& steps,
                             const std::vector<double>& values, Visit&& visit) {
  const Index n = op.size();
  const CsrPattern& pattern = op.jacobian_pattern();
  std::vector<double> yy = y, yyp = yp, rp(n), rm(n), column(n);
  for (Index j = 0; j < n; ++j) {
    const double step = steps[j];
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
      const Index pos = pattern.find(i, j);
      visit(i, j, column[i], pos >= 0 ? values[pos] : 0.0);
    }
  }
}

// steps[j]: the difference step of unknown j (and of its derivative); one step for all
// unknowns with the overload below.
// scales[j]: the typical size of unknown j, for max_entry_relative (default: the steps).
inline JacobianCheck check_jacobian(SystemOperator& op, double t, double c_j,
                                    const std::vector<double>& y, const std::vector<double>& yp,
                                    const std::vector<double>& steps,
                                    const std::vector<double>& scales = {}) {
  const std::vector<double>& unit = scales.empty() ? steps : scales;
  const Index n = op.size();
  const CsrPattern& pattern = op.jacobian_pattern();
  const std::vector<double> values = analytic_jacobian(op, t, c_j, y, yp);
  JacobianCheck result;
  for (double v : values) result.max_abs_entry = std::max(result.max_abs_entry, std::abs(v));

  std::vector<double> row_difference(n, 0.0), row_entry(n, 0.0), row_scaled(n, 0.0);
  for (Index i = 0; i < n; ++i)
    for (Index p = pattern.row_ptr[i]; p < pattern.row_ptr[i + 1]; ++p) {
      row_entry[i] = std::max(row_entry[i], std::abs(values[p]));
      row_scaled[i] = std::max(row_scaled[i], std::abs(values[p]) * unit[pattern.col_idx[p]]);
    }
  for_each_jacobian_entry(
      op, t, c_j, y, yp, steps, values, [&](Index i, Index j, double fd, double analytic) {
        const double difference = std::abs(fd - analytic);
        result.max_abs_difference = std::max(result.max_abs_difference, difference);
        row_difference[i] = std::max(row_difference[i], difference);
        const double entry_relative =
            difference * unit[j] / (std::abs(analytic) * unit[j] + 1e-6 * row_scaled[i] + 1e-300);
        if (entry_relative > result.max_entry_relative) {
          result.max_entry_relative = entry_relative;
          result.worst_entry_row = i;
          result.worst_entry_col = j;
        }
      });
  for (Index i = 0; i < n; ++i)
    if (row_entry[i] > 0 && row_difference[i] / row_entry[i] > result.max_row_relative) {
      result.max_row_relative = row_difference[i] / row_entry[i];
      result.worst_row = i;
    }
  return result;
}

inline JacobianCheck check_jacobian(SystemOperator& op, double t, double c_j,
                                    const std::vector<double>& y, const std::vector<double>& yp,
                                    double step) {
  return check_jacobian(op, t, c_j, y, yp, std::vector<double>(y.size(), step));
}

// The drift of an initial state along its derivative: max_{k < n_rows} |F(t, y + d y', y')_k|.
// For a consistent (y, y') of a system whose first n_rows rows are algebraic it is O(d^2): the
// initial-state tests assert the ratio at d and d/2 near 4.
inline double drift_along_derivative(SystemOperator& op, double t, const std::vector<double>& y,
                                     const std::vector<double>& yp, Index n_rows, double d) {
  std::vector<double> moved(y), r(y.size());
  for (std::size_t k = 0; k < y.size(); ++k) moved[k] += d * yp[k];
  op.residual(t, moved, yp, r);
  double m = 0;
  for (Index k = 0; k < n_rows; ++k) m = std::max(m, std::abs(r[k]));
  return m;
}

}  // namespace rfmems::test_support

// Scaled sparse LU solve of the Stokes system: see stokes_solve.hpp.
#include "physics/gas/stokes/stokes_solve.hpp"

#include "solvers/klu_factorization.hpp"

namespace rfmems {

std::vector<Real> solve_stokes(const StokesOperator& op) {
  const CsrPattern& pattern = op.pattern();
  const auto &rows = op.row_scale(), &columns = op.column_scale();
  std::vector<Real> values(op.values()), x(op.rhs());
  for (Index r = 0; r < pattern.n_rows(); ++r) {
    for (Index k = pattern.row_ptr[r]; k < pattern.row_ptr[r + 1]; ++k)
      values[k] *= rows[r] * columns[pattern.col_idx[k]];
    x[r] *= rows[r];
  }
  KluFactorization lu(pattern, values, KluOrdering::NestedDissection);
  lu.solve(x);
  for (Index k = 0; k < op.size(); ++k) x[k] *= columns[k];
  return x;
}

}  // namespace rfmems

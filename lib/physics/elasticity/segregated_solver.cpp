#include "physics/elasticity/segregated_solver.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "solvers/klu_factorization.hpp"

namespace rfmems {

namespace {
// Infinity norm that propagates NaN (std::max would silently drop it).
Real max_abs(const std::vector<Real>& v) {
  Real m = 0;
  for (Real x : v) {
    if (std::isnan(x)) return x;
    m = std::max(m, std::abs(x));
  }
  return m;
}
}  // namespace

SegregatedStats solve_segregated(ElasticityOperator& op, Real t, std::vector<Real>& u,
                                 const SegregatedOptions& options) {
  const int dim = op.dim();
  const Index nc = op.mesh().n_cells();
  const LinearElastic& m = op.material();
  const Real kappa =
      options.diffusivity == SegregatedOptions::Diffusivity::Mu ? m.mu() : 2 * m.mu() + m.lambda();
  std::vector<std::unique_ptr<KluFactorization>> factors;
  for (int k = 0; k < dim; ++k) {
    CsrPattern pattern;
    std::vector<Real> values;
    op.primary_matrix(k, kappa, pattern, values);
    factors.push_back(std::make_unique<KluFactorization>(pattern, values));
  }

  SegregatedStats stats;
  std::vector<Real> r(op.size()), rhs(nc);
  op.internal_residual(t, u, r);
  stats.initial_residual = stats.final_residual = max_abs(r);
  if (stats.initial_residual == 0) {
    stats.converged = true;
    return stats;
  }
  while (stats.outer_iterations < options.max_outer_iterations) {
    for (int k = 0; k < dim; ++k) {
      for (Index c = 0; c < nc; ++c) rhs[c] = -options.relaxation * r[c * dim + k];
      factors[k]->solve(rhs);
      for (Index c = 0; c < nc; ++c) u[c * dim + k] += rhs[c];
    }
    ++stats.outer_iterations;
    op.internal_residual(t, u, r);
    stats.final_residual = max_abs(r);
    if (!std::isfinite(stats.final_residual)) break;
    if (stats.final_residual <= options.relative_tolerance * stats.initial_residual) {
      stats.converged = true;
      break;
    }
  }
  return stats;
}

}  // namespace rfmems

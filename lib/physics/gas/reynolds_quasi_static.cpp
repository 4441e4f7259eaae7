// Quasi-static film pressure by Newton's method: see reynolds_quasi_static.hpp.
#include "physics/gas/reynolds_quasi_static.hpp"

#include "solvers/klu_factorization.hpp"

namespace rfmems {

std::vector<Real> quasi_static_pressure(const ReynoldsFilm& film, std::span<const Real> gap,
                                        std::span<const Real> gap_rate, int newton_iterations) {
  const Index n = film.size();
  std::vector<Real> p(n, film.gas().ambient_pressure), zero(n, 0.0), r(n);
  std::vector<Real> values(film.cell_pattern().nnz());
  for (int it = 0; it < newton_iterations; ++it) {
    film.residual(p, zero, gap, gap_rate, r);
    film.pressure_jacobian(0.0, p, zero, gap, gap_rate, values);
    KluFactorization lu(film.cell_pattern(), values);
    lu.solve(r);
    for (Index c = 0; c < n; ++c) p[c] -= r[c];
  }
  return p;
}

}  // namespace rfmems

#include "physics/gas/kinetic/sequential_solver.hpp"

#include <chrono>
#include <cmath>

#include "physics/gas/kinetic/downwind_ordering.hpp"
#include "solvers/convergence_forecast.hpp"

namespace rfmems {

void downwind_sweep(const KineticOperator& op, const std::vector<DownwindGroup>& groups,
                    std::span<Real> f, Real b, std::span<const Real> h) {
  const FaceGraph& g = op.graph();
  const VelocityGrid& grid = op.grid();
  const Index N = op.n_ordinates();
  std::vector<Real> numerator, denominator;
  for (const DownwindGroup& group : groups) {
    const std::size_t m = group.ordinates.size();
    numerator.resize(m);
    denominator.resize(m);
    for (const Index c : group.cells) {
      if (c >= op.n_owned_cells()) continue;  // ghosts come from their owners
      const Real vnu = g.cell_volume[c] * op.collision_frequency(c);
      const std::span<const Real> feq = op.equilibrium(c);
      const Real bv = b * g.cell_volume[c];
      for (std::size_t j = 0; j < m; ++j) {
        const Index k = group.ordinates[j];
        numerator[j] = vnu * feq[k] + (bv != 0 ? bv * h[c * N + k] : 0.0);
        denominator[j] = vnu + bv;
      }
      if (op.has_body_force()) {  // + V s_ck (kinetic_operator.hpp), lagged with f_eq
        const Vec3 a = op.body_force_gradient(c);
        const Vec3& u = op.macro(c).u;
        for (std::size_t j = 0; j < m; ++j) {
          const Index k = group.ordinates[j];
          numerator[j] += g.cell_volume[c] * a.dot(grid.c[k] - u) * feq[k];
        }
      }
      for (Index i = g.cell_face_offsets[c]; i < g.cell_face_offsets[c + 1]; ++i) {
        const Index face = g.cell_faces[i];
        const bool owner = g.face_owner[face] == c;
        const Vec3 S = owner ? g.face_area[face] : Vec3(-g.face_area[face]);
        const Real* upwind =
            g.is_boundary(face)
                ? op.boundary_values(face).data()
                : f.data() + (owner ? g.face_neighbour[face] : g.face_owner[face]) * N;
        // A periodic face whose partner face is the cell's own (a channel one cell long):
        // the inflow is the cell's own outflow, taken implicitly (else the lag converges
        // slowly for ordinates nearly along the channel), with the lagged difference of the
        // cached face value from the cell value on the right (second order: nonzero).
        const Index partner = op.periodic_partner(face);
        const bool self = partner >= 0 && g.face_owner[partner] == c;
        const Real* old = f.data() + c * N;
        for (std::size_t j = 0; j < m; ++j) {
          const Index k = group.ordinates[j];
          const Real d = grid.c[k].dot(S);
          if (d > 0) {
            denominator[j] += d;
          } else if (self) {
            denominator[j] += d;
            numerator[j] -= d * (upwind[k] - old[k]);
          } else {
            numerator[j] -= d * upwind[k];
          }
        }
      }
      // Second-order transport: the lagged correction D = F_2 - F_1 on the right-hand side.
      const std::span<const Real> correction = op.transport_correction(c);
      if (!correction.empty())
        for (std::size_t j = 0; j < m; ++j) numerator[j] -= correction[group.ordinates[j]];
      Real* fc = f.data() + c * N;
      for (std::size_t j = 0; j < m; ++j) fc[group.ordinates[j]] = numerator[j] / denominator[j];
    }
  }
}

KineticSolveResult solve_sequential(KineticOperator& op, std::span<Real> f,
                                    const SequentialOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<DownwindGroup> groups = downwind_groups(op.graph(), op.grid());
  std::vector<Real> r(op.size());
  KineticSolveResult result;
  op.exchange_ghosts(f);
  op.residual(f, r);  // also refreshes the lagged collision and boundary values
  result.initial_residual = op.global_norm(r);
  result.final_residual = result.initial_residual;
  result.residual_ratio = 1;
  if (result.initial_residual == 0) result.converged = true;
  const bool closed = op.is_closed();
  const Real mass = op.total_mass(f);
  while (!result.converged && result.iterations < options.max_iterations) {
    downwind_sweep(op, groups, f);
    if (closed) op.restore_mass(f, mass);
    op.exchange_ghosts(f);  // ranks: block Jacobi between partitions, Gauss-Seidel within
    op.residual(f, r);
    ++result.iterations;
    result.final_residual = op.global_norm(r);
    result.residual_ratio = result.final_residual / result.initial_residual;
    result.history.push_back(result.residual_ratio);
    result.converged = result.residual_ratio <= options.tolerance;
    if (!std::isfinite(result.residual_ratio)) break;
    if (!result.converged && options.stop_when_hopeless) {
      result.stop_reason = ConvergenceForecast::hopeless(
          result.history, options.tolerance, options.max_iterations, "the sequential solver");
      if (!result.stop_reason.empty()) break;
    }
    if (options.monitor && !options.monitor(result.iterations, result.residual_ratio)) break;
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace rfmems

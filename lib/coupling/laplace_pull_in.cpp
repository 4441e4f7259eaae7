#include "coupling/laplace_pull_in.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"
#include "coupling/displacement_control_fixed_point.hpp"
#include "coupling/laplace_gap_field.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

LaplacePullIn trace_pull_in_laplace(ElasticityScene& beam, const std::string& bottom_patch,
                                    Real gap, const ElectrodeExtent& electrode, Index control,
                                    const LaplacePullInOptions& options) {
  LaplaceGapOptions gap_options;
  gap_options.gap_cells = options.gap_cells;
  gap_options.motion = options.motion;
  LaplaceGapField field(*beam.op, bottom_patch, gap, electrode, gap_options);

  // One factorisation of the (linear) beam stiffness.
  ElasticityOperator& op = *beam.op;
  const Index n = op.size();
  std::vector<Real> k_values(op.stiffness_pattern().nnz()), zero(n, 0.0);
  op.stiffness(0.0, zero, k_values);
  KluFactorization stiffness(op.stiffness_pattern(), k_values);

  LaplacePullIn out;
  out.gap_cells_total = field.gap_cells_total();
  // Force per V^2 on the beam's unknowns at displacement u (moves the gap mesh).
  auto load_per_volt2 = [&](std::span<const Real> u) { return field.load_per_volt2(u); };

  // Equilibrium at delta from a solved state: Aitken-relaxed fixed point (see the header).
  auto solve = [&](Real delta, const FoldSample& from) {
    FoldSample s{{}, from.state};
    if (from.point.displacement != 0)
      for (Real& v : s.state) v *= delta / from.point.displacement;
    std::vector<Real>& u = s.state;
    const DisplacementControlResult r = relax_displacement_control(
        stiffness, load_per_volt2, LinearFunctional::unknown(control), delta,
        options.coupling_tolerance, options.max_coupling_iterations, u);
    const Real lambda = r.voltage_squared;
    const int it = r.iterations;
    if (!r.converged)
      throw SolverError(
          fmt::format("Laplace pull-in: coupling not converged at delta = {:.4e} m "
                      "after {} iterations",
                      delta, it));
    if (lambda < 0)
      throw SolverError(fmt::format("Laplace pull-in: negative V^2 at delta = {:.4e} m", delta));
    s.point = {delta, std::sqrt(lambda), field.last_min_gap(), true, it + 1};
    return s;
  };
  FoldSample rest{{0.0, 0.0, gap, true, 0}, std::vector<Real>(n, 0.0)};
  out.result = trace_fold(solve, rest, gap, options.sampling);
  out.coupling_iterations = field.solves();
  out.result.solves = out.coupling_iterations;
  return out;
}

}  // namespace rfmems

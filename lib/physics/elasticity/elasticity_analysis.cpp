// The static and transient analyses of an ElasticityScene (see the header for the keys).
#include "physics/elasticity/elasticity_analysis.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "core/structural_systems.hpp"
#include "solvers/static_solve.hpp"

namespace rfmems {

namespace {

// Largest edge of the mesh's bounding box: the length scale of the default atol.
Real mesh_extent(const Mesh& mesh) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::infinity()), hi = -lo;
  for (const Vec3& x : mesh.nodes()) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return mesh.n_nodes() > 0 ? (hi - lo).maxCoeff() : 1.0;
}

AnalysisStats run_static(ElasticityScene& scene, const AnalysisSettings& settings,
                         AnalysisObserver& observer) {
  AnalysisStats stats;
  stats.type = AnalysisType::Static;
  stats.stress = scene.stress;
  const Real t = scene.load_time;
  std::vector<Real> u(scene.op->size(), 0.0);
  if (scene.stress == StressMethod::Coupled) {
    KinsolOptions options;
    options.relative_tolerance = settings.tolerance;
    options.max_iterations = static_cast<int>(settings.max_iterations);
    StaticSolution solution = solve_static(*scene.op, t, options);
    u = std::move(solution.y);
    stats.newton = solution.stats;
  } else {
    SegregatedOptions options = scene.segregated;
    options.relative_tolerance = settings.tolerance;
    options.max_outer_iterations = static_cast<int>(settings.max_iterations);
    stats.segregated = solve_segregated(*scene.op, t, u, options);
    if (!stats.segregated.converged)
      throw SolverError(fmt::format(
          "segregated solver: no convergence after {} outer iterations (residual {:.3e} -> "
          "{:.3e}, wanted a reduction to {:g}); raise solver.max_iterations or lower "
          "solver.segregated.relaxation",
          stats.segregated.outer_iterations, stats.segregated.initial_residual,
          stats.segregated.final_residual, settings.tolerance));
  }
  observer.output(0, t, u, {});
  stats.n_outputs = 1;
  stats.final_time = t;
  return stats;
}

AnalysisStats run_transient(ElasticityScene& scene, const AnalysisSettings& settings,
                            AnalysisObserver& observer, ProgressReporter& progress) {
  AnalysisStats stats;
  stats.type = AnalysisType::Transient;
  stats.stress = scene.stress;
  ElasticityOperator& op = *scene.op;
  const Index n = op.size();

  // From rest; the acceleration balances whatever load acts at t = 0.
  std::vector<Real> y(2 * n, 0.0), yp(2 * n, 0.0), r(n);
  op.internal_residual(0.0, std::span<const Real>(y).subspan(0, n), r);
  const std::vector<Real> mass = op.mass_diagonal();
  for (Index i = 0; i < n; ++i) yp[n + i] = -r[i] / mass[i];

  FirstOrderSystem system(op);
  IdaIntegrator ida(system, settings.ida);
  ida.initialize(0.0, y, yp);
  auto emit = [&](int index, Real t) {
    const auto state = ida.y();
    observer.output(index, t, state.subspan(0, n), state.subspan(n, n));
  };
  emit(0, 0.0);

  // k dt up to end_time; a last, shorter interval if end_time is not a multiple of dt.
  const Real dt = settings.output_interval, t_end = settings.end_time;
  const long n_intervals = std::max(1L, static_cast<long>(std::ceil(t_end / dt - 1e-9)));
  for (long k = 1; k <= n_intervals; ++k) {
    const Real t = k == n_intervals ? t_end : static_cast<Real>(k) * dt;
    ida.advance(t);
    emit(static_cast<int>(k), t);
    const IntegratorStats s = ida.stats();
    progress.update(t, s.last_step, s.steps);
  }
  stats.transient = ida.stats();
  stats.n_outputs = static_cast<int>(n_intervals) + 1;
  stats.final_time = t_end;
  return stats;
}

}  // namespace

AnalysisType read_analysis_type(const CaseNode& root) {
  const std::string type =
      root.child("analysis").get_choice("type", {"static", "transient"});
  return type == "static" ? AnalysisType::Static : AnalysisType::Transient;
}

AnalysisSettings read_analysis_settings(const CaseNode& root, const ElasticityScene& scene) {
  AnalysisSettings s;
  s.type = read_analysis_type(root);
  const CaseNode analysis = root.child("analysis");
  const CaseNode solver = root.child_or_empty("solver");
  if (s.type == AnalysisType::Static) {
    const bool coupled = scene.stress == StressMethod::Coupled;
    s.tolerance = solver.get_real("tolerance", 1e-6, Range::open(0.0, 1.0));
    s.max_iterations = solver.get_int("max_iterations", coupled ? 50 : 100000,
                                      Range::closed(1, 1e9));
    return s;
  }
  s.end_time = analysis.get_quantity("end_time", Dimension::Time, Range::positive());
  s.output_interval =
      analysis.get_quantity("output_interval", Dimension::Time, Range::positive());
  analysis.require(s.output_interval <= s.end_time, "output_interval",
                   "must not exceed analysis.end_time");
  analysis.require(s.end_time / s.output_interval <= 1e6, "output_interval",
                   "more than a million outputs; choose a longer interval");
  s.ida.rtol = solver.get_real("rtol", 1e-6, Range::open(0.0, 1.0));
  // Small-strain displacements are up to ~1e-4 of the body's size: allow rtol of that.
  s.ida.atol = solver.get_quantity("atol", Dimension::Length,
                                   s.ida.rtol * 1e-4 * mesh_extent(*scene.mesh), Range::positive());
  // BDF3-5 are not A-stable: on undamped elastodynamics (eigenvalues on the imaginary axis)
  // IDA collapses its step at those orders, so structural transients default to 2.
  s.ida.max_order = static_cast<int>(solver.get_int("max_order", 2, Range::closed(1, 5)));
  s.ida.fixed_step =
      solver.get_quantity("fixed_step", Dimension::Time, 0.0, Range::non_negative());
  return s;
}

AnalysisStats run_analysis(ElasticityScene& scene, const AnalysisSettings& settings,
                           AnalysisObserver& observer, ProgressReporter& progress) {
  return settings.type == AnalysisType::Static ? run_static(scene, settings, observer)
                                               : run_transient(scene, settings, observer, progress);
}

}  // namespace rfmems

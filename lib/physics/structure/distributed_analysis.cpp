#include "physics/structure/distributed_analysis.hpp"

#include <memory>

#include "core/error.hpp"
#include "parallel/distributed_structural_systems.hpp"
#include "parallel/single_rank_operator.hpp"
#include "physics/elasticity/distributed_elasticity.hpp"
#include "physics/plate/distributed_plate.hpp"
#include "physics/plate/von_karman_plate.hpp"
#include "physics/structure/output_schedule.hpp"
#include "solvers/distributed_ida_integrator.hpp"
#include "solvers/distributed_static_solve.hpp"

namespace rfmems {

namespace {

// The reason this model or analysis cannot run on distributed vectors, or empty.
std::string why_not_distributable(StructuralModel& model, const AnalysisSettings& settings) {
  const bool continuum = dynamic_cast<const ElasticityOperator*>(&model.structure()) != nullptr;
  const bool plate = dynamic_cast<const PlateOperator*>(&model.structure()) != nullptr;
  if (dynamic_cast<const VonKarmanPlate*>(&model.structure()))
    return "does not support model.geometric_nonlinearity (the von Karman plate is solved on one "
           "rank with KLU)";
  if (settings.type == AnalysisType::Modal || settings.type == AnalysisType::Harmonic)
    return "is for static and transient analyses; modal and harmonic analyses are solved on "
           "one rank with a direct factorisation";
  if (!continuum && !(plate && settings.type == AnalysisType::Static))
    return "is for the continuum (model.structure plane or solid3d) and for static plates; a "
           "plate transient is solved on one rank with KLU";
  if (model.static_method() != "newton" && settings.type != AnalysisType::Transient)
    return "needs model.stress coupled (the segregated method is serial)";
  if (settings.ida.fixed_step != 0) return "does not support solver.fixed_step";
  return {};
}

}  // namespace

void settle_linear_solver(StructuralModel& model, AnalysisSettings& settings,
                          const CaseNode& root) {
  using Linear = AnalysisSettings::Linear;
  const CaseNode solver = root.child_or_empty("solver");
  const std::string why = why_not_distributable(model, settings);
  if (settings.linear == Linear::Auto)
    settings.linear = why.empty() && settings.type == AnalysisType::Static &&
                              model.structure_mesh().dim() == 3 &&
                              dynamic_cast<const ElasticityOperator*>(&model.structure()) &&
                              model.structure().size() > kMultigridUnknowns
                          ? Linear::Multigrid
                          : Linear::Direct;
  if (settings.linear == Linear::Multigrid && !why.empty()) solver.fail("linear", why);
  if (settings.distributed && !why.empty()) solver.fail("distributed", why);
}

bool on_distributed_vectors(const AnalysisSettings& settings) {
  return settings.distributed || settings.linear == AnalysisSettings::Linear::Multigrid;
}

namespace {

DistributedLinearization::Family family_of(const AnalysisSettings& settings) {
  return settings.linear == AnalysisSettings::Linear::Multigrid
             ? DistributedLinearization::Family::Multigrid
             : DistributedLinearization::Family::Schwarz;
}

AnalysisStats run_static(StructuralModel& model, const AnalysisSettings& settings,
                         DistributedSecondOrderOperator& op, AnalysisObserver& observer) {
  AnalysisStats stats;
  stats.type = AnalysisType::Static;
  stats.static_method = "newton";
  const Real t = model.ramp_end_time();
  DistributedNewtonOptions options;
  options.preconditioner = family_of(settings);
  options.relative_tolerance = settings.tolerance;
  if (settings.linear == AnalysisSettings::Linear::Multigrid) {
    // GMRES to a tenth of the Newton tolerance: a linear structure still converges in one
    // Newton step, without the iterations a reduction to round-off costs (a V-cycle each).
    options.linear_tolerance = 0.1 * settings.tolerance;
    options.krylov_dimension = 150;
    options.classical_gram_schmidt = true;
  }
  options.max_iterations = static_cast<int>(settings.max_iterations);
  const DistributedStaticSolution solution = solve_static_distributed(op, t, options);
  stats.newton = solution.stats;
  stats.multigrid_levels = solution.multigrid.levels;
  stats.multigrid_complexity = solution.multigrid.operator_complexity;
  const std::vector<Real> u = op.gather_to_root(solution.y);
  if (op.communicator().is_root()) observer.output(0, t, u, {});
  stats.n_outputs = 1;
  stats.final_time = t;
  return stats;
}

AnalysisStats run_transient(const AnalysisSettings& settings, DistributedSecondOrderOperator& op,
                            AnalysisObserver& observer, ProgressReporter& progress) {
  AnalysisStats stats;
  stats.type = AnalysisType::Transient;
  const bool root = op.communicator().is_root();
  const Index n = op.owned_size();
  DistributedFirstOrderSystem system(op);
  // From rest; the acceleration balances whatever load acts at t = 0 (as the serial run).
  std::vector<Real> y(system.owned_size(), 0.0), yp(system.owned_size(), 0.0), r(n);
  op.internal_residual(0.0, std::span<const Real>(y).subspan(0, n), r);
  const std::vector<Real> mass = op.mass_diagonal();
  for (Index i = 0; i < n; ++i) yp[n + i] = -r[i] / mass[i];

  DistributedIdaIntegrator ida(system, settings.ida, family_of(settings));
  ida.initialize(0.0, y, yp);
  auto emit = [&](int index, Real t) {
    const auto state = ida.y();
    const std::vector<Real> u = op.gather_to_root(state.subspan(0, n));
    const std::vector<Real> v = op.gather_to_root(state.subspan(n, n));
    if (root) observer.output(index, t, u, v);
  };
  emit(0, 0.0);
  const Real dt = settings.output_interval, t_end = settings.end_time;
  const long n_intervals =
      advance_through_outputs(ida, dt, t_end, emit, [&](Real t, const IntegratorStats& s) {
        if (root) progress.update(t, s.last_step, s.steps);
      });
  stats.transient = ida.stats();
  stats.n_outputs = static_cast<int>(n_intervals) + 1;
  stats.final_time = t_end;
  return stats;
}

}  // namespace

AnalysisStats run_distributed_analysis(StructuralModel& model, const AnalysisSettings& settings,
                                       const Communicator& comm, AnalysisObserver& observer,
                                       ProgressReporter& progress) {
  std::unique_ptr<DistributedSecondOrderOperator> op;
  auto* elasticity = dynamic_cast<ElasticityOperator*>(&model.structure());
  auto* plate = dynamic_cast<PlateOperator*>(&model.structure());
  if (!elasticity && !plate)
    throw SolverError("distributed analysis: neither a continuum nor a plate");
  // One rank: the operator itself; with multigrid on a continuum of higher degree,
  // matrix-free with the linear reconstruction's operator as the preconditioner's matrix.
  std::unique_ptr<ElasticityOperator> compact;
  if (comm.is_serial() && elasticity && elasticity->dim() == 3 &&
      elasticity->requested_reconstruction_degree() != 1 && elasticity->has_stiffness_product() &&
      settings.linear == AnalysisSettings::Linear::Multigrid &&
      settings.type == AnalysisType::Static) {
    compact =
        std::make_unique<ElasticityOperator>(elasticity->mesh(), elasticity->material(),
                                             elasticity->boundaries(), elasticity->body_force(), 1);
  }
  if (comm.is_serial())
    op = std::make_unique<SingleRankOperator>(
        model.structure(),
        static_cast<int>(model.structure().size() / model.structure_mesh().n_cells()),
        compact.get());
  else if (elasticity)
    op = std::make_unique<DistributedElasticity>(*elasticity, comm);
  else
    op = std::make_unique<DistributedPlate>(*plate, comm);
  AnalysisStats stats = settings.type == AnalysisType::Static
                            ? run_static(model, settings, *op, observer)
                            : run_transient(settings, *op, observer, progress);
  stats.distributed_ranks = comm.size();
  stats.linear_solver =
      settings.linear == AnalysisSettings::Linear::Multigrid ? "multigrid" : "klu_subdomains";
  return stats;
}

}  // namespace rfmems

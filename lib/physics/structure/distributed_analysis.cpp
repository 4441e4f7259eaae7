#include "physics/structure/distributed_analysis.hpp"

#include <memory>

#include "core/error.hpp"
#include "parallel/distributed_structural_systems.hpp"
#include "physics/elasticity/distributed_elasticity.hpp"
#include "physics/plate/distributed_plate.hpp"
#include "physics/plate/von_karman_plate.hpp"
#include "physics/structure/output_schedule.hpp"
#include "solvers/distributed_ida_integrator.hpp"
#include "solvers/distributed_static_solve.hpp"

namespace rfmems {

void check_distributable(StructuralModel& model, const AnalysisSettings& settings,
                         const CaseNode& root) {
  const CaseNode solver = root.child_or_empty("solver");
  const bool continuum = dynamic_cast<const ElasticityOperator*>(&model.structure()) != nullptr;
  const bool plate = dynamic_cast<const PlateOperator*>(&model.structure()) != nullptr;
  solver.require(dynamic_cast<const VonKarmanPlate*>(&model.structure()) == nullptr, "distributed",
                 "does not support model.geometric_nonlinearity (the von Karman plate is solved on "
                 "one rank)");
  solver.require(settings.type != AnalysisType::Modal && settings.type != AnalysisType::Harmonic,
                 "distributed",
                 "is for static and transient analyses; modal and harmonic analyses are solved on "
                 "one rank");
  solver.require(continuum || (plate && settings.type == AnalysisType::Static), "distributed",
                 "is for the continuum (model.structure plane or solid3d) and for static plates; "
                 "a plate transient is solved on one rank");
  solver.require(model.static_method() == "newton" || settings.type == AnalysisType::Transient,
                 "distributed", "needs model.stress coupled (the segregated method is serial)");
  solver.require(settings.ida.fixed_step == 0, "distributed", "does not support solver.fixed_step");
}

namespace {

AnalysisStats run_static(StructuralModel& model, const AnalysisSettings& settings,
                         DistributedSecondOrderOperator& op, AnalysisObserver& observer) {
  AnalysisStats stats;
  stats.type = AnalysisType::Static;
  stats.static_method = "newton";
  const Real t = model.ramp_end_time();
  DistributedNewtonOptions options;
  options.relative_tolerance = settings.tolerance;
  options.max_iterations = static_cast<int>(settings.max_iterations);
  const DistributedStaticSolution solution = solve_static_distributed(op, t, options);
  stats.newton = solution.stats;
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

  DistributedIdaIntegrator ida(system, settings.ida);
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
  std::unique_ptr<DistributedLocalOperator> op;
  if (auto* elasticity = dynamic_cast<ElasticityOperator*>(&model.structure()))
    op = std::make_unique<DistributedElasticity>(*elasticity, comm);
  else if (auto* plate = dynamic_cast<PlateOperator*>(&model.structure()))
    op = std::make_unique<DistributedPlate>(*plate, comm);
  else
    throw SolverError("distributed analysis: neither a continuum nor a plate");
  AnalysisStats stats = settings.type == AnalysisType::Static
                            ? run_static(model, settings, *op, observer)
                            : run_transient(settings, *op, observer, progress);
  stats.distributed_ranks = comm.size();
  return stats;
}

}  // namespace rfmems

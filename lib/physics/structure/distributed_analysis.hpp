// The static and transient analyses of structural_analysis.hpp with the structure
// distributed over the ranks (case key solver.distributed: true): the continuum's
// FV elasticity operator on METIS parts (physics/elasticity/distributed_elasticity.hpp),
// Newton (KINSOL) or IDA on SUNDIALS' MPI parallel N_Vector, GMRES preconditioned by KLU on
// the rank-local blocks (restricted additive Schwarz on the ghost overlap; transients on the
// Schur complement K + c_j^2 M; lib/solvers/distributed_*). Every output is gathered on the root,
// which alone receives it (the result file is the serial run's, from rank 0).
//
// Supported: plane and 3D continua with the coupled stress method (static and transient),
// the plate's static solve (physics/plate/distributed_plate.hpp); the plate's transient and
// the segregated method stay serial (InputError naming solver.distributed). Static: the serial
// convergence test (solver.tolerance on ||R||/||R0||), one Newton step for the linear
// structure. Transient: the serial IDA settings (rtol, atol, max_order); fixed_step is not
// supported distributed.
#pragma once
#include "parallel/communicator.hpp"
#include "physics/structure/structural_analysis.hpp"

namespace rfmems {

// solver.linear auto solves a 3D continuum's static problem with multigrid above this many
// unknowns, where GMRES with BoomerAMG overtakes KLU (the 3D box: equal at 1920 unknowns, 1.6x
// faster at 6480, 6.1x at 15360, in CPU; docs/scale.md). Plane and plate structures stay direct:
// on slender plane beams the cycle is weak and KLU the faster (docs/scale.md).
inline constexpr Index kMultigridUnknowns = 5000;

// Settles solver.linear (auto becomes direct or multigrid) and checks that the model and the
// analysis can run on distributed vectors where solver.distributed or multigrid asks for them:
// InputError naming the key if not (auto falls back to direct instead). Cheap; call before any
// solving, on every rank.
void settle_linear_solver(StructuralModel& model, AnalysisSettings& settings, const CaseNode& root);
// After settle_linear_solver: whether the run goes through run_distributed_analysis.
bool on_distributed_vectors(const AnalysisSettings& settings);

// Collective (over `comm`: the world when distributed, one rank for multigrid alone), with
// KLU on the parts or multigrid as settings.linear says. `observer` (and `progress`) are
// used on the root only; other ranks may pass
// any observer, it is never called there. The statistics are the distributed solvers'
// (Newton: linear_iters = GMRES iterations; transient: linear_iters, preconditioner_setups).
AnalysisStats run_distributed_analysis(StructuralModel& model, const AnalysisSettings& settings,
                                       const Communicator& comm, AnalysisObserver& observer,
                                       ProgressReporter& progress);

}  // namespace rfmems

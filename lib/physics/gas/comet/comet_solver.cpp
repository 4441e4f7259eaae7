#include "physics/gas/comet/comet_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "parallel/communication_counters.hpp"
#include "physics/gas/comet/fas_transfer.hpp"
#include "physics/gas/kinetic/sequential_solver.hpp"
#include "solvers/convergence_forecast.hpp"

namespace rfmems {

struct CometSolver::Level {
  const FaceGraph* graph = nullptr;
  std::unique_ptr<KineticOperator> own_operator;  // coarse levels
  KineticOperator* op = nullptr;
  std::unique_ptr<PointCoupledSmoother> smoother;
  std::vector<Real> f;           // coarse levels: the level's state
  std::vector<Real> source;      // FAS source (empty on the fine level: 0)
  std::vector<Real> residual;    // s - A(f)
  std::vector<Real> restricted;  // R f of the finer level, kept for the correction
  bool collision_current = false;
  long passes = 0;
  double seconds = 0;
};

CometSolver::CometSolver(KineticOperator& fine, const CometOptions& options)
    : fine_(fine), options_(options) {
  if (options.pre_sweeps < 0 || options.post_sweeps < 0 || options.coarsest_sweeps < 1 ||
      options.pre_sweeps + options.post_sweeps < 1)
    throw InputError("COMET: sweep counts must be >= 0 (pre, post, their sum >= 1; coarsest >= 1)");
  if (!(options.tolerance > 0)) throw InputError("COMET: tolerance must be > 0");
  if (options.multigrid)
    hierarchy_ =
        agglomeration_hierarchy(fine.graph(), std::max<Index>(options.min_coarse_cells, 1),
                                options.max_levels, fine.communicator(), fine.ghost_exchange());
  auto fine_level = std::make_unique<Level>();
  fine_level->graph = &fine.graph();
  fine_level->op = &fine;
  levels_.push_back(std::move(fine_level));
  for (const Agglomeration& a : hierarchy_) {
    auto level = std::make_unique<Level>();
    level->graph = &a.coarse;
    level->own_operator =
        std::make_unique<KineticOperator>(a.coarse, fine.grid(), fine.gas(), fine.boundaries());
    level->op = level->own_operator.get();
    if (fine.ghost_exchange()) level->op->set_parallel(fine.communicator(), &a.coarse_exchange);
    const Index size = level->op->size();
    level->f.resize(size);
    level->source.resize(size);
    level->restricted.resize(size);
    levels_.push_back(std::move(level));
  }
  for (auto& level : levels_) {
    level->smoother = std::make_unique<PointCoupledSmoother>(*level->op, options.coupling,
                                                             options.cell_newton_iterations);
    level->residual.resize(level->op->size());
  }
}

CometSolver::~CometSolver() = default;

const FaceGraph& CometSolver::level_graph(int level) const { return *levels_.at(level)->graph; }
KineticOperator& CometSolver::level_operator(int level) { return *levels_.at(level)->op; }

std::span<Real> CometSolver::level_f(int level) {
  return level == 0 ? fine_f_ : std::span<Real>(levels_[level]->f);
}

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

void CometSolver::residual(int l, std::span<const Real> f, std::span<Real> r) {
  const auto t0 = std::chrono::steady_clock::now();
  levels_[l]->op->residual(f, r);
  levels_[l]->seconds += seconds_since(t0);
}

void CometSolver::smooth(int l, int sweeps, bool post) {
  const auto t0 = std::chrono::steady_clock::now();
  Level& level = *levels_[l];
  const std::span<Real> f = level_f(l);
  if (!level.collision_current) level.op->update_collision(f);
  // Gauss-Seidel within a rank's part, the ghosts refreshed after every pass (the thesis's
  // parallel COMET, step 12): block Jacobi between parts, one exchange per pass.
  // One-pass coarse sweeps: forward before the coarse visit, backward after it (the cycle
  // stays symmetric); alternating on the coarsest level.
  const bool one_pass = !options_.symmetric || (l > 0 && !coarse_symmetric_);
  for (int s = 0; s < sweeps; ++s) {
    const bool forward = !options_.symmetric || !one_pass || (s % 2 == (post ? 1 : 0));
    level.smoother->sweep(f, level.source, forward);
    level.op->exchange_ghosts(f);
    ++level.passes;
    if (!one_pass) {
      level.smoother->sweep(f, level.source, false);
      level.op->exchange_ghosts(f);
      ++level.passes;
    }
  }
  level.collision_current = true;
  level.seconds += seconds_since(t0);
}

CometCycle comet_cycle_from_name(const std::string& name) {
  if (name == "V") return CometCycle::V;
  if (name == "W") return CometCycle::W;
  if (name == "F") return CometCycle::F;
  if (name == "auto") return CometCycle::Auto;
  throw InputError("COMET: cycle '" + name + "' is not V, W, F or auto");
}

const char* comet_cycle_name(CometCycle shape) {
  switch (shape) {
    case CometCycle::V:
      return "V";
    case CometCycle::W:
      return "W";
    case CometCycle::F:
      return "F";
    case CometCycle::Auto:
      return "auto";
  }
  return "?";
}

void CometSolver::cycle(int l, CometCycle shape) {
  if (l + 1 == n_levels()) {
    smooth(l, options_.coarsest_sweeps);
    return;
  }
  Level& fine = *levels_[l];
  Level& coarse = *levels_[l + 1];
  const Agglomeration& agg = hierarchy_[l];
  const Index n = fine.op->n_ordinates();
  smooth(l, options_.pre_sweeps);

  // FAS residual of this level, r = s - A(f).
  const std::span<Real> f = level_f(l);
  residual(l, f, fine.residual);
  fine.collision_current = true;
  if (!fine.source.empty())
    for (std::size_t i = 0; i < fine.residual.size(); ++i)
      fine.residual[i] = fine.source[i] - fine.residual[i];
  else
    for (Real& r : fine.residual) r = -r;

  // Coarse state and FAS source s_c = A_c(R f) + R' r.
  restrict_solution(*fine.graph, agg, n, f, coarse.f);
  coarse.op->exchange_ghosts(coarse.f);  // the coarse residual reads its ghosts
  coarse.restricted = coarse.f;
  residual(l + 1, coarse.f, coarse.residual);
  coarse.collision_current = true;
  restrict_residual(agg, n, fine.residual, coarse.source);
  for (std::size_t i = 0; i < coarse.source.size(); ++i) coarse.source[i] += coarse.residual[i];

  // Coarse visits (the FAS equation of level l + 1 keeps its source between them).
  if (shape == CometCycle::V) {
    cycle(l + 1, CometCycle::V);
  } else if (shape == CometCycle::W) {
    cycle(l + 1, CometCycle::W);
    cycle(l + 1, CometCycle::W);
  } else {
    cycle(l + 1, CometCycle::F);
    cycle(l + 1, CometCycle::V);
  }

  // Correction by injection, damped per fine cell so that f stays positive.
  for (std::size_t i = 0; i < coarse.f.size(); ++i)
    coarse.restricted[i] = coarse.f[i] - coarse.restricted[i];
  const Index nc = fine.graph->n_owned_cells;
  for (Index c = 0; c < nc; ++c) {
    const Real* e = &coarse.restricted[agg.coarse_of_fine[c] * n];
    Real* fc = &f[c * n];
    Real theta = 1.0;
    for (Index k = 0; k < n; ++k)
      if (fc[k] > 0 && fc[k] + e[k] < 0.1 * fc[k]) theta = std::min(theta, 0.9 * fc[k] / -e[k]);
    if (theta < 1.0) ++damped_prolongations_;
    for (Index k = 0; k < n; ++k) fc[k] += theta * e[k];
  }
  fine.op->exchange_ghosts(f);
  fine.collision_current = false;
  smooth(l, options_.post_sweeps, true);
}

Real CometSolver::domain_knudsen(std::span<const Real> f) const {
  const FaceGraph& g = fine_.graph();
  const Index n = fine_.n_ordinates();
  Real volume = 0, mass = 0, thermal = 0;
  for (Index c = 0; c < g.n_owned_cells; ++c) {
    const MacroState m = moments(f.subspan(c * n, n), fine_.grid(), fine_.gas());
    volume += g.cell_volume[c];
    mass += g.cell_volume[c] * m.rho;
    thermal += g.cell_volume[c] * m.T;
  }
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::infinity()), hi = -lo;
  for (const Vec3& x : g.face_centroid) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  // Over every rank's part, so all ranks take the same regime decision.
  const Communicator& comm = fine_.communicator();
  volume = comm.sum(volume);
  mass = comm.sum(mass);
  thermal = comm.sum(thermal);
  Real extent = 0;
  for (int d = 0; d < 3; ++d) extent = std::max(extent, comm.max(hi[d]) - comm.min(lo[d]));
  return fine_.gas().knudsen(mass / volume, thermal / volume, extent);
}

CometResult CometSolver::solve(std::span<Real> f) {
  if (static_cast<Index>(f.size()) != fine_.size())
    throw InputError("COMET: state has the wrong length");
  const auto start = std::chrono::steady_clock::now();
  const Real knudsen = domain_knudsen(f);
  if (options_.sequential_above_knudsen > 0 && knudsen >= options_.sequential_above_knudsen) {
    SequentialOptions so;
    so.tolerance = options_.tolerance;
    so.max_iterations = options_.max_cycles;
    so.monitor = options_.monitor;
    so.stop_when_hopeless = options_.stop_when_hopeless;
    const KineticSolveResult rs = solve_sequential(fine_, f, so);
    CometResult r;
    r.method = "sequential";
    r.knudsen = knudsen;
    r.converged = rs.converged;
    r.cycles = rs.iterations;
    r.initial_residual = rs.initial_residual;
    r.residual_ratio = rs.residual_ratio;
    r.history = rs.history;
    r.stop_reason = rs.stop_reason;
    r.level_cells = {fine_.communicator().sum(fine_.graph().n_owned_cells)};
    r.mass_rescaled = fine_.is_closed();
    r.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }
  fine_f_ = f;
  fine_.exchange_ghosts(f);
  const CommunicationCounters sent0 = communication_counters();
  for (auto& level : levels_) {
    level->passes = 0;
    level->seconds = 0;
    level->collision_current = false;
  }
  damped_prolongations_ = 0;
  long updates0 = 0, damped0 = 0;
  for (auto& level : levels_) {
    updates0 += level->smoother->cell_updates();
    damped0 += level->smoother->damped_steps();
  }
  const bool rescale = options_.conserve_mass && fine_.is_closed();
  const Real mass0 = fine_.total_mass(f);

  // The cycle by regime (header): near continuum F-cycles with one-pass coarse sweeps.
  CometCycle shape = options_.cycle_shape;
  coarse_symmetric_ = options_.coarse_symmetric;
  if (shape == CometCycle::Auto) {
    const bool dense = knudsen < options_.f_cycle_below_knudsen;
    shape = dense ? CometCycle::F : CometCycle::V;
    coarse_symmetric_ = !dense;
  }
  CometResult result;
  result.cycle_shape = shape;
  result.coarse_symmetric = coarse_symmetric_;
  result.knudsen = knudsen;
  result.levels = n_levels();
  result.mass_rescaled = rescale;
  const Communicator& comm = fine_.communicator();
  for (auto& level : levels_) result.level_cells.push_back(comm.sum(level->graph->n_owned_cells));
  result.initial_residual = fine_.residual_norm(f);
  levels_[0]->collision_current = true;
  Real ratio = 1.0;
  if (result.initial_residual == 0.0) {
    result.converged = true;
  } else {
    for (int it = 0; it < options_.max_cycles; ++it) {
      if (options_.multigrid && n_levels() > 1) {
        cycle(0, shape);
      } else {
        smooth(0, options_.pre_sweeps + options_.post_sweeps);
      }
      ++result.cycles;
      if (rescale) fine_.restore_mass(f, mass0);
      ratio = fine_.residual_norm(f) / result.initial_residual;
      levels_[0]->collision_current = true;
      if (!std::isfinite(ratio)) throw SolverError("COMET: residual is not finite");
      result.history.push_back(ratio);
      if (ratio <= options_.tolerance) {
        result.converged = true;
        break;
      }
      if (options_.stop_when_hopeless) {
        result.stop_reason = ConvergenceForecast::hopeless(result.history, options_.tolerance,
                                                           options_.max_cycles, "COMET");
        if (!result.stop_reason.empty()) break;
      }
      if (options_.monitor && !options_.monitor(result.cycles, ratio)) break;
    }
  }
  result.residual_ratio = result.converged && result.cycles == 0 ? 0.0 : ratio;
  const Real fine_cells = Real(comm.sum(levels_[0]->graph->n_owned_cells));
  for (auto& level : levels_) {
    result.cell_updates += level->smoother->cell_updates();
    result.damped_steps += level->smoother->damped_steps();
    result.fine_sweep_equivalents +=
        Real(level->passes) * Real(comm.sum(level->graph->n_owned_cells)) / fine_cells;
    result.level_seconds.push_back(level->seconds);
  }
  result.cell_updates = comm.sum(Index(result.cell_updates - updates0));
  result.damped_steps = comm.sum(Index(result.damped_steps + damped_prolongations_ - damped0));
  result.communication = communication_counters() - sent0;
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace rfmems

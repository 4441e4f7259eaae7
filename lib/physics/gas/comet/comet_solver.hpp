// COMET (thesis ch. 5): the point-coupled Gauss-Seidel sweep
// (point_coupled_smoother.hpp) as the smoother of a full-approximation-scheme (FAS) geometric
// multigrid cycle (V or F, chosen by regime: below) on agglomerated coarse levels
// (fv/agglomeration.hpp), for the steady discrete-velocity BGK / ESBGK equation r(f) = 0 of a
// KineticOperator.
//
// Levels: the fine FaceGraph, then pairwise agglomerations down to `min_coarse_cells` cells.
// Each coarse level re-discretises the same equation on its agglomerated cells and faces: a
// KineticOperator on the coarse FaceGraph with the same grid, gas and boundary conditions
// (patches are kept by agglomeration), so its residual A_c is the coarse kinetic operator.
//
// V-cycle on level l with equation A_l(f_l) = s_l (s_0 = 0):
//   pre_sweeps smoothing sweeps;
//   r_l = s_l - A_l(f_l);
//   f_{l+1} = R f_l (volume-weighted), s_{l+1} = A_{l+1}(f_{l+1}) + R' r_l (summed)
//     [the FAS source tau = A_c(R f) - R' A_f(f) + R' s_f of the brief, written with r_l];
//   the cycle on level l + 1 (V: once; W: twice; F: an F- then a V-cycle; the coarsest level:
//   coarsest_sweeps sweeps);
//   f_l += P (f_{l+1} - R f_l) (injection; damped per cell to keep every f_k > 0);
//   post_sweeps smoothing sweeps.
// A sweep is forward, or forward + backward when `symmetric`; with coarse_symmetric = false a
// coarse-level sweep is one pass (forward before the coarser visit, backward after it).
//
// The cycle by regime (cycle_shape = Auto, the default; docs/kinetic.md, "COMET cycle by regime"):
// near continuum the V-cycle's rate decays (40 x 40 heat transfer at Kn 0.01: 0.57 per cycle, 19
// cycles against 7 at Kn 1) because pairwise agglomeration with injection corrects the smooth
// error poorly; an F-cycle visits level l about l + 1 times and keeps the count flat (9), but
// with halving coarsening it costs ~2x a V-cycle in symmetric sweeps. With one-pass coarse
// sweeps an F-cycle costs ~10 fine-sweep equivalents against the V-cycle's 8, and needs 10 and
// 9 cycles at Kn 0.01 (heat transfer, cavity): less work than V there, more at Kn >= 0.025
// where V converges fast. So Auto runs F-cycles with one-pass coarse sweeps when the domain
// Knudsen number (below) is < f_cycle_below_knudsen (0.02), V-cycles with symmetric sweeps
// otherwise; explicit V, W, F run as set (coarse_symmetric applies to them).
//
// Closed domains (no pressure boundary): the steady equation does not determine the mass
// (sum_c sum_k w_k r_ck = 0 for every f), and a Gauss-Seidel or source iteration drifts it
// (3 % in the 10 x 10 heat-transfer case); since nu grows with rho the drift changes the
// solution (its Knudsen number). With conserve_mass (default) f is rescaled to the initial
// total mass after every cycle, so the converged state is the steady solution with the initial
// mass, to round-off (KineticOperator::restore_mass, as the sequential solver does).
//
// Regime: in the transport-dominated regime the sequential iteration converges in a few dozen
// iterations, each ~12x cheaper than a V-cycle here (measured: bench_comet_vs_sequential, the
// crossover near Kn = 0.1-0.2), so with sequential_above_knudsen > 0 solve() hands a domain whose
// Knudsen number is >= that threshold to solve_sequential (same residual, tolerance, mass
// pinning and monitor) and says so in CometResult::method ("sequential"): the smoother
// and the cycle chosen by regime. Domain Knudsen number: Bird's mean free path at the
// volume-mean density and temperature of the initial state over the largest extent of the
// mesh's bounding box (domain_knudsen()).
//
// Distributed runs (thesis ch. 5; the operator set_parallel on a rank's part with
// one ghost layer): the coarse levels are agglomerated per part (fv/agglomeration.hpp: coarse
// cells never cross ranks, coarse ghost numbers exchanged, coarse connectivity rebuilt per
// level), each coarse operator gets its level's ghost exchange; a smoothing pass is
// Gauss-Seidel over the rank's owned cells and is followed by a ghost exchange (block Jacobi
// between parts); restriction and prolongation act on owned cells (fas_transfer.hpp) and are
// followed by a ghost exchange of the level they wrote; residual norms, masses, the domain
// Knudsen number and the level sizes are global. A rank without cells takes part in every
// collective. On one rank this is the serial algorithm, bit for bit; on P ranks it converges
// to the serial steady state (to the tolerance) in a few more cycles
// (test/mpi/test_comet_distributed.cpp).
//
// Convergence (shared with the sequential solver, kinetic_operator.hpp): ||r(f)||_2 /
// ||r(f_0)||_2 <= tolerance on the fine level, checked after every cycle. With
// multigrid = false the same loop runs the smoother alone (single-level COMET; an iteration is
// then pre_sweeps + post_sweeps sweeps, the fine-level work of one V-cycle).
#pragma once
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fv/agglomeration.hpp"
#include "parallel/communication_counters.hpp"
#include "physics/gas/comet/point_coupled_smoother.hpp"
#include "physics/gas/kinetic/kinetic_operator.hpp"

namespace rfmems {

enum class CometCycle { V, W, F, Auto };
CometCycle comet_cycle_from_name(const std::string& name);  // "V" | "W" | "F" | "auto"
const char* comet_cycle_name(CometCycle shape);

struct CometOptions {
  CometCoupling coupling = CometCoupling::Conserved;
  bool multigrid = true;
  Index min_coarse_cells = 8;  // stop agglomerating before a level would have fewer cells
  int max_levels = 30;         // coarse levels at most
  int pre_sweeps = 1;
  int post_sweeps = 1;
  int coarsest_sweeps = 4;
  // Coarse-level visits per level: V once; W twice (the FAS equation of level l+1 iterated
  // twice with the same source before the correction); F an F-cycle then a V-cycle; Auto by
  // regime (above).
  CometCycle cycle_shape = CometCycle::Auto;
  Real f_cycle_below_knudsen = 0.02;  // Auto: F-cycles below this domain Kn, V-cycles above
  bool symmetric = true;              // a sweep = forward + backward pass
  // Coarse levels (V, W, F; Auto chooses): false makes a coarse sweep one pass, forward before
  // the coarser visit and backward after it (alternating on the coarsest level).
  bool coarse_symmetric = true;
  int cell_newton_iterations = 1;
  bool conserve_mass = true;            // closed domains only (see above)
  Real sequential_above_knudsen = 0.2;  // <= 0: always COMET
  Real tolerance = 1e-6;                // on ||r||_2 / ||r_0||_2
  int max_cycles = 1000;
  // Stop as soon as the contraction rate forecasts that max_cycles will not reach the
  // tolerance (solvers/convergence_forecast.hpp); false runs to the cap.
  bool stop_when_hopeless = true;
  // Called after every cycle with (cycle, residual ratio); return false to stop.
  std::function<bool(int, Real)> monitor;
};

struct CometResult {
  const char* method = "comet";  // or "sequential" (regime switch)
  Real knudsen = 0;              // domain_knudsen of the initial state
  bool converged = false;
  int cycles = 0;
  Real initial_residual = 0;        // ||r(f_0)||_2
  Real residual_ratio = 0;          // ||r||_2 / ||r_0||_2 at exit
  std::vector<Real> history;        // residual ratio after each cycle
  int levels = 1;                   // including the fine level
  std::vector<Index> level_cells;   // summed over the ranks
  long cell_updates = 0;            // cell point solves, all levels (all ranks)
  Real fine_sweep_equivalents = 0;  // sum over levels of passes x (cells / fine cells)
  long damped_steps = 0;
  bool mass_rescaled = false;  // conserve_mass applied (closed domain)
  double wall_seconds = 0;
  CommunicationCounters communication;     // sent by this rank during the solve (COMET path)
  CometCycle cycle_shape = CometCycle::V;  // the cycle run (Auto resolved)
  bool coarse_symmetric = true;            // the coarse sweeps run
  std::vector<double> level_seconds;       // wall seconds in smoothing and residuals, per level
  std::string stop_reason;                 // the forecast's sentence when it stopped the solve
};

class CometSolver {
 public:
  // `fine` (and its graph) must outlive the solver; the coarse levels are built here.
  CometSolver(KineticOperator& fine, const CometOptions& options);
  ~CometSolver();

  // Iterates on f (length fine.size()) until converged or max_cycles.
  CometResult solve(std::span<Real> f);

  int n_levels() const { return static_cast<int>(levels_.size()); }
  // Mean free path at the volume-mean rho and T of f over the largest bounding-box extent.
  Real domain_knudsen(std::span<const Real> f) const;
  const FaceGraph& level_graph(int level) const;
  KineticOperator& level_operator(int level);

 private:
  struct Level;
  void residual(int level, std::span<const Real> f, std::span<Real> r);
  void smooth(int level, int sweeps, bool post = false);
  void cycle(int level, CometCycle shape);
  std::span<Real> level_f(int level);

  KineticOperator& fine_;
  CometOptions options_;
  std::vector<Agglomeration> hierarchy_;
  std::vector<std::unique_ptr<Level>> levels_;
  std::span<Real> fine_f_;
  long damped_prolongations_ = 0;
  bool coarse_symmetric_ = true;  // of the current solve
};

}  // namespace rfmems

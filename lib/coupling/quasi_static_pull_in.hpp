// Quasi-static pull-in by displacement control (the static deflection-voltage curve through
// its fold, both branches).
//
// The voltage is an unknown and the deflection of one control unknown y_c (the centre of a
// membrane, the tip of a cantilever) is prescribed, so the bordered system
//
//   R(y) + lambda q(y) = 0,            lambda = V^2, q = d(residual)/d(V^2)
//   k_ref (y_c - delta) = 0            (k_ref: the structure's stiffness scale, for conditioning)
//
// is regular at the fold, where dV/d(delta) = 0 and the voltage-controlled Jacobian
// K + lambda dq/dy is singular (Riks/Crisfield's displacement control; see also Pamidighantam
// et al. 2002 for MEMS pull-in). KINSOL solves it (exact Newton + KLU) from the previous
// point's solution, for delta = -k/N f g0, k = 1 .. N. The pull-in voltage is the curve's
// largest V; it is located by golden-section search on delta between the neighbours of the
// largest sampled point until the bracket's voltages agree within voltage_tolerance.
// Points with |delta| below the fold's are the stable branch, beyond it the unstable one.
#pragma once
#include <functional>
#include <vector>

#include "physics/electrostatics/parallel_plate_actuation.hpp"
#include "solvers/kinsol_solver.hpp"

namespace rfmems {

struct QuasiStaticOptions {
  int n_points = 40;              // samples of delta over (0, max_fraction g0]
  Real max_fraction = 0.9;        // deepest prescribed deflection, as a fraction of the gap
  Real voltage_tolerance = 1e-3;  // [V] on the fold voltage
  // KINSOL: ||F||_inf <= this x the largest electrostatic force on a structure unknown (the
  // load the structure balances). 0: tied to the voltage tolerance, 0.2 voltage_tolerance / V
  // (within [1e-12, 1e-4]), so that each point's voltage is good to a tenth of it.
  Real newton_tolerance = 0;
  // Per solve; the Jacobian is refreshed every 10 iterations (modified Newton).
  int max_newton_iterations = 100;
  KluOrdering ordering = KluOrdering::BySize;  // of the bordered Jacobian's KLU factorisation
  // The size from which it factorises with UMFPACK instead (solvers/sparse_direct_solver.hpp),
  // in its symmetric strategy on the nested-dissection order with the voltage last
  // (UmfpackOrdering::SymmetricNestedDissection): the voltage's column couples every loaded
  // unknown, and UMFPACK's own METIS ordering fills 5-8x more. Its dense fronts refactorise
  // and solve 3-4x faster than KLU's columns: the 160 x 16 plate's trace takes 2.1 s CPU against
  // KLU's 7.1 s, 80 x 8 0.27 s against 0.47 s; at 40 x 4 (481 unknowns) KLU is ahead
  // (bench/bench_quasi_static_trace --ordering umfpack nested_dissection).
  Index umfpack_from = 1000;
};

struct PullInPoint {
  Real displacement;  // y_c [m] (negative: towards the electrode)
  Real voltage;       // [V]
  Real min_gap;       // [m]
  bool stable;        // before the fold
  long newton_iterations;
};

struct QuasiStaticPullIn {
  std::vector<PullInPoint> curve;  // in order of increasing |delta|, fold included
  Real pull_in_voltage = 0;
  Real pull_in_displacement = 0;
  long newton_iterations = 0;  // all solves
  long solves = 0;
  NonlinearStats last;           // of the fold's solve
  std::vector<Real> fold_state;  // the solver's state at the fold (structure unknowns first)
};

// The structure's stiffness scale k_ref: the largest diagonal entry of its K at rest.
Real stiffness_scale(ParallelPlateActuation& actuation);

// control: the index of y_c. The actuation's voltage function is overwritten.
QuasiStaticPullIn trace_pull_in(ParallelPlateActuation& actuation, Index control,
                                const QuasiStaticOptions& options = {});

// Displacement control along a path: from `from` (structure unknowns, then V^2; a solved
// state, its control unknown at from[control]) through each deflection in `path`, every solve
// starting from the last one scaled to the new deflection. Returns the last state (structure
// unknowns, then V^2). SolverError if a solve fails.
std::vector<Real> follow_displacement(ParallelPlateActuation& actuation, Index control,
                                      std::span<const Real> from, const std::vector<Real>& path,
                                      const QuasiStaticOptions& options = {});

// A solved, deflected state to follow the curve from by displacement control (structure
// unknowns, then V^2): the static equilibrium at a tenth of the curve's fold voltage, by Newton
// from rest. The actuation's voltage function is overwritten.
std::vector<Real> displacement_control_start(ParallelPlateActuation& actuation,
                                             const QuasiStaticPullIn& curve);

// The sampling and fold search on their own, for any equilibrium solver under displacement
// control (the field-coupled structure's in field_coupled_structure.hpp): `solve(delta, from)`
// returns the equilibrium at control deflection delta, starting from the solved sample `from`
// (delta 0: the state at rest). Counts are summed into the result by the caller's solve.
struct FoldSample {
  PullInPoint point;
  std::vector<Real> state;
};
using DeltaSolve = std::function<FoldSample(Real delta, const FoldSample& from)>;
QuasiStaticPullIn trace_fold(const DeltaSolve& solve, const FoldSample& rest, Real gap,
                             const QuasiStaticOptions& options);

}  // namespace rfmems

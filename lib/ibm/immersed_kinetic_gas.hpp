// The ESBGK (or BGK) gas on the FLUID cells of a fixed background mesh with an immersed body
// (thesis ch. 6, steps 2-3 of a coupled step): the gas slot of the coupled switch.
//
// Per coupled step the caller does
//   gas.set_body(surface, segment_velocity);   // mark, rebuild what changed, interpolate
//   gas.advance(dt);                           // BDF2 (or backward Euler) over [t, t + dt]
//   forces = gas.segment_forces();             // gas on the body, per surface segment
// (solve_steady() instead of advance() for a steady state).
//
// Pieces: CellMarker (FLUID / SOLID / IB); the FluidFaceGraph of the FLUID cells with the IB
// faces on the patch "immersed" (KineticBoundaryKind::External); IbKineticFaceValues (the
// thesis's three steps for the IB-face distribution); a KineticOperator on that graph with the
// background's own conditions on the outer patches; ForceTransfer (IB-face forces to the
// segments, conserving force and moment; the segments' velocities to the IB faces by its
// adjoint).
//
// Forces: F_i = sum_k w_k c_k (c_k . S_i) f_ik on IB face i (S_i out of the fluid): the
// momentum the gas gives the body through the face (KineticOperator::wall_force's flux).
//
// Time step: backward Euler, V_c (f_c - f_c^n) / dt + r_c(f) = 0 (r the steady residual of
// KineticOperator), solved by downwind Gauss-Seidel sweeps (the sequential solver's sweep with
// the extra diagonal V / dt) until ||V (f - f^n) / dt + r(f)||_2 <= step_tolerance ||V f^n /
// dt||_2. A converged step conserves the FLUID mass up to the IB and outer boundary flows (the
// collision is discrete-conservative), to the residual left: the mass error of a step is
// dt sum_ck w_k R_ck, reported.
//
// Cells that change class (set_body with a marking whose cell classes differ): the graph, the
// operator and the interpolations are rebuilt, the distribution is carried over by background
// cell; a cell that becomes FLUID takes the inverse-distance mean of its FLUID face neighbours
// from before the move (a degree-0 least-squares extrapolation; cells with no such neighbour
// take it from the cells filled before them), the gas of a cell that leaves the fluid goes
// with it. Mass bookkeeping: the gas between the IB faces and the body is not simulated; it is
// counted at the reference density, so the gas mass of the domain is
//   M = M_FLUID + rho_ref (A_background - A_body - A_FLUID)        (conserved_mass()).
// A gas step keeps M_FLUID (the IB faces' net flow is rho_ref sum u_i . S_i = 0 for a rigid
// motion) and the areas. A re-marking changes A_FLUID by whole cells, dA: the carried-over
// M_FLUID (RemarkReport::mass_carried) is then scaled to M_before + rho_ref dA (mass_target;
// conserve_mass_on_remark, closed domains only: no pressure patch), so M is an invariant of
// every set_body too; the scale factor differs from 1 by O((rho_cell - rho_ref) dA / M).
//
// Under MPI (options.comm with more than one rank): the background is
// partitioned once (METIS k-way on its cell graph, weights 16 for a FLUID cell at the first
// marking, 1 otherwise: the gas's cost is its FLUID cells), on the root and broadcast. Every
// rank marks, fits, transfers and builds the global FLUID graph from the same global data
// (deterministic, O(surface) beside the gas), then keeps the FLUID cells of its background
// cells plus ghosts (FluidGraphPart: the transport neighbours and the IB band the IB fits
// read). The distribution, the sweeps, the collision and the mass are per rank; ghost values
// are exchanged after every sweep (block Jacobi between parts, Gauss-Seidel within: the
// converged step is the serial one, to the step tolerance); norms, masses, boundary flows
// and the IB-face forces are sums over the ranks (each IB face's force computed by its
// owner, so the segment forces are the same on every rank). The IB-face values of the
// global fits come from the band (LocalIbFaceValues; the band starts at the widest ring cap
// of the fits + 1 and is widened ring by ring while a fit reads beyond it). The carry-over of a
// re-marking runs per owned cell, with a ghost exchange between its filling passes, so it fills the
// cells the serial one fills, in the same passes. GasStepper::Ida is serial only.
//
// Second-order transport (options.transport; second_order_transport.hpp): the FLUID
// graph's KineticOperator gets the body-fitted gas's scheme unchanged (LS gradient, limiter,
// deferred correction). Near the body:
//   - the gradient stencil of a cell is its FLUID face neighbours only; the IB faces are
//     boundary faces of the FLUID graph and are not stencil points (their leaving half is the
//     cell's own reconstruction, circular; their entering half is a fit of the same FLUID
//     cells and the wall values, lagged). A one-sided stencil (a cell beside an IB face has
//     neighbours on the other three sides) is still exact for linear data; a stencil that does
//     not span the plane (a cell with one FLUID neighbour, or two in line) gets no gradient:
//     first order in that cell (LinearReconstruction's rank test).
//   - the limiter's bounds are min / max over the cell and its FLUID neighbours, applied at
//     every face including the IB faces, as at a body-fitted wall.
//   - the ordinates leaving the fluid through an IB face take the owner's limited
//     reconstruction at the IB face (not its cell value); the entering ones come from the
//     thesis's three steps as before. The mass-flux factor a_i is computed with the same
//     leaving values, so the face carries the wall's mass flux exactly and the closed-box
//     conservation is that of first order; the residual's correction includes the IB faces'
//     outgoing (c.S)^+ (f_face - f_c) so that the residual carries that same flux.
// Time: the correction D(f) is refreshed from the iterate at every residual evaluation of a
// step's iteration (advance() evaluates the full residual before each sweep and stops on it),
// so a converged step solves alpha V (f - h) / dt + r_2(f) = 0 with the second-order r_2 at
// f^(n+1): BDF2 / backward Euler keep their order and consistency; the lag is between sweeps
// only, not between steps. GasStepper::Ida sees the same r_2 in every residual (the
// preconditioner stays first order).
// MPI: the slopes of ghost cells come from their owners (KineticOperator exchanges them after
// each reconstruction; the transport ghosts are the face neighbours the upwind faces need), the
// limiter's length scale is the global mesh's, and the IB-face owners are owned cells, so the
// reconstruction and the correction are the serial ones.
#pragma once
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "core/types.hpp"
#include "fv/face_graph.hpp"
#include "ibm/cell_marking.hpp"
#include "ibm/fluid_face_graph.hpp"
#include "ibm/fluid_graph_part.hpp"
#include "ibm/force_transfer.hpp"
#include "ibm/ib_kinetic_face_values.hpp"
#include "ibm/immersed_surface.hpp"
#include "ibm/local_ib_face_values.hpp"
#include "mesh/mesh.hpp"
#include "parallel/communicator.hpp"
#include "physics/gas/comet/point_coupled_smoother.hpp"
#include "physics/gas/kinetic/downwind_ordering.hpp"
#include "physics/gas/kinetic/kinetic_operator.hpp"
#include "physics/gas/kinetic/sequential_solver.hpp"

namespace rfmems {

// How advance() solves a step: downwind sweeps (BDF2 / backward Euler, to step_tolerance), or
// IDA over [t, t + dt] (variable-order BDF, error control at ida_rtol, internal steps <= dt,
// restarted every call) with GMRES and the arrowhead preconditioner of TransientKineticSystem
// (COMET's point block). IDA's mass conservation is that of its Newton tolerance (measured in
// test_immersed_kinetic_gas), not round-off.
enum class GasStepper { Sweeps, Ida };

// The sweep of GasStepper::Sweeps: Downwind, the sequential solver's downwind Gauss-Seidel
// (ordinate by ordinate, the collision lagged within a sweep); PointCoupled, COMET's
// point-coupled cell solve (PointCoupledSmoother with the step's b V on the diagonal: all N
// ordinates of a cell with its conserved moments, so the collision stiffness nu dt is solved
// per cell), cells in index order, alternately forward and backward; Both: one of each per
// iteration.
enum class GasSmoother { Downwind, PointCoupled, Both };

struct ImmersedGasOptions {
  IbKineticOptions ib;
  GasStepper stepper = GasStepper::Sweeps;
  Real ida_rtol = 1e-6;
  bool conserve_mass_on_remark = true;  // closed domains only
  bool bdf2 = true;
  Real step_tolerance = 1e-12;
  int max_step_sweeps = 2000;
  GasSmoother smoother = GasSmoother::Downwind;
  // Start the step's iteration from f^n + (dt / dt_prev) (f^n - f^(n-1)) (linear
  // extrapolation, when f^(n-1) is on the same graph) instead of f^n.
  bool predictor = false;
  // The ranks the gas is distributed over (see "Under MPI" above); serial: one process.
  Communicator comm = Communicator::serial();
  // The IB band's first depth in rings (0: the fits' widest ring cap + 1); widened as needed.
  int band_rings = 0;
  // Face values of the transport (default first order; see "Second-order transport" above).
  TransportScheme transport;
};

struct ImmersedGasTimings {  // CPU seconds of the process, accumulated
  double marking = 0;        // CellMarker::mark + fluid graph + carry-over
  double interpolation = 0;  // IB interpolations, force transfer, wall Maxwellians
  double gas = 0;            // sweeps, residuals, IB-face updates
};

struct RemarkReport {
  bool reclassified = false;
  Index cells_gained = 0, cells_lost = 0;
  Real mass_before = 0, mass_carried = 0, mass_target = 0, mass_after = 0;  // FLUID mass
};

struct GasStepReport {
  int order = 1;                // 1: backward Euler, 2: BDF2
  int sweeps = 0;               // sweeps; GasStepper::Ida: IDA's internal steps
  bool predicted = false;       // started from the extrapolation (options.predictor)
  long newton = 0, krylov = 0;  // GasStepper::Ida
  // Sweeps: ||R|| / ||alpha V h / dt|| of the step's equation; GasStepper::Ida: 0 (IDA's own
  // error control).
  Real residual_ratio = 0;
  bool converged = false;
  Real mass_before = 0, mass_after = 0;
  Real boundary_mass_flow = 0;  // out through every patch (IB included), kg/s per unit depth
};

// The background's partition under MPI (METIS on the background's cell graph, once).
struct GasPartitionReport {
  int ranks = 1;
  Index edge_cut = 0;      // background faces between parts
  double imbalance = 1.0;  // largest part weight / mean (FLUID cells at rest)
  Index owned_cells = 0;   // FLUID cells this rank owns, last graph
  Index ghost_cells = 0;   // and holds as ghosts (transport + IB band)
  int band_rings = 0;
};

class ImmersedKineticGas {
 public:
  // outer: one condition per patch of the background mesh. The mesh must outlive this.
  ImmersedKineticGas(const Mesh& background, std::vector<KineticBoundary> outer, VelocityGrid grid,
                     KineticGas gas, ImmersedGasOptions options = {});
  ~ImmersedKineticGas();

  // The body and its velocity per segment (m/s).
  void set_body(const ImmersedSurface& body, std::vector<Vec3> segment_velocity);
  // Equilibrium at rest state everywhere in the fluid (needs a body); sets rho_ref = s.rho.
  void initialize(const GasState& state);
  // Steady state by the sequential solver on the FLUID cells.
  KineticSolveResult solve_steady(const SequentialOptions& options = {});
  // One time step of length dt (BDF2 or backward Euler, see above).
  GasStepReport advance(Real dt);

  // The coupled step in one call (the shape of lib/coupling's ImmersedGasModel::advance):
  // set_body(surface, segment_velocity), advance(dt), and the gas force per segment [N/m].
  std::vector<Vec3> step(const ImmersedSurface& surface, std::span<const Vec3> segment_velocity,
                         Real dt, GasStepReport* report = nullptr);

  // One checkpoint of the gas after the last step: the body, its velocity and its marking (so
  // the FLUID graph, its part and the IB fits), f^n, the BDF2 / predictor history f^(n-1) and
  // its dt. restore_checkpoint() puts the body back by set_body on the saved marking (the
  // graph rebuilt only if a step since changed the classes) and then the saved
  // distributions, so that the next step
  // is the one that would have followed the save (the strong coupling's redo of a step).
  // Under MPI the owned cells are put back by global FLUID cell and the ghosts exchanged (the
  // band may have been widened since; collective, every rank together).
  void save_checkpoint();
  void restore_checkpoint();
  // Held: set_body keeps the marking of the body at the call (classes, IB faces, cut lists)
  // and fits the IB faces to each new body on it; restore_checkpoint puts back the saved
  // marking. For the strong coupling's iterates within a step, whose bodies differ by far less
  // than a cell: a cell changing class between two iterates made the gas force jump by
  // 5 % (measured, coarse switch), and the fixed point did not exist.
  void hold_marking(bool hold);

  // Gas force on each IB face (marking order) and per surface segment (ForceTransfer).
  std::vector<Vec3> ib_face_forces() const;
  std::vector<Vec3> segment_forces() const;
  // FLUID mass sum_c V_c rho_c, the FLUID area, and the domain's gas mass M (see above).
  Real total_mass() const { return op_->total_mass(f_); }
  Real fluid_area() const;
  Real conserved_mass() const;

  const CellMarking& marking() const { return marking_; }
  // This rank's FLUID graph (serial: the global one) and the global one (every rank holds it).
  const FluidFaceGraph& fluid() const { return *fluid_; }
  const FluidFaceGraph& global_fluid() const { return *global_fluid_; }
  // The distribution of every FLUID cell in global FLUID order, on every rank (collective;
  // serial: distribution()).
  std::vector<Real> global_distribution() const;
  const GasPartitionReport& partition() const { return partition_; }
  const KineticOperator& kinetic() const { return *op_; }
  KineticOperator& kinetic() { return *op_; }
  const IbKineticFaceValues& face_values() const { return *values_; }
  std::span<const Real> distribution() const { return f_; }
  std::span<Real> distribution() { return f_; }
  const ImmersedGasTimings& timings() const { return timings_; }
  const RemarkReport& last_remark() const { return remark_; }
  bool closed() const;

 private:
  bool distributed() const { return !options_.comm.is_serial(); }
  void partition_background(const CellMarking& rest);
  void rebuild_graph(const CellMarking& marking);
  void widen_band(int rings);
  std::vector<Real> carry_over(const FluidFaceGraph& fluid, const GhostExchange* exchange,
                               const std::vector<Real>& from, RemarkReport* report) const;
  void sweep(Real b, std::span<const Real> h);
  GasStepReport advance_ida(Real dt);

  struct Checkpoint;
  std::unique_ptr<Checkpoint> checkpoint_;
  std::optional<CellMarking> held_marking_;
  // v (this part's layout at the save, owned cells global_cell) on the current part's layout.
  std::vector<Real> to_current_layout(const std::vector<Real>& v,
                                      const std::vector<Index>& global_cell) const;

  const Mesh& background_;
  FaceGraph background_graph_;
  CellMarker marker_;
  std::vector<KineticBoundary> outer_;
  VelocityGrid grid_;
  KineticGas gas_;
  ImmersedGasOptions options_;

  std::optional<ImmersedSurface> body_;
  std::vector<Vec3> segment_velocity_, ib_face_velocity_;
  CellMarking marking_;
  std::vector<int> owner_rank_;  // per background cell (distributed only)
  GasPartitionReport partition_;
  std::unique_ptr<FluidFaceGraph> global_fluid_;
  std::unique_ptr<FluidGraphPart> part_;   // distributed only
  const FluidFaceGraph* fluid_ = nullptr;  // this rank's: part_->local, or global_fluid_
  std::unique_ptr<KineticOperator> op_;
  std::unique_ptr<ForceTransfer> transfer_;
  std::unique_ptr<IbKineticFaceValues> values_;      // on the global FLUID graph
  std::unique_ptr<LocalIbFaceValues> local_values_;  // distributed: values_ on part_
  std::vector<Real> band_buffer_;                    // its global copy (NaN outside the band)
  bool has_state_ = false;                           // initialize() was called
  std::vector<DownwindGroup> downwind_;
  std::unique_ptr<PointCoupledSmoother> point_;  // per graph, made on first use
  std::vector<Real> f_;
  std::vector<Real> f_previous_;  // f^(n-1) for BDF2 (empty: none on this graph)
  Real dt_previous_ = 0;
  std::vector<Real> predictor_previous_;  // f^(n-1) carried over a re-marking (predictor only)
  std::vector<Real> scratch_h_, scratch_r_, scratch_start_, scratch_source_;  // advance()
  Real reference_density_ = 0;
  ImmersedGasTimings timings_;
  RemarkReport remark_;
};

}  // namespace rfmems

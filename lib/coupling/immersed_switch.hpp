// The coupling manager of the immersed-boundary switch (thesis ch. 6): a plane
// elastic beam on its own structure mesh moving through a fixed Cartesian background mesh
// that carries the potential (beam at V, an immersed equipotential; bottom electrode at 0)
// and, through the gas slot (immersed_gas.hpp), the gas.
//
// One electrostatic load evaluation (electrostatic_load):
//   move    the beam's boundary nodes by the structure's displacement (each node the mean of
//           the linear reconstructions of the two cells whose faces meet there, so that the
//           load stiffness between neighbouring cells is symmetric; the anchored face stays,
//           shifted anchor_extension into the wall so that the surface leaves the background)
//   mark    CellMarker::mark (FLUID / SOLID / IB)
//   interpolate   IbInterpolation on the new marking (rings capped so that the wall points'
//           reach stays inside the beam's thickness, ib_interpolation.hpp's limitation)
//   electrostatics   ImmersedElectrostatics (KLU), Maxwell force per IB face
//   transfer ForceTransfer::to_surface, then each segment's force to the structure cell that
//           owns its face (total force and moment conserved to round-off)
//
// Time stepping (run): IDA (BDF, adaptive order and step from its error estimate on the
// structure) in one-step mode. The structural system is M u'' + K u - f(u) = 0 with the load
//   f_y,c(u) = F_y,c (g_ref,c / g_c(u))^2,   f_x,c = F_x,c,   g_c = g0 + u_y,c,
// F the IBM force at the reference state u_ref (the state after the last accepted step), so
// the load follows the dominant gap dependence of the parallel-plate law inside the step and
// the Jacobian carries the electrostatic spring softening -2 F g_ref^2 / g^3. After every
// step IDA accepts, the load is re-evaluated by the IBM at the new state (Staggered), and
// the gas advanced over the step; the gas force is lagged by one step (Strong with
// strong_gas: inside the iteration, not lagged; see run()). Implicit: the IBM
// load is evaluated inside every residual call (the exact coupled system; the scaled lagged
// model only in the Jacobian): the reference the staggered scheme's error is measured against
// (docs/immersed_switch.md). Strongly coupled: per step, Aitken-relaxed fixed-point iterations
// on the electrostatic interface load, the step redone from IDA's checkpoint until
// |F_IBM(u) - F_applied(u)| <= tolerance |F_IBM(u)| (at most max_iterations): it converges to
// the implicit scheme's step. With strong_gas the gas is inside every iterate too (redone from
// its own checkpoint with each iterate's motion; gas_every 1, a gas model with a checkpoint),
// else advanced once after the converged step, its force lagged. gas_every k advances the gas
// over every k-th accepted structure step (one gas step spanning them, its force held in
// between): the gas's step decoupled from IDA's, whose steps (~2e-9 s near pull-in) are far
// below what the gas's accuracy needs. Roots: the smallest gap reaching contact_gap (touch-down,
// the pull-in time) and the control's velocity rising through zero after moving down (turning back:
// no pull-in for a step voltage).
#pragma once
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "coupling/coupling_settings.hpp"
#include "coupling/dynamic_pull_in.hpp"
#include "coupling/immersed_gas.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "ibm/cell_marking.hpp"
#include "ibm/ib_interpolation.hpp"
#include "ibm/immersed_electrostatics.hpp"
#include "ibm/immersed_surface.hpp"
#include "physics/elasticity/elasticity_operator.hpp"

namespace rfmems {

struct ImmersedSwitchGeometry {
  Vec3 background_lower = Vec3::Zero();
  Vec3 background_upper = Vec3::Zero();
  int background_cells[2] = {150, 50};
  Real electrode_begin = 0, electrode_end = 0;  // x extent of the electrode on the bottom
  std::string anchor_patch = "left";            // structure patch clamped in the wall
  std::string facing_patch = "bottom";          // structure patch over the electrode
  Real anchor_extension = 0;                    // 0: one background cell width
};

// The background: background_cells Cartesian cells; patches electrode (bottom faces whose
// centre lies in the electrode's extent), substrate (the rest of the bottom), left, right, top.
Mesh make_switch_background(const ImmersedSwitchGeometry& geometry);

// CPU seconds per physics, summed over a run (or all runs since reset_times()).
struct ImmersedPhysicsTimes {
  double move = 0, marking = 0, interpolation = 0, electrostatics = 0, transfer = 0, gas = 0;
  double structure = 0;
  long load_evaluations = 0, gas_steps = 0, structure_steps = 0;
  long electrostatic_analyses = 0;  // solves on a new pattern (the rest refactor the kept LU)
  long electrostatic_krylov_iterations = 0;  // distributed field: GMRES iterations
  // Strong coupling: iterations over all steps (one IBM evaluation each, and one gas step with
  // strong_gas), the most in a step, and the steps left at max_iterations unconverged;
  // the largest relative interface residual |r| / |F| a step ended with (strong only).
  long coupling_iterations = 0, unconverged_steps = 0;
  int max_coupling_iterations = 0;
  double max_coupling_residual = 0;
};

struct ImmersedLoad {
  std::vector<Real> force;    // per structure unknown [N/m]
  Vec3 total = Vec3::Zero();  // on the beam [N/m] (y negative: closing)
  Index ib_faces = 0, one_sided = 0, unreached = 0;
};

struct ImmersedStatic {
  std::vector<Real> u;
  Real control = 0;  // deflection of the control point [m]
  Real force_y = 0;  // electrostatic force on the beam [N/m]
  int iterations = 0;
};

class ImmersedSwitch {
 public:
  // beam: the plane elasticity operator of the structure mesh (its patch anchor_patch fixed);
  // control: the deflection reported and controlled, a functional of the beam's unknowns (the
  // tip's u_y from its cell's reconstruction: ElasticityOperator::displacement_functional).
  ImmersedSwitch(ElasticityOperator& beam, const ImmersedSwitchGeometry& geometry,
                 LinearFunctional control);
  ~ImmersedSwitch();

  const Mesh& background() const { return *background_; }
  const ImmersedSurface& rest_surface() const { return rest_surface_; }
  Real rest_gap() const { return gap0_; }  // beam bottom to electrode at rest
  const LinearFunctional& control() const { return control_; }
  Real background_cell_height() const;
  // Euler-Bernoulli estimate of the first bending period of the clamped-free beam,
  // 2 pi / (1.875^2 (h / L^2) sqrt(E / (12 rho))): scales the velocity tolerance and delays the
  // turning root (a step load also excites higher modes, whose velocity can change the
  // control's sign in the first quarter period before the first mode dominates).
  Real first_bending_period() const { return first_period_; }

  // Displacement of each surface vertex: the mean of the linear reconstructions of the two
  // cells whose segments meet there (zero on the anchored patch).
  std::vector<Vec3> vertex_displacements(std::span<const Real> u) const;
  ImmersedSurface moved_surface(std::span<const Real> u) const;
  std::vector<Vec3> segment_velocities(std::span<const Real> v) const;
  // The smallest gap between the moved facing side (its vertices, as moved_surface puts them)
  // and the electrode: what the contact root watches.
  Real min_gap(std::span<const Real> u) const;
  // move -> mark -> interpolate -> electrostatics -> transfer at displacement u, voltage V.
  ImmersedLoad electrostatic_load(std::span<const Real> u, Real voltage);
  // Per-segment forces to structure unknowns.
  std::vector<Real> to_structure(std::span<const Vec3> segment_forces) const;
  // Segments of the facing patch (for a film under the beam).
  std::vector<Index> facing_segments() const;

  // Static equilibrium K u = f(u) at V by fixed point (one KLU factorisation), to a relative
  // change of the control's deflection.
  ImmersedStatic solve_static(Real voltage, Real tolerance = 1e-7, int max_iterations = 200);
  // Quasi-static pull-in under displacement control of the control's deflection (trace_fold),
  // the same fixed point with V^2 = delta / l(z) per iterate (as laplace_pull_in.hpp).
  QuasiStaticPullIn trace_quasi_static(const QuasiStaticOptions& options,
                                       Real coupling_tolerance = 1e-6);

  // A step voltage V from rest to end_time, touch-down or turning back (options: the events
  // as run_dynamic's, output_interval > 0: the history resampled at it by cubic Hermite in the
  // control's deflection and velocity, else IDA's steps; ida.atol on the displacements, the
  // velocities' atol 2 pi / first_bending_period() times it; the turning root armed after a
  // quarter of that period; coupling: staggered, implicit or strongly_coupled, see the
  // header). gas may be null.
  DynamicRun run(Real voltage, const DynamicOptions& options, ImmersedGasModel* gas);

  const ImmersedPhysicsTimes& times() const { return times_; }
  void reset_times() { times_ = {}; }
  // The electrostatic LU: kept between evaluations while its pattern holds (default) or fresh.
  void set_electrostatics_lu(LuReuse reuse);
  // The field solved over comm's ranks (ImmersedElectrostatics::distribute; every rank of comm
  // then evaluates every load together, as under mpirun with the ESBGK gas); the serial
  // communicator gives back the KLU path (the default).
  void distribute_electrostatics(const Communicator& comm,
                                 const DistributedLinearOptions& options = {});
  bool electrostatics_distributed() const;
  // The last evaluation's marking and potential (for output).
  std::span<const Real> potential() const;

 private:
  struct Kernel;
  ElasticityOperator& beam_;
  ImmersedSwitchGeometry geometry_;
  std::unique_ptr<Mesh> background_;
  std::unique_ptr<Kernel> kernel_;
  ImmersedSurface rest_surface_;
  std::vector<Index> vertex_node_;  // per surface vertex
  std::vector<bool> vertex_anchored_;
  std::vector<Index> segment_cell_;  // per segment: the structure cell
  struct FacingVertex {
    Real rest_gap;
    LinearFunctional u_y;
  };
  std::vector<FacingVertex> facing_vertices_;  // free vertices of the facing side (min_gap)
  LinearFunctional control_;
  Real gap0_ = 0, electrode_y_ = 0, first_period_ = 0;
  IbInterpolationOptions interpolation_;
  ImmersedPhysicsTimes times_;
};

}  // namespace rfmems

// The immersed-boundary field of a switch (thesis ch. 6): a plane elastic beam on its own structure
// mesh moving through a fixed Cartesian background mesh that carries the potential (beam at V, an
// immersed equipotential; bottom electrode at 0) and, through the gas slot (immersed_gas.hpp), the
// gas.
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
// The field-coupled structure (coupling/field_coupled_structure.hpp) solves its equilibria and its
// runs with this load (physics/electrostatics/gap_field.hpp): the IBM load is solved at every field
// evaluation, so its equilibria are fixed points to the tolerance the background resolves (its load
// jumps as slivers are cut), the lagged load's trial gap stays above 2 % of g0, the velocities'
// tolerance is the displacements' times 2 pi / first_bending_period(), and the turning root is
// armed after a quarter of that period. The gas (immersed_gas.hpp) lives on the background around
// the moved surface, its force per segment transferred to the structure cells.
#pragma once
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ibm/cell_marking.hpp"
#include "ibm/ib_interpolation.hpp"
#include "ibm/immersed_electrostatics.hpp"
#include "ibm/immersed_gas.hpp"
#include "ibm/immersed_surface.hpp"
#include "physics/elasticity/elasticity_operator.hpp"
#include "physics/electrostatics/gap_field.hpp"
#include "physics/gas/structure_gas.hpp"

namespace rfmems {

struct ImmersedBoundaryGeometry {
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
Mesh make_switch_background(const ImmersedBoundaryGeometry& geometry);

// CPU seconds per stage of the field's evaluations, summed since reset_times().
struct ImmersedPhysicsTimes {
  double move = 0, marking = 0, interpolation = 0, electrostatics = 0, transfer = 0;
  long load_evaluations = 0;
  long electrostatic_analyses = 0;  // solves on a new pattern (the rest refactor the kept LU)
  long electrostatic_krylov_iterations = 0;  // distributed field: GMRES iterations
  double total() const { return move + marking + interpolation + electrostatics + transfer; }
};

struct ImmersedLoad {
  std::vector<Real> force;    // per structure unknown [N/m]
  Vec3 total = Vec3::Zero();  // on the beam [N/m] (y negative: closing)
  Index ib_faces = 0, one_sided = 0, unreached = 0;
};

class ImmersedBoundaryField : public GapField {
 public:
  // beam: the plane elasticity operator of the structure mesh (its patch anchor_patch fixed);
  // control: the deflection reported and controlled, a functional of the beam's unknowns (the
  // tip's u_y from its cell's reconstruction: ElasticityOperator::displacement_functional).
  ImmersedBoundaryField(ElasticityOperator& beam, const ImmersedBoundaryGeometry& geometry,
                        LinearFunctional control);
  ~ImmersedBoundaryField();

  const Mesh& background() const { return *background_; }
  const ImmersedSurface& rest_surface() const { return rest_surface_; }
  Real rest_gap() const override { return gap0_; }  // beam bottom to electrode at rest
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
  Real min_gap(std::span<const Real> u) const override;
  // move -> mark -> interpolate -> electrostatics -> transfer at displacement u, voltage V.
  ImmersedLoad electrostatic_load(std::span<const Real> u, Real voltage);
  // Per-segment forces to structure unknowns.
  std::vector<Real> to_structure(std::span<const Vec3> segment_forces) const;
  // Segments of the facing patch (for a film under the beam).
  std::vector<Index> facing_segments() const;

  std::string name() const override { return "immersed"; }
  // The electrostatic load as the coupled beam applies it.
  StructureLoad load(std::span<const Real> u, Real voltage) override;
  GapFieldTraits traits() const override;
  double seconds() const override { return times_.total(); }
  Json counters() const override;
  // The gas around the beam's surface as the coupling steps it (physics/gas/structure_gas.hpp):
  // at rest around the rest surface, advanced with the surface moved to u at the segment
  // velocities of v, its per-segment force transferred to the structure.
  std::unique_ptr<StructureGas> surface_gas(std::unique_ptr<ImmersedGasModel> gas) const;

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
  ImmersedBoundaryGeometry geometry_;
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

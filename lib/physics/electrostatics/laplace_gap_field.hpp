// The electrostatic field in the air gap under a plane (2D) beam, as a load on the beam: the
// Laplace equation (physics/electrostatics/electrostatic_solver.hpp) on a gap mesh whose top
// nodes are the beam's bottom nodes (physics/electrostatics/gap_mesh.hpp) and which follows
// the beam (mesh/mesh_motion.hpp: nearest moving node by KD-tree, blending, spring smoothing).
// The electrode is a stretch of the bottom at potential 0, the beam at V, the rest zero flux.
//
// One evaluation at a beam displacement u (load):
//   1. the beam's displacement at its bottom nodes (each from a bottom cell's reconstruction)
//      moves the gap mesh (a cell that inverts: MeshError);
//   2. Laplace with V = 1 (the field scales with V, the Maxwell traction with V^2);
//   3. the traction on each top face of the gap mesh, times its area, goes to the beam cell
//      that owns the matching bottom face: q(u), the force per V^2 per beam unknown [N/m/V^2].
//
// The field-coupled structure (coupling/field_coupled_structure.hpp) solves its equilibria and its
// runs with it (gap_field.hpp: load = V^2 q(u)).
#pragma once
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "mesh/mesh_motion.hpp"
#include "physics/elasticity/elasticity_operator.hpp"
#include "physics/electrostatics/gap_field.hpp"
#include "physics/electrostatics/parallel_plate_actuation.hpp"

namespace rfmems {

class ElectrostaticSolver;

struct LaplaceGapOptions {
  int gap_cells = 16;  // cells across the gap
  MeshMotionOptions motion;
};

class LaplaceGapField : public GapField {
 public:
  // beam: a 2D continuum whose patch `bottom_patch` faces the electrode across `gap` (below
  // it, along -y).
  LaplaceGapField(ElasticityOperator& beam, const std::string& bottom_patch, Real gap,
                  const ElectrodeExtent& electrode, const LaplaceGapOptions& options = {});
  ~LaplaceGapField();
  LaplaceGapField(const LaplaceGapField&) = delete;
  LaplaceGapField& operator=(const LaplaceGapField&) = delete;

  std::string name() const override { return "laplace"; }
  // V^2 q(u), q the force per V^2 on every beam unknown (moves the gap mesh and solves at
  // V = 1), and its total along y.
  StructureLoad load(std::span<const Real> u, Real voltage) override;
  // The smallest gap over the bottom cells' centroid u_y (cheap, for root functions): the
  // parallel-plate law's gap measure.
  Real min_gap(std::span<const Real> u) const override;
  Real rest_gap() const override { return gap_; }
  GapFieldTraits traits() const override { return {}; }
  double seconds() const override { return move_seconds_ + field_seconds_; }
  // Field solves, and the CPU seconds moving the gap mesh and in the field solve.
  Json counters() const override;

  Index gap_cells_total() const;
  long solves() const { return solves_; }

 private:
  ElasticityOperator& beam_;
  Real gap_;
  std::unique_ptr<Mesh> gap_mesh_;
  std::unique_ptr<MeshMotion> motion_;
  std::unique_ptr<ElectrostaticSolver> field_;
  std::vector<Index> beam_nodes_, node_match_, node_owner_, top_face_cell_, bottom_cells_;
  Index top_first_face_ = 0;
  std::vector<Vec3> node_displacement_;
  long solves_ = 0;
  double move_seconds_ = 0, field_seconds_ = 0;
};

}  // namespace rfmems

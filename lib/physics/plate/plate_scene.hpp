// A Mindlin-Reissner plate as described by a case file: the mid-surface mesh (2D), section,
// boundary conditions, pressure and point loads, assembled into a PlateOperator.
//
//   mesh: {type: rectangle, lower: [0 um, 0 um], size: [400 um, 100 um], cells: [80, 20]}
//   material: {E: 200 GPa, nu: 0.31, density: 7854 kg/m^3}    # density: transients only
//             residual_stress: 30 MPa    # optional in-plane sigma0, or [xx, yy, xy]; its membrane
//                                        # force h sigma0 stiffens the plate (residual_stress.hpp)
//   model:
//     structure: plate
//     thickness: 4 um                # h > 0
//     shear_correction: 0.8333       # k in Q = k G h (grad w + beta), default 5/6
//     reconstruction: cubic          # linear | quadratic | cubic (default; see PlateOperator)
//     geometric_nonlinearity: false  # true: the von Karman plate (von_karman_plate.hpp), the
//                                    # in-plane displacements u, v added; read by build_structure
//   boundaries:                      # one entry per mesh patch
//     left:   {type: clamped}                          # w = 0, beta = 0
//     right:  {type: simply_supported}                 # w = 0, M_nn = 0, beta.t = 0 (hard)
//     top:    {type: simply_supported_soft}            # w = 0, M n = 0
//     bottom: {type: free}                             # M n = 0, Q.n = 0
//     edge1:  {type: displacement, w: 1 um, beta: [0, 0]}      # prescribed w, beta
//     edge2:  {type: load, shear: -100 N/m, moment: [0 N, 0 N]} # Q.n and M n per unit edge
//                                                               # length acting on the plate
//   (simply supported edges take an optional w and beta too: a support that moves)
//   in_plane: immovable     # with geometric nonlinearity, on an edge that holds w: u = v = 0
//                           # (immovable, the default) or N n = 0 (free: it slides)
//   pressure: {value: -1 kPa, ramp: 0 s}   # uniform pressure along +z, optional
//   point_loads:                           # optional; each on the cell nearest to `at`
//     - {at: [200 um, 50 um], force: -1 uN, moment: [0 N*m, 0 N*m], ramp: 0 s}
//
// Every boundary entry but clamped/free takes an optional `ramp`. Outputs per step:
// deflection (n x 3: 0, 0, w, so ParaView's "warp by vector" shows the deflected plate) [m],
// rotation (beta_x, beta_y, 0), velocity (transients: 0, 0, dw/dt), moment (n x 3: M_xx,
// M_yy, M_xy) [N m/m] from the cell rotation gradients, shear_force (Q_x, Q_y, 0) [N/m].
// Probes record (w, beta_x, beta_y) at their point from the cell's reconstruction.
// With geometric nonlinearity the deflection field is (u, v, w) and a membrane_force field
// (N_xx, N_yy, N_xy) [N/m] of the stretching (without the residual stress's N0) is written.
#pragma once
#include <memory>
#include <string>

#include "io/case_file.hpp"
#include "physics/plate/plate_operator.hpp"
#include "physics/plate/von_karman_plate.hpp"
#include "physics/structure/structural_model.hpp"

namespace rfmems {

struct PlateScene : StructuralModel {
  std::unique_ptr<Mesh> mesh;  // on the heap: the operator keeps a reference
  PlateSection section;
  std::unique_ptr<PlateOperator> op;
  std::unique_ptr<VonKarmanPlate> von_karman;  // with geometric nonlinearity: built on op
  Real load_time = 0;                          // the longest ramp

  std::string kind() const override { return "plate"; }
  const Mesh& structure_mesh() const override { return *mesh; }
  SecondOrderOperator& structure() override {
    return von_karman ? static_cast<SecondOrderOperator&>(*von_karman) : *op;
  }
  Real ramp_end_time() const override { return load_time; }
  std::vector<bool> quasi_static_components() const override {
    return von_karman ? von_karman->quasi_static_components() : op->rotation_components();
  }
  void write_fields(ResultWriter& writer, int index, Real t, std::span<const Real> y,
                    std::span<const Real> v) const override;
  std::array<std::string, 3> probe_components() const override { return {"w", "beta_x", "beta_y"}; }
  std::vector<Vec3> probe_values(const std::vector<Probe>& probes, Real t,
                                 std::span<const Real> y) const override;
  int main_probe_component() const override { return 0; }
  std::vector<GapElement> gap_elements(const std::string& patch) const override;
  Index gap_unknown(Index cell) const override { return 3 * cell + PlateOperator::kW; }
};

// The gap elements of a plate (PlateScene::gap_elements): every cell, its w the unknown, its
// points the plate's w reconstruction at 3 x 3 Simpson points on a quadrilateral, 7 points
// (corners, edge midpoints, centroid) on a triangle, one point at the cell's own w on other
// cells (plate_scene.cpp).
std::vector<GapElement> plate_gap_elements(const Mesh& mesh, const PlateOperator& op);

// Reads the keys above from the case root (model.structure, which chose the plate, and
// model.geometric_nonlinearity, passed as geometric_nonlinearity, are build_structure's).
// case_dir locates relative mesh files. InputError on anything wrong.
PlateScene build_plate_scene(const CaseNode& root, const std::string& case_dir,
                             AnalysisType analysis, bool geometric_nonlinearity = false);

}  // namespace rfmems

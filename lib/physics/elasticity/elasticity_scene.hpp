// An elasticity problem as described by a case file: mesh, material, model, boundary
// conditions and body force, assembled into an ElasticityOperator.
//
//   material: {E: 200 GPa, nu: 0.31, density: 7854 kg/m^3}   # E > 0, nu in (-1, 0.5),
//                                                            # density > 0 (required for
//                                                            # transients, optional if static)
//   model:
//     structure: plane              # plane (2D meshes, default there) | solid3d (3D meshes)
//     hypothesis: plane_stress      # plane_stress (default) | plane_strain (plane) | 3d (solid3d)
//     stress: coupled               # coupled (default) | segregated (static analyses only)
//     reconstruction: default       # default (cubic 2D, quadratic 3D) | linear | quadratic | cubic
//     grid_damping: 0.2             # damping ratio at the grid's highest frequency, in [0, 1]
//                                   # (numerical Kelvin-Voigt damping; 0: none)
//     geometric_nonlinearity: false # true: total Lagrangian, St Venant-Kirchhoff (see
//                                   # ElasticityOperator); read by build_structure. Loads stay
//                                   # dead: a pressure boundary (a follower load) and the
//                                   # segregated method are bad input with it
//   boundaries:                     # one entry per mesh patch, no more, no fewer
//     left:   {type: fixed}                                    # u = value (default 0)
//     right:  {type: traction, value: [0, -1000 Pa], ramp: 0.02 s}
//     top:    {type: free}                                     # zero traction
//     bottom: {type: symmetry}                                 # u.n = 0, no shear
//     hole:   {type: pressure, value: 1 kPa}                   # traction -p n
//   body_force: [0, -9.81e3]        # N/m^3, optional (SI numbers; not ramped)
//   solver:
//     segregated: {diffusivity: 2mu+lambda, relaxation: 1}     # with model.stress segregated
//
// `value` vectors have one entry per mesh dimension. `ramp: T` scales a load (or a prescribed
// displacement) linearly from 0 at t = 0 to its full value at t = T, then holds it; a static
// analysis is solved at load_time, when every ramp has finished.
#pragma once
#include <memory>
#include <string>

#include "io/case_file.hpp"
#include "materials/linear_elastic.hpp"
#include "mesh/mesh.hpp"
#include "physics/elasticity/elasticity_operator.hpp"
#include "physics/elasticity/segregated_solver.hpp"
#include "physics/structure/structural_model.hpp"

namespace rfmems {

enum class StressMethod { Coupled, Segregated };

// The default model.grid_damping (docs/immersed_switch.md, "Grid damping").
inline constexpr Real kGridDamping = 0.2;

std::string to_string(StressMethod method);  // "coupled", "segregated"

// Fields written per output: displacement (n x 3, z = 0 in 2D) [m], velocity [m/s]
// (transients), stress (n x 6, Voigt xx yy zz yz xz xy) [Pa] from the cell gradients.
// Probes record the displacement (ux, uy, uz) from the cell's reconstruction. With geometric
// nonlinearity the stress field is still that of the small-strain law, C : sym(grad u).
struct ElasticityScene : StructuralModel {
  // On the heap because the operator keeps a reference to the mesh: the scene may move.
  std::unique_ptr<Mesh> mesh;
  LinearElastic material;
  std::unique_ptr<ElasticityOperator> op;
  StressMethod stress = StressMethod::Coupled;
  SegregatedOptions segregated;  // diffusivity and relaxation from the case when segregated
  Real load_time = 0;            // the longest ramp (0 without ramps)

  // StructuralModel
  std::string kind() const override;
  const Mesh& structure_mesh() const override { return *mesh; }
  SecondOrderOperator& structure() override { return *op; }
  Real ramp_end_time() const override { return load_time; }
  std::string static_method() const override {
    return stress == StressMethod::Coupled ? "newton" : "segregated";
  }
  bool solve_static_otherwise(Real t, const AnalysisSettings& settings, std::vector<Real>& y,
                              AnalysisStats& stats) override;
  void write_fields(ResultWriter& writer, int index, Real t, std::span<const Real> y,
                    std::span<const Real> v) const override;
  std::array<std::string, 3> probe_components() const override { return {"ux", "uy", "uz"}; }
  std::vector<Vec3> probe_values(const std::vector<Probe>& probes, Real t,
                                 std::span<const Real> y) const override;
  int main_probe_component() const override { return 1; }
  std::vector<GapElement> gap_elements(const std::string& patch) const override;
  Index gap_unknown(Index cell) const override { return op->gap_unknown(cell); }
};

// Reads mesh, material, model, boundaries, body_force (and solver.segregated) from the case
// root; structure: plane or solid3d as build_structure read model.structure (empty: the one
// the mesh's dimension says); geometric_nonlinearity as build_structure read it. case_dir
// locates relative mesh files. InputError on anything wrong.
ElasticityScene build_elasticity_scene(const CaseNode& root, const std::string& case_dir,
                                       AnalysisType analysis, const std::string& structure = "",
                                       bool geometric_nonlinearity = false);

}  // namespace rfmems

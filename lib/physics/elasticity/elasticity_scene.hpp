// An elasticity problem as described by a case file: mesh, material, model, boundary
// conditions and body force, assembled into an ElasticityOperator.
//
//   material: {E: 200 GPa, nu: 0.31, density: 7854 kg/m^3}   # E > 0, nu in (-1, 0.5),
//                                                            # density > 0 (required for
//                                                            # transients, optional if static)
//   model:
//     hypothesis: plane_stress      # plane_stress | plane_strain (2D meshes) | 3d (3D meshes)
//     stress: coupled               # coupled (default) | segregated (static analyses only)
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

namespace rfmems {

enum class AnalysisType { Static, Transient };
enum class StressMethod { Coupled, Segregated };

std::string to_string(AnalysisType type);  // "static", "transient"
std::string to_string(StressMethod method);  // "coupled", "segregated"

struct ElasticityScene {
  // On the heap because the operator keeps a reference to the mesh: the scene may move.
  std::unique_ptr<Mesh> mesh;
  LinearElastic material;
  std::unique_ptr<ElasticityOperator> op;
  StressMethod stress = StressMethod::Coupled;
  SegregatedOptions segregated;  // diffusivity and relaxation from the case when segregated
  Real load_time = 0;            // the longest ramp (0 without ramps)
};

// Reads mesh, material, model, boundaries, body_force (and solver.segregated) from the case
// root. case_dir locates relative mesh files. InputError on anything wrong.
ElasticityScene build_elasticity_scene(const CaseNode& root, const std::string& case_dir,
                                       AnalysisType analysis);

}  // namespace rfmems

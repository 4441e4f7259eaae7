// Quasi-static pull-in of a plane (2D) beam with the full electrostatic field: the Laplace
// equation in the air gap under the beam (physics/electrostatics/electrostatic_solver.hpp) on
// a gap mesh that follows the beam (mesh/mesh_motion.hpp), strongly coupled to the linear
// elasticity of the beam under displacement control (thesis secs. 2.3-2.7).
//
// The gap mesh's top nodes are the beam's bottom nodes (physics/electrostatics/gap_mesh.hpp);
// the electrode is a stretch of the bottom at potential 0, the beam at V, the rest zero flux.
// The force per V^2 is computed with V = 1 (the field scales with V). For a prescribed
// deflection delta of the control unknown, one coupling iteration is
//
//   1. move the gap mesh by the beam's displacement at its bottom nodes;
//   2. solve Laplace (V = 1): traction on each of the beam's bottom faces, q(u) per unknown;
//   3. solve K z = q (one KLU factorisation of the beam's stiffness for the whole run);
//      lambda = delta / z_c, u_new = lambda z, so that u_new_c = delta exactly, V^2 = lambda;
//   4. u <- u + omega (u_new - u), omega by Aitken's Delta^2 (Irons & Tuck 1969; Kuettler &
//      Wall 2008), until ||u_new - u||_inf <= coupling_tolerance |delta|.
//
// The fold in V(delta) is then found by trace_fold (quasi_static_pull_in.hpp). Mesh-motion
// failures (an inverted gap cell) are MeshError.
#pragma once
#include <string>

#include "coupling/quasi_static_pull_in.hpp"
#include "mesh/mesh_motion.hpp"
#include "physics/elasticity/elasticity_scene.hpp"
#include "physics/electrostatics/parallel_plate_actuation.hpp"

namespace rfmems {

struct LaplacePullInOptions {
  QuasiStaticOptions sampling;     // n_points, max_fraction, voltage_tolerance
  int gap_cells = 16;              // cells across the gap
  Real coupling_tolerance = 1e-9;  // on the displacement update, relative to |delta|
  int max_coupling_iterations = 200;
  MeshMotionOptions motion;
};

struct LaplacePullIn {
  QuasiStaticPullIn result;
  long coupling_iterations = 0;  // = Laplace solves
  Index gap_cells_total = 0;
};

// beam: a 2D continuum whose patch `bottom_patch` faces the electrode across `gap` (below it,
// along -y); control: the index of the controlled unknown (a u_y).
LaplacePullIn trace_pull_in_laplace(ElasticityScene& beam, const std::string& bottom_patch,
                                    Real gap, const ElectrodeExtent& electrode, Index control,
                                    const LaplacePullInOptions& options = {});

}  // namespace rfmems

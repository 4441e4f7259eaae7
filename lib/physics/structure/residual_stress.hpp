// The residual stress a structure holds at rest (deposition stress of a film), as a case gives
// it:
//
//   material:
//     residual_stress: 30 MPa                # the same normal stress along every in-plane axis
//     residual_stress: [20 MPa, 0 MPa, 0 MPa]  # the components: [xx, yy, xy] in 2D,
//                                              # [xx, yy, zz, yz, xz, xy] in 3D
//
// The film's plane is normal to the gap axis, the mesh's last: a plate's in-plane axes are x
// and y, a plane continuum's (a section along the beam) x only, a 3D body's x and y. Tension
// is positive.
//
// It enters every structural model as an initial stress sigma0 with its geometric stiffness:
// the first Piola-Kirchhoff stress of a prestressed body is P = sigma0 + C : eps + grad(u)
// sigma0 to first order in u, and sigma0 is in equilibrium by itself, so the balance gains
// the force grad(u) sigma0 S on every face (for the plate, the membrane force N0 = h sigma0
// acting on the slope: N0 grad(w) . S). That force is what raises a stretched membrane's
// stiffness and frequencies (and lowers them under compression, down to buckling).
//
// sigma0 must be in equilibrium as given: a uniform stress is, inside the body, but a free
// edge carries no stress, so sigma0 n = 0 must hold on every face that no support holds. A
// bridge released with free sides keeps only its stress along the span, sigma (1 - nu) for a
// biaxial film stress sigma (the sides relax sigma_yy to 0 while the anchors keep eps_xx = 0).
#pragma once
#include <functional>

#include "core/types.hpp"
#include "io/case_file.hpp"
#include "mesh/mesh.hpp"

namespace rfmems {

// Reads material.residual_stress (default 0) into a stress tensor of a dim-dimensional model
// whose first film_axes axes lie in the film's plane (see above). InputError on a wrong count.
Mat3 read_residual_stress(const CaseNode& material, int dim, int film_axes);

// InputError (naming material.residual_stress) unless sigma0 n = 0, to 1e-9 of |sigma0|, on
// every boundary face of a patch that released(patch) says no support holds.
void require_released_edges_free(const CaseNode& material, const Mat3& sigma0, const Mesh& mesh,
                                 const std::function<bool(int patch)>& released);

}  // namespace rfmems

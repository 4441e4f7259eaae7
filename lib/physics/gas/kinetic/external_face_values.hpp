// Face values of boundary faces whose condition is KineticBoundaryKind::External: supplied from
// outside the kinetic module (the immersed boundary, lib/ibm/immersed_kinetic_gas.hpp, whose
// IB-face values are interpolated from the gas and the body's wall values).
//
// Contract with KineticOperator: update_boundary_values(f) over all faces calls update(f, owner)
// once, then fill() for every External face; the per-face update_boundary_values(face, f) and
// the wall integrals (wall_force, boundary_mass_flow) call fill() alone, on whatever update()
// last computed (lagged, as a point smoother expects). The source must outlive the operator's
// use of it. An External patch counts as closed (is_closed): it stands for a wall.
//
// The owner's values at a face are what the transport scheme gives the ordinates leaving the
// owner through it: the owner cell's values with first-order transport, its limited linear
// reconstruction at the face centroid with second order (second_order_transport.hpp). The
// operator hands them over, so a source needs no knowledge of the scheme.
#pragma once
#include <span>

#include "core/types.hpp"

namespace rfmems {

class ExternalFaceValues {
 public:
  virtual ~ExternalFaceValues() = default;
  // Refresh whatever the face values depend on from the distribution f (cell-major layout);
  // owner_values[(face - n_interior_faces) * N + k]: the owner's values at every boundary face
  // of the operator's graph (see above).
  virtual void update(std::span<const Real> f, std::span<const Real> owner_values) = 0;
  // All ordinates on External boundary face `face` (a face of the operator's graph), given the
  // owner's values at that face.
  virtual void fill(Index face, std::span<const Real> owner_values, std::span<Real> out) const = 0;
};

}  // namespace rfmems

// Face values of boundary faces whose condition is KineticBoundaryKind::External: supplied from
// outside the kinetic module (the immersed boundary, lib/ibm/immersed_kinetic_gas.hpp, whose
// IB-face values are interpolated from the gas and the body's wall values).
//
// Contract with KineticOperator: update_boundary_values(f) over all faces calls update(f) once,
// then fill() for every External face; the per-face update_boundary_values(face, f) and the
// wall integrals (wall_force, boundary_mass_flow) call fill() alone, on whatever update() last
// computed (lagged, as a point smoother expects). The source must outlive the operator's use of
// it. An External patch counts as closed (is_closed): it stands for a wall.
#pragma once
#include <span>

#include "core/types.hpp"

namespace rfmems {

class ExternalFaceValues {
 public:
  virtual ~ExternalFaceValues() = default;
  // Refresh whatever the face values depend on from the distribution f (cell-major layout).
  virtual void update(std::span<const Real> f) = 0;
  // All ordinates on External boundary face `face` (a face of the operator's graph) from f.
  virtual void fill(Index face, std::span<const Real> f, std::span<Real> out) const = 0;
};

}  // namespace rfmems

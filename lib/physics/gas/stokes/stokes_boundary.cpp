// Tangential ghost values of the Stokes boundaries: see stokes_boundary.hpp.
#include "physics/gas/stokes/stokes_boundary.hpp"

namespace rfmems {

AffineForm wall_tangential_ghost(const StokesWall& wall, const Point2& at, int tangential,
                                 const AffineForm& inside, Real h) {
  const Real r = wall.slip_length / h;
  const Real u_wall = wall.velocity(at)[tangential];
  return (r - 0.5) / (r + 0.5) * inside + AffineForm::known(u_wall / (r + 0.5));
}

AffineForm side_tangential_ghost(const StokesSide& side, const Point2& at, int tangential,
                                 const AffineForm& inside, Real h) {
  switch (side.kind) {
    case StokesSide::Kind::Wall:
      return wall_tangential_ghost(side.wall, at, tangential, inside, h);
    case StokesSide::Kind::Symmetry:
      return inside;
    case StokesSide::Kind::Open:
      if (side.tangential == OpenTangential::Velocity)
        return AffineForm::known(2 * side.tangential_velocity(at)) - inside;
      return inside;
  }
  return inside;
}

}  // namespace rfmems

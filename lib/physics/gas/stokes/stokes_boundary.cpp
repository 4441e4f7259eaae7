// Tangential ghost values of the Stokes boundaries: see stokes_boundary.hpp.
#include "physics/gas/stokes/stokes_boundary.hpp"

namespace rfmems {

namespace {

// (u_in + u_g)/2 - u_b = l (u_in - u_g)/h solved for the ghost u_g.
AffineForm slip_ghost(Real u_b, Real slip_length, const AffineForm& inside, Real h) {
  const Real r = slip_length / h;
  return (r - 0.5) / (r + 0.5) * inside + AffineForm::known(u_b / (r + 0.5));
}

}  // namespace

AffineForm wall_tangential_ghost(const StokesWall& wall, const Point2& at, int tangential,
                                 const AffineForm& inside, Real h) {
  return slip_ghost(wall.velocity(at)[tangential], wall.slip_length, inside, h);
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
        return slip_ghost(side.tangential_velocity(at), side.tangential_slip_length, inside, h);
      return inside;
  }
  return inside;
}

}  // namespace rfmems

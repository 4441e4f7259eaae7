// Boundary conditions of the Stokes solve on a MAC grid (mac_grid.hpp): the four sides of the
// rectangle and the walls of its solid blocks.
//
//   Wall      the wall velocity's normal component on the faces in the wall (impermeable in
//             the wall's frame), and first-order Maxwell slip for the tangential one,
//               u_t - u_wall,t = l du_t/dn,   l = ((2 - sigma) / sigma) lambda
//             (n into the gas; l = 0 is no slip). On a flat wall moving uniformly du_n/dt = 0,
//             so l du_t/dn is l tau / mu, Maxwell's form.
//   Symmetry  u_n = 0 and zero shear stress (the mirror of the tangential velocity).
//   Open      the normal stress of the ambient gas, -p + 2 mu du_n/dn = -p_a, and one of
//             three tangential conditions:
//               ZeroGradient  du_t/dn = 0 (the default): exact for fully developed flow
//                             through the side (plane Poiseuille and Couette with open ends
//                             are reproduced exactly), and the tangential velocity is left
//                             free;
//               ZeroStress    tau_nt = 0, the "do-nothing" traction -p_a n of the full stress:
//                             NOT satisfied by developed channel flow (its tau_nt = mu du/dy
//                             at the outlet), so it shifts a channel's effective pressure
//                             drop by O(h) and its flow by O(1) where the outlet carries shear;
//               Velocity      u_t prescribed (0 by default): the continuum limit of a kinetic
//                             pressure boundary that feeds the ambient Maxwellian at rest,
//                             whose incoming half carries no tangential momentum (a slip
//                             length ~ lambda, negligible at Kn ~ 0.01).
//             The three bracket what a truncated domain's side may impose; the damping study
//             reports the spread (docs/gas_damping.md).
//             Optionally a normal impedance Z: -p + 2 mu du_n/dn = -(p_a + Z u_n), u_n the
//             outward velocity. It is the continuum limit of the kinetic pressure boundary
//             (incoming half the ambient Maxwellian at rest): its Knudsen layer needs the jump
//             p - p_a = C p u_n / sqrt(2 R T) to pass a normal flow, C = 2.13 for BGK (Sone,
//             Molecular Gas Dynamics, 2007: the linearised condensation problem, quoted from
//             memory), and C does not vanish with Kn, so Z L / mu ~ C L / lambda: near the
//             continuum such a side is all but closed to normal flow
//             (test_kinetic_pressure_boundary.cpp measures C of the kinetic code;
//             docs/gas_damping.md). With Velocity, a slip length l, u_t - u_b = l du_t/dn
//             (the Kramers layer of a diffuse wall, the same for that boundary), completes
//             that limit.
//
// The tangential conditions act through ghost values at the mirror point h/2 beyond the
// boundary line, on the nodes where the shear stress lives (tangential_ghost below).
#pragma once
#include <array>
#include <functional>
#include <vector>

#include "physics/gas/stokes/affine_form.hpp"
#include "physics/gas/stokes/mac_grid.hpp"

namespace rfmems {

using VelocityField = std::function<Point2(const Point2&)>;
using ScalarField = std::function<Real(const Point2&)>;

// l = ((2 - sigma) / sigma) lambda for tangential momentum accommodation sigma.
inline Real maxwell_slip_length(Real accommodation, Real mean_free_path) {
  return (2 - accommodation) / accommodation * mean_free_path;
}

struct StokesWall {
  VelocityField velocity = [](const Point2&) { return Point2(0, 0); };
  Real slip_length = 0;  // l; 0: no slip
};

enum class OpenTangential { ZeroGradient, ZeroStress, Velocity };

struct StokesSide {
  enum class Kind { Wall, Symmetry, Open };
  Kind kind = Kind::Wall;
  StokesWall wall;                                                      // Wall
  ScalarField ambient_pressure = [](const Point2&) { return 0.0; };     // Open: p_a
  OpenTangential tangential = OpenTangential::ZeroGradient;             // Open
  ScalarField tangential_velocity = [](const Point2&) { return 0.0; };  // Open, Velocity
  Real tangential_slip_length = 0;                                      // Open, Velocity: l [m]
  Real normal_impedance = 0;  // Open: Z [Pa s/m]; 0: the ambient traction alone

  static StokesSide make_wall(StokesWall w) {
    StokesSide s;
    s.wall = std::move(w);
    return s;
  }
  static StokesSide symmetry() {
    StokesSide s;
    s.kind = Kind::Symmetry;
    return s;
  }
  static StokesSide open(Real p_a, OpenTangential t = OpenTangential::ZeroGradient) {
    StokesSide s;
    s.kind = Kind::Open;
    s.ambient_pressure = [p_a](const Point2&) { return p_a; };
    s.tangential = t;
    return s;
  }
};

enum class Side { Left, Right, Bottom, Top };

struct StokesBoundaries {
  std::array<StokesSide, 4> sides;  // indexed by Side
  std::vector<StokesWall> blocks;   // one per MacGrid block
  const StokesSide& side(Side s) const { return sides[static_cast<int>(s)]; }
};

// The ghost of the tangential velocity at the mirror point of `inside` (h/2 from the line, on
// the gas side) across a boundary line; `at` is the node on the line. Wall: the linear profile
// through inside and ghost has (u_in + u_g)/2 - u_w = l (u_in - u_g)/h, so the wall shear
// mu (u_in - u_g)/h = mu (u_in - u_w) / (l + h/2), exact for Couette flow. `tangential`
// picks the velocity component along the line (0: x, 1: y).
AffineForm wall_tangential_ghost(const StokesWall& wall, const Point2& at, int tangential,
                                 const AffineForm& inside, Real h);
// Symmetry, or Open with ZeroGradient / ZeroStress (the caller zeroes the stress of the
// latter): the mirror; Open with Velocity: the wall's ghost for u_b and the slip length
// (2 u_b - u_in without slip).
AffineForm side_tangential_ghost(const StokesSide& side, const Point2& at, int tangential,
                                 const AffineForm& inside, Real h);

}  // namespace rfmems

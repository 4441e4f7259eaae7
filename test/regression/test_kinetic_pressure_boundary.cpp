// The normal impedance of the kinetic pressure boundary (the continuum end of the gas
// damping study, docs/gas_damping.md "Why ESBGK sits above the Stokes reference").
//
// A pressure boundary feeds the ambient Maxwellian at rest (p_a, T) into the gas
// (kinetic_boundary.hpp). To pass a normal outflow u_n its Knudsen layer needs the interior
// pressure p = p_a + C p u_n / sqrt(2 R T): the linearised condensation problem, C = 2.13 for
// BGK (Sone, Molecular Gas Dynamics, 2007; quoted from memory), the collisionless value
// (4 + pi) / (2 sqrt(pi)) = 2.01 (free_molecular_wall.hpp). C is O(1) at every Kn, so in the
// continuum limit the side's impedance Z = C p / sqrt(2 R T) outgrows the viscous stresses,
// Z L / mu ~ C L / lambda: such a side is not the continuum's open boundary. The Stokes
// reference models it as an impedance (stokes_boundary.hpp).
//
// Slab (2 x 40 cells, height L, specular sides; 2 columns so that the second-order
// reconstruction has a full stencil): the bottom is a diffuse wall moving along its normal at
// +-V into the gas (it injects rho V through the fixed mesh), the top a pressure boundary at
// p_a. The steady flow is uniform, the wall's emission is the gas's own drifting Maxwellian
// (no layer there), so the wall's normal traction is the bulk pressure and its odd part in V
// is C p_a V / sqrt(2 R T). Asserted (ESBGK, second order, 12^3 velocities, COMET):
//   - C within 5 % of the BGK value 2.13 at Kn = lambda / L = 0.05 (measured 2.085; 8^3:
//     2.047, 16^3: 2.094);
//   - C the same at Kn = 0.02 and 0.2, to 3 % (not a Knudsen-layer term that vanishes with
//     Kn; measured 2.08-2.09 at 12^3);
//   - the even part (the pressure at V = 0): p_a to 1e-5.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/kinetic_slab.hpp"
#include "physics/gas/comet/comet_kinetic_solver.hpp"
#include "physics/gas/kinetic/kinetic_operator.hpp"

using namespace rfmems;

namespace {

constexpr Real kT = 273.15, kL = 1.0, kV = 0.1;

struct Impedance {
  Real coefficient = 0;  // C: (p - p_a) / (p_a V / sqrt(2 R T))
  Real even = 0;         // (p(+V) + p(-V)) / (2 p_a) - 1
};

// The bottom wall's normal traction (the bulk pressure) at wall speed v.
Real bulk_pressure(Real v, Real rho, const FaceGraph& g, const VelocityGrid& grid,
                   const KineticGas& gas) {
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::specular_wall());
  bcs[g.find_patch("bottom")] = KineticBoundary::diffuse_wall(kT, Vec3(0, v, 0));
  bcs[g.find_patch("top")] = KineticBoundary::pressure_outlet(gas.pressure(rho, kT), kT);
  KineticOperator op(g, grid, gas, bcs);
  TransportScheme second;
  second.order = TransportOrder::SecondOrder;
  op.set_transport(second);
  std::vector<Real> f(op.size());
  op.initialize(f, [&](const Vec3&) { return GasState{rho, Vec3(0, v, 0), kT}; });
  const KineticSolveResult r =
      solve_comet(op, f, CometOptions{}, 1e-9, 200, [](int, Real) { return true; });
  EXPECT_TRUE(r.converged);
  return -op.wall_force("bottom", f).y() / kL;  // the wall is kL x 1 m
}

Impedance measure(Real kn, int points) {
  const FaceGraph g = test_support::kinetic_slab(kL, 2, 40);
  const KineticGas gas = KineticGas::argon();
  const Real c0 = gas.thermal_speed(kT);
  const VelocityGrid grid = VelocityGrid::uniform(points, points, points, 3.5 * c0);
  const Real rho = gas.density_for_knudsen(kn, kT, kL), p_a = gas.pressure(rho, kT);
  const Real up = bulk_pressure(kV, rho, g, grid, gas),
             down = bulk_pressure(-kV, rho, g, grid, gas);
  Impedance z;
  z.coefficient = (up - down) / (2 * kV) * c0 / p_a;
  z.even = (up + down) / (2 * p_a) - 1;
  std::printf("Kn = %g, %d^3 velocities: C = %.4f, even part %.2e\n", kn, points, z.coefficient,
              z.even);
  return z;
}

}  // namespace

TEST(KineticPressureBoundary, NormalImpedanceIsTheCondensationJumpAtEveryKnudsenNumber) {
  const Impedance mid = measure(0.05, 12);
  EXPECT_NEAR(mid.coefficient / 2.13, 1, 0.05);
  EXPECT_LT(std::abs(mid.even), 1e-5);
  for (Real kn : {0.02, 0.2}) {
    const Impedance z = measure(kn, 12);
    EXPECT_NEAR(z.coefficient / mid.coefficient, 1, 0.03) << "Kn " << kn;
    EXPECT_LT(std::abs(z.even), 1e-5);
  }
}

// Free-molecular damping of a diffuse wall moving in a gas at rest (the large-Kn end
// of the gas damping study), ESBGK argon at Kn = 100 against the closed form of
// lib/physics/gas/kinetic/free_molecular_wall.hpp.
//
// Quasi-1D slab (1 x 4 cells, height L, specular sides): the bottom is a diffuse wall at T
// moving at V = 0.1 m/s, the top a pressure boundary (the ambient Maxwellian at p, T). At
// Kn = lambda / L = 100 the gas arriving at the wall is the ambient Maxwellian up to O(1/Kn),
// so the damping traction, the odd part [F(+V) - F(-V)] / 2 per unit area, is
//   normal motion (along y, into the gas):  -(4 + pi) p V / (2 sqrt(2 pi R T))
//   tangential (along z, the 2D mesh's invariant direction, so the specular sides do not
//   reverse it):                             -p V / sqrt(2 pi R T).
// Asserted: within 5 % of the closed form on the same velocity grid (the discrete half-range
// sums; measured +0.02 % normal, -0.67 % tangential: the O(1/Kn) collisions) and of the
// continuous closed form (measured -2.1 % / +3.8 %: the half-range quadrature's error on
// 10 points over +-3.5 c0, second order in dc); the closed forms themselves: the discrete
// odd parts converge to the continuous ones at second order (3e-2 -> 2.8e-4 normal,
// 6e-2 -> 7e-4 shear from 10 to 80 points), and the linear coefficients are the derivatives
// of the exact traction (central difference).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "../support/kinetic_slab.hpp"
#include "physics/gas/kinetic/free_molecular_wall.hpp"
#include "physics/gas/kinetic/sequential_solver.hpp"

using namespace rfmems;

namespace {

constexpr Real kT = 273.15, kL = 1e-3, kV = 0.1;

// y component (normal) or z (tangential) of the bottom wall's force per unit area when it
// moves at `velocity`.
Vec3 slab_wall_traction(const Vec3& velocity, Real kn, const VelocityGrid& grid, Real& rho) {
  const FaceGraph g = test_support::kinetic_slab(kL, 1, 4);
  const KineticGas gas = KineticGas::argon();
  rho = gas.density_for_knudsen(kn, kT, kL);
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::specular_wall());
  bcs[g.find_patch("bottom")] = KineticBoundary::diffuse_wall(kT, velocity);
  bcs[g.find_patch("top")] = KineticBoundary::pressure_outlet(gas.pressure(rho, kT), kT);
  KineticOperator op(g, grid, gas, bcs);
  std::vector<Real> f(op.size());
  op.initialize(f, [&](const Vec3&) { return GasState{rho, Vec3::Zero(), kT}; });
  SequentialOptions options;
  options.tolerance = 1e-10;
  const KineticSolveResult result = solve_sequential(op, f, options);
  EXPECT_TRUE(result.converged);
  return op.wall_force("bottom", f) / kL;  // the wall is kL x 1 m
}

}  // namespace

TEST(FreeMolecularWall, ClosedFormsAgree) {
  const KineticGas gas = KineticGas::argon();
  const Real rho = 1e-3, c0 = gas.thermal_speed(kT);
  const Vec3 m(0, -1, 0);  // bottom wall: normal out of the gas
  const FreeMolecularDamping d = free_molecular_damping(rho, kT, gas.R);
  // The linear coefficients are the derivatives of the exact traction at U = 0.
  const Real h = 1e-4 * c0;
  const Vec3 tn = (free_molecular_wall_traction(rho, kT, gas.R, Vec3(0, h, 0), m) -
                   free_molecular_wall_traction(rho, kT, gas.R, Vec3(0, -h, 0), m)) /
                  (2 * h);
  const Vec3 tt = (free_molecular_wall_traction(rho, kT, gas.R, Vec3(0, 0, h), m) -
                   free_molecular_wall_traction(rho, kT, gas.R, Vec3(0, 0, -h), m)) /
                  (2 * h);
  EXPECT_NEAR(tn.y() / -d.normal, 1, 1e-7);
  EXPECT_NEAR(tt.z() / -d.tangential, 1, 1e-12);
  // At rest the wall feels the pressure.
  EXPECT_NEAR(
      free_molecular_wall_traction(rho, kT, gas.R, Vec3::Zero(), m).y() / -gas.pressure(rho, kT), 1,
      1e-14);
  // The discrete half-range sums converge to the continuous closed form (second order in
  // dc across the kink at c . m = 0): the odd parts (the damping; the even part carries the
  // midpoint rule's spectrally small error in the ambient pressure, 1e-4 p on 8 points in c_x),
  // normal and tangential motion at s = 0.01.
  const Vec3 un(0, 0.01 * c0, 0), ut(0, 0, 0.01 * c0);
  auto odd = [&](const Vec3& u, auto traction) { return 0.5 * (traction(u) - traction(-u)); };
  auto exact = [&](const Vec3& u) { return free_molecular_wall_traction(rho, kT, gas.R, u, m); };
  const Vec3 exact_n = odd(un, exact), exact_t = odd(ut, exact);
  Real previous_n = 1, previous_t = 1;
  for (int n : {10, 20, 40, 80}) {
    const VelocityGrid grid = VelocityGrid::uniform(8, n, n, 4.0 * c0);
    auto discrete = [&](const Vec3& u) {
      return discrete_free_molecular_wall_traction(grid, rho, kT, gas.R, u, m);
    };
    const Real en = std::abs(odd(un, discrete).y() / exact_n.y() - 1);
    const Real et = std::abs(odd(ut, discrete).z() / exact_t.z() - 1);
    std::printf("%2d points: normal damping %.2e, shear %.2e relative\n", n, en, et);
    EXPECT_LT(en, previous_n);
    EXPECT_LT(et, previous_t);
    previous_n = en;
    previous_t = et;
  }
  EXPECT_LT(previous_n, 1e-3);
  EXPECT_LT(previous_t, 1e-3);
}

TEST(FreeMolecularWall, EsbgkAtKnudsen100MatchesTheClosedForm) {
  const KineticGas gas = KineticGas::argon();
  const VelocityGrid grid = VelocityGrid::uniform(10, 10, 10, 3.5 * gas.thermal_speed(kT));
  const Vec3 m(0, -1, 0);
  for (int axis : {1, 2}) {  // normal (y), tangential (z)
    Vec3 v = Vec3::Zero();
    v[axis] = kV;
    Real rho = 0;
    const Real up = slab_wall_traction(v, 100, grid, rho)[axis];
    const Real down = slab_wall_traction(-v, 100, grid, rho)[axis];
    const Real damping = 0.5 * (up - down);  // odd part, per unit area
    const Real discrete =
        0.5 * (discrete_free_molecular_wall_traction(grid, rho, kT, gas.R, v, m) -
               discrete_free_molecular_wall_traction(grid, rho, kT, gas.R, -v, m))[axis];
    const FreeMolecularDamping d = free_molecular_damping(rho, kT, gas.R);
    const Real closed = -(axis == 1 ? d.normal : d.tangential) * kV;
    std::printf(
        "%s: ESBGK %.5e Pa, discrete closed form %.5e (%+.2f %%), continuous %.5e "
        "(%+.2f %%)\n",
        axis == 1 ? "normal" : "tangential", damping, discrete, 100 * (damping / discrete - 1),
        closed, 100 * (damping / closed - 1));
    EXPECT_NEAR(damping / discrete, 1, 0.05);
    EXPECT_NEAR(damping / closed, 1, 0.05);
  }
}

// Heat transfer between parallel diffuse plates in the free-molecular limit (Kn = 1000), the
// 1D heat-transfer case of thesis sec. 5.5.1 at its rarefied end, against the closed form:
// each wall re-emits a half-Maxwellian at its temperature; zero net mass flux gives the
// one-way mass flux Phi = rho_1 sqrt(R T_1 / (2 pi)) = rho_2 sqrt(R T_2 / (2 pi)) with
// rho_1 + rho_2 = 2 rho_mean (each half-Maxwellian fills half of velocity space everywhere),
// and each molecule carries 2 R T of energy across, so
//     q = 2 R (T_hot - T_cold) Phi,  Phi = 2 rho_mean sqrt(R T_c / 2 pi) / (1 + sqrt(T_c / T_h)).
// ESBGK, argon, walls 273.15 K / 327.78 K, a quasi-1D mesh (1 x 4 cells, specular sides).
// The half-range quadrature of the midpoint grid converges at second order in dc (the
// integrand has a kink at c_y = 0): the error against q falls ~4x from 12 to 24 points in c_y
// (3.6 % -> 0.76 %); at 24 points it is below 1 %. The wall heat flows balance (energy
// conservation) to 1e-5.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "mesh/structured_mesh.hpp"
#include "physics/gas/kinetic/sequential_solver.hpp"

using namespace rfmems;

namespace {

constexpr Real kCold = 273.15, kHot = 327.78, kL = 0.01;

struct HeatRun {
  Real q_bottom, q_top, q_exact;
};

HeatRun free_molecular_heat_flux(int ny_velocity) {
  BoxSpec spec;
  spec.upper = Vec3(kL, kL, 0);
  spec.n[0] = 1;
  spec.n[1] = 4;
  const FaceGraph g = face_graph_of(make_structured_mesh(spec));
  const KineticGas gas = KineticGas::argon();
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::specular_wall());
  bcs[g.find_patch("bottom")] = KineticBoundary::diffuse_wall(kCold);
  bcs[g.find_patch("top")] = KineticBoundary::diffuse_wall(kHot);
  const Real extent = 3.5 * gas.thermal_speed(kCold);
  const Vec3 extents(extent, 1.1 * extent, extent);  // the hot wall's Maxwellian is wider
  KineticOperator op(g, VelocityGrid::uniform(8, ny_velocity, 8, extents), gas, bcs);
  const Real rho = gas.density_for_knudsen(1000, kCold, kL);
  std::vector<Real> f(op.size());
  op.initialize(f, [&](const Vec3&) { return GasState{rho, Vec3::Zero(), kCold}; });
  const KineticSolveResult result = solve_sequential(op, f);
  EXPECT_TRUE(result.converged);
  const Real width = kL;  // per unit depth: the wall is kL x 1 m
  HeatRun run;
  run.q_bottom = op.wall_heat_flow(g.find_patch("bottom"), f) / width;
  run.q_top = op.wall_heat_flow(g.find_patch("top"), f) / width;
  const Real phi = 2 * rho * std::sqrt(gas.R * kCold / (2 * std::numbers::pi)) /
                   (1 + std::sqrt(kCold / kHot));
  run.q_exact = 2 * gas.R * (kHot - kCold) * phi;
  std::printf("%2d points in c_y: q = %.5e W/m^2 (top %.5e), free-molecular %.5e (%+.3f %%), "
              "%d iterations\n",
              ny_velocity, run.q_bottom, run.q_top, run.q_exact,
              100 * (run.q_bottom / run.q_exact - 1), result.iterations);
  return run;
}

}  // namespace

TEST(KineticHeatTransfer, FreeMolecularHeatFluxBetweenPlates) {
  const HeatRun coarse = free_molecular_heat_flux(12);
  const HeatRun fine = free_molecular_heat_flux(24);
  EXPECT_LE(std::abs(fine.q_bottom + fine.q_top) / fine.q_bottom, 1e-5);
  EXPECT_LE(std::abs(fine.q_bottom / fine.q_exact - 1), 0.01);
  // Second order in dc: 3.6 % -> 0.76 % measured.
  EXPECT_LT(4 * std::abs(fine.q_bottom / fine.q_exact - 1),
            1.3 * std::abs(coarse.q_bottom / coarse.q_exact - 1));
}

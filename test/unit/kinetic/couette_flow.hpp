// Plane Couette flow of argon between diffuse walls (thesis sec. 5.5.1): walls H = 1 m apart at
// T0 = 273.15 K, the top one moving at U = 10 m/s, density set by the Knudsen number
// (Kn = lambda / H with Bird's lambda = (mu / p) sqrt(pi R T / 2)), mu_ref = 2.117e-5 Pa s,
// omega = 0.81, 10 x 10 x 10 velocities over +-3.5 sqrt(2 R T0), ESBGK.
//
// Quasi-1D mesh: one column of Ny cells in the (x, y) plane with specular sides; the walls move
// along z, the invariant direction of the 2D mesh, so the specular sides (which reverse c_x)
// do not touch the flow. First-order slip solution (Maxwell, accommodation sigma):
//   u(y) = U (y / H + zeta) / (1 + 2 zeta),   zeta = (2 - sigma) / sigma Kn.
// Shared by the Couette regression test and study.
#pragma once
#include <cmath>
#include <vector>

#include "../../support/kinetic_slab.hpp"
#include "physics/gas/kinetic/sequential_solver.hpp"

namespace rfmems::test_support {

struct CouetteRun {
  std::vector<Real> y, u;  // cell centres and velocity along the walls
  Real rms_error = 0;      // RMS over cells of (u - u_slip) / U
  Real shear_stress = 0;   // tau_zy averaged over the cells
  Vec3 force_top = Vec3::Zero(), force_bottom = Vec3::Zero();  // gas on the walls, N/m
  KineticSolveResult solve;
};

// nx columns across the same width H (on one column the second-order reconstruction's
// least-squares gradient is the one along the column: second_order_transport.cpp);
// coarse_fine_difference needs nx = 1.
inline CouetteRun run_couette(Real kn, int ny, CollisionModel model = CollisionModel::Esbgk,
                              int nv = 10, Real sigma = 1, int nx = 1,
                              TransportOrder order = TransportOrder::FirstOrder) {
  constexpr Real H = 1, U = 10, T0 = 273.15;
  const FaceGraph g = kinetic_slab(H, nx, ny);
  const KineticGas gas = KineticGas::argon(model);
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::specular_wall());
  bcs[g.find_patch("bottom")] = KineticBoundary::diffuse_wall(T0, Vec3::Zero(), sigma);
  bcs[g.find_patch("top")] = KineticBoundary::diffuse_wall(T0, Vec3(0, 0, U), sigma);
  const Real rho = gas.density_for_knudsen(kn, T0, H);
  KineticOperator op(g, VelocityGrid::uniform(nv, nv, nv, 3.5 * gas.thermal_speed(T0)), gas, bcs);
  TransportScheme scheme;
  scheme.order = order;
  op.set_transport(scheme);
  std::vector<Real> f(op.size());
  // Linear initial profile, as in the thesis.
  op.initialize(f, [&](const Vec3& x) { return GasState{rho, Vec3(0, 0, U * x.y() / H), T0}; });
  CouetteRun run;
  run.solve = solve_sequential(op, f);
  const Real zeta = (2 - sigma) / sigma * kn;
  Real sum = 0;
  for (Index c = 0; c < op.n_cells(); ++c) {
    const Real y = g.cell_centroid[c].y();
    const Real u = op.macro(c).u.z();
    run.y.push_back(y);
    run.u.push_back(u);
    sum += std::pow((u - U * (y / H + zeta) / (1 + 2 * zeta)) / U, 2);
    run.shear_stress += op.macro(c).stress(2, 1) / op.n_cells();
  }
  run.rms_error = std::sqrt(sum / op.n_cells());
  run.force_top = op.wall_force("top", f);
  run.force_bottom = op.wall_force("bottom", f);
  return run;
}

// RMS over the coarse cells of u_coarse - (mean of the two fine cells inside), / U.
inline Real coarse_fine_difference(const CouetteRun& coarse, const CouetteRun& fine) {
  Real sum = 0;
  for (std::size_t i = 0; i < coarse.u.size(); ++i) {
    const Real restricted = 0.5 * (fine.u[2 * i] + fine.u[2 * i + 1]);
    sum += std::pow((coarse.u[i] - restricted) / 10.0, 2);
  }
  return std::sqrt(sum / coarse.u.size());
}

}  // namespace rfmems::test_support

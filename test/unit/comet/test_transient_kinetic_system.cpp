// The transient kinetic system under IDA (SPGMR, COMET block preconditioner):
//  1. the preconditioner inverts a cell's own block of the Jacobian dF/df + c_j dF/df'
//     (central differences, BGK at equilibrium, interior cell): P^-1 (J v) = v to 1e-6;
//  2. heat transfer between diffuse walls (specular sides), started from a uniform gas: the
//     transient reaches the sequential solver's steady state (temperature and density to
//     1e-5 relative), the closed box keeps its mass, and the preconditioned Krylov solver needs
//     few iterations per Newton iteration.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/structured_mesh.hpp"
#include "physics/gas/comet/transient_kinetic_system.hpp"
#include "physics/gas/kinetic/sequential_solver.hpp"
#include "solvers/ida_integrator.hpp"

using namespace rfmems;

namespace {

constexpr Real kT0 = 273.15;

FaceGraph box(int nx, int ny, Real size) {
  BoxSpec spec;
  spec.upper = Vec3(size, size, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  return face_graph_of(make_structured_mesh(spec));
}

std::vector<KineticBoundary> heat_transfer_walls(const FaceGraph& g) {
  std::vector<KineticBoundary> bcs;
  for (const std::string& name : g.patch_names) {
    if (name == "bottom")
      bcs.push_back(KineticBoundary::diffuse_wall(kT0));
    else if (name == "top")
      bcs.push_back(KineticBoundary::diffuse_wall(1.2 * kT0));
    else
      bcs.push_back(KineticBoundary::specular_wall());
  }
  return bcs;
}

}  // namespace

TEST(TransientKinetic, PreconditionerInvertsTheCellBlock) {
  const FaceGraph g = box(3, 3, 0.01);
  KineticGas gas = KineticGas::argon();
  gas.model = CollisionModel::Bgk;
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::specular_wall());
  KineticOperator op(g, VelocityGrid::uniform(6, 6, 6, 3.5 * gas.thermal_speed(kT0)), gas, bcs);
  const Real rho0 = gas.density_for_knudsen(0.1, kT0, 0.01);
  std::vector<Real> f(op.size()), fp(op.size(), 0.0);
  op.initialize(f, [&](const Vec3&) { return GasState{rho0, Vec3(30, -20, 0), kT0}; });
  TransientKineticSystem system(op);
  const Real c_j = 2.0 * op.collision_frequency(4);  // stiff enough to matter, not dominant
  system.preconditioner_setup(0, c_j, f, fp);

  const Index N = op.n_ordinates(), centre = 4;
  std::vector<Real> v(op.size(), 0.0);
  for (Index k = 0; k < N; ++k)
    v[centre * N + k] = f[centre * N + k] * std::sin(0.7 * static_cast<Real>(k) + 0.3);
  // J v = dF/df v + c_j V v by central differences of F along v.
  const Real eps = 1e-4;
  std::vector<Real> fplus(f), fminus(f), rplus(op.size()), rminus(op.size()), jv(op.size());
  for (Index i = 0; i < op.size(); ++i) {
    fplus[i] += eps * v[i];
    fminus[i] -= eps * v[i];
  }
  system.residual(0, fplus, fp, rplus);
  system.residual(0, fminus, fp, rminus);
  const Real V = g.cell_volume[centre];
  for (Index i = 0; i < op.size(); ++i) jv[i] = (rplus[i] - rminus[i]) / (2 * eps) + c_j * V * v[i];
  // Only the centre cell's rows: its own block (the neighbours' rows see v through the fluxes).
  std::vector<Real> block_rhs(op.size(), 0.0), z(op.size());
  for (Index k = 0; k < N; ++k) block_rhs[centre * N + k] = jv[centre * N + k];
  system.preconditioner_solve(block_rhs, z);
  Real err = 0, scale = 0;
  for (Index k = 0; k < N; ++k) {
    err = std::max(err, std::abs(z[centre * N + k] - v[centre * N + k]));
    scale = std::max(scale, std::abs(v[centre * N + k]));
  }
  std::printf("cell block inverse: max |P^-1 J v - v| / max |v| = %.2e\n", err / scale);
  EXPECT_LE(err / scale, 1e-6);
}

TEST(TransientKinetic, HeatTransferReachesTheSteadyState) {
  const Real L = 0.01;
  const FaceGraph g = box(1, 12, L);
  const KineticGas gas = KineticGas::argon();
  const VelocityGrid grid = VelocityGrid::uniform(8, 8, 8, 3.5 * gas.thermal_speed(kT0));
  const Real rho0 = gas.density_for_knudsen(0.1, kT0, L);
  auto uniform = [&](const Vec3&) { return GasState{rho0, Vec3::Zero(), kT0}; };

  KineticOperator steady_op(g, grid, gas, heat_transfer_walls(g));
  std::vector<Real> f_steady(steady_op.size());
  steady_op.initialize(f_steady, uniform);
  SequentialOptions options;
  options.tolerance = 1e-11;
  ASSERT_TRUE(solve_sequential(steady_op, f_steady, options).converged);
  steady_op.update_collision(f_steady);

  KineticOperator op(g, grid, gas, heat_transfer_walls(g));
  std::vector<Real> f(op.size()), fp(op.size(), 0.0), r(op.size());
  op.initialize(f, uniform);
  const Real mass0 = op.total_mass(f);
  TransientKineticSystem system(op);
  // Consistent start: f' = -r(f) / V.
  op.residual(f, r);
  for (Index c = 0; c < op.n_cells(); ++c)
    for (Index k = 0; k < op.n_ordinates(); ++k)
      fp[c * op.n_ordinates() + k] = -r[c * op.n_ordinates() + k] / g.cell_volume[c];

  IdaOptions ida;
  ida.linear_solver = IdaOptions::LinearSolver::Spgmr;
  ida.rtol = 1e-7;
  ida.atol = 1e-7 * 1e-3 * rho0 / std::pow(gas.thermal_speed(kT0), 3);
  IdaIntegrator integrator(system, ida);
  integrator.initialize(0, f, fp);
  // Diffusion time L^2 rho c_v / kappa ~ 1e-4 s here; 100 of them.
  const Real t_end = 2e-2;
  ASSERT_EQ(integrator.advance(t_end), IdaIntegrator::Status::Reached);
  const IntegratorStats stats = integrator.stats();

  std::vector<Real> f_end(integrator.y().begin(), integrator.y().end());
  op.update_collision(f_end);
  Real dT = 0, drho = 0;
  for (Index c = 0; c < op.n_cells(); ++c) {
    dT = std::max(dT, std::abs(op.macro(c).T / steady_op.macro(c).T - 1));
    drho = std::max(drho, std::abs(op.macro(c).rho / steady_op.macro(c).rho - 1));
  }
  const Real mass_drift = std::abs(op.total_mass(f_end) / mass0 - 1);
  const Real krylov_per_newton =
      static_cast<Real>(stats.linear_iters) / static_cast<Real>(stats.newton_iters);
  std::printf(
      "transient vs steady: max |dT/T| %.2e, |drho/rho| %.2e, mass drift %.2e; "
      "%ld steps, %ld Newton, %.2f Krylov iterations per Newton, %ld preconditioner "
      "setups\n",
      dT, drho, mass_drift, stats.steps, stats.newton_iters, krylov_per_newton,
      system.preconditioner_setups());
  EXPECT_LE(dT, 1e-5);
  EXPECT_LE(drho, 1e-5);
  EXPECT_LE(mass_drift, 1e-6);
  EXPECT_LE(krylov_per_newton, 10.0);
}

// COMET and the sequential solver converge to the same steady fields.
//
// Heat transfer and lid-driven cavity (test/unit/comet/comet_cases.hpp: argon, ESBGK), 10 x 10
// cells, 8^3 velocities, Kn = 0.1 and (heat transfer) Kn = 1; both solvers to
// ||r|| / ||r_0|| <= 1e-8, from the same initial state. The steady equation of a closed domain
// leaves the mass free; both solvers hold the initial mass (restore_mass), so they solve the
// same problem. Asserted: max |T_c - T_s| <=
// 1e-6 (T_hot - T0) (heat transfer) or 1e-6 T0 (cavity), max |rho_c - rho_s| <= 1e-6 rho0,
// max |u_c - u_s| <= 1e-6 x (10 m/s lid speed, or sqrt(2 R T0) in the heat transfer); both final
// masses equal the initial mass to 1e-12; both converged.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../unit/comet/comet_cases.hpp"
#include "physics/gas/comet/comet_solver.hpp"
#include "physics/gas/kinetic/sequential_solver.hpp"

namespace rfmems {
namespace {

using namespace comet_test;

void compare(Case which, Real kn) {
  auto p = make_problem(which, kn, 10, 8);
  KineticOperator& op = *p->op;
  std::vector<Real> fs = p->f;
  SequentialOptions so;
  so.tolerance = 1e-8;
  const KineticSolveResult rs = solve_sequential(op, fs, so);
  ASSERT_TRUE(rs.converged);

  std::vector<Real> fc = p->f;
  const Real mass = op.total_mass(fc);
  EXPECT_NEAR(op.total_mass(fs), mass, 1e-12 * mass);
  CometOptions co;
  co.tolerance = 1e-8;
  co.sequential_above_knudsen = 0;  // COMET itself at every Kn
  CometSolver comet(op, co);
  const CometResult rc = comet.solve(fc);
  ASSERT_TRUE(rc.converged);
  EXPECT_NEAR(op.total_mass(fc), mass, 1e-12 * mass);

  std::vector<MacroState> ms, mc;
  for (Index c = 0; c < op.n_owned_cells(); ++c) {
    const Index N = op.n_ordinates();
    ms.push_back(moments(std::span<const Real>(fs).subspan(c * N, N), op.grid(), op.gas()));
    mc.push_back(moments(std::span<const Real>(fc).subspan(c * N, N), op.grid(), op.gas()));
  }
  const Real t_scale = which == Case::HeatTransfer ? kTHot - kT0 : kT0;
  const Real u_scale = which == Case::HeatTransfer ? op.gas().thermal_speed(kT0) : kLidSpeed;
  Real dT = 0, drho = 0, du = 0;
  for (std::size_t c = 0; c < ms.size(); ++c) {
    dT = std::max(dT, std::abs(ms[c].T - mc[c].T) / t_scale);
    drho = std::max(drho, std::abs(ms[c].rho - mc[c].rho) / p->rho0);
    du = std::max(du, (ms[c].u - mc[c].u).norm() / u_scale);
  }
  std::printf(
      "Kn %g: sequential %d iterations, COMET %d cycles (%d levels); max diff T %.1e rho "
      "%.1e u %.1e\n",
      kn, rs.iterations, rc.cycles, rc.levels, dT, drho, du);
  EXPECT_LT(dT, 1e-6);
  EXPECT_LT(drho, 1e-6);
  EXPECT_LT(du, 1e-6);
}

TEST(CometVsSequential, HeatTransferKn01) { compare(Case::HeatTransfer, 0.1); }
TEST(CometVsSequential, HeatTransferKn1) { compare(Case::HeatTransfer, 1.0); }
TEST(CometVsSequential, CavityKn01) { compare(Case::Cavity, 0.1); }

}  // namespace
}  // namespace rfmems

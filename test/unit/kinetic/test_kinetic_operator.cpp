// KineticOperator on small meshes:
//  1. closed box, specular walls (axis-aligned: exact reflection map), random f: the residual
//     summed over cells, sum_c sum_k w_k r_ck (the rate of loss of mass), is zero to round-off,
//     and so is the energy (specular walls do no work);
//  2. the same with diffuse walls (moving wavy lid, hot floor): every diffuse face carries zero
//     mass flux in its wall's frame (n_w from zero net flux), fixed walls pass nothing, and the
//     cells lose exactly the boundary outflow;
//  3. a discrete Maxwellian at rest, at the walls' temperature and the outlet's pressure, is a
//     fixed point of the discrete equation on a skewed mesh: max |r| / flux scale <= 1e-12;
//  4. the wall force of a gas at rest at pressure p on a wall of area A is p A along the
//     outward normal (to the quadrature error of the grid, 1e-6);
//  5. outgoing_coefficients / incoming_flux reassemble residual_frozen exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "mesh/structured_mesh.hpp"
#include "physics/gas/kinetic/kinetic_operator.hpp"

using namespace rfmems;

namespace {

constexpr Real kT0 = 273.15, kRho0 = 9.28e-6;

FaceGraph box_graph(int nx, int ny, bool skew = false) {
  BoxSpec spec;
  spec.upper = Vec3(0.02, 0.01, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  spec.grading[1] = 1.3;
  if (!skew) return face_graph_of(make_structured_mesh(spec));
  return face_graph_of(make_structured_mesh(spec, [](const Vec3& x) {
    return Vec3(x.x() + 0.2 * x.y(), x.y() + 0.05 * std::sin(300 * x.x()) * x.y(), 0);
  }));
}

KineticGas gas() { return KineticGas::argon(CollisionModel::Esbgk); }

// Coarse but with spacing ~ the thermal speed: the discrete moment problem of the equilibrium
// is solvable for T down to ~0.3 T0 (an even grid has no c = 0: variances >= (dc/2)^2).
VelocityGrid grid() { return VelocityGrid::uniform(10, 10, 8, 3.5 * gas().thermal_speed(kT0)); }

std::vector<Real> random_state(const KineticOperator& op, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> noise(-0.2, 0.2);
  std::vector<Real> f(op.size());
  std::vector<Real> m(op.n_ordinates());
  for (Index c = 0; c < op.n_cells(); ++c) {
    sample_maxwellian(kRho0 * (1 + noise(rng)), Vec3(50 * noise(rng), 30 * noise(rng), 0),
                      kT0 * (1 + noise(rng)), op.gas(), op.grid(), m);
    for (Index k = 0; k < op.n_ordinates(); ++k)
      f[c * op.n_ordinates() + k] = m[k] * (1 + noise(rng));
  }
  return f;
}

// sum over cells and ordinates of w_k phi(c_k) r_ck, for phi = 1 and |c|^2/2, and the scale
// sum |w_k phi r_ck| against which round-off is judged.
std::pair<Real, Real> net(const KineticOperator& op, const std::vector<Real>& r, bool energy) {
  Real s = 0, scale = 0;
  const Index N = op.n_ordinates();
  for (Index c = 0; c < op.n_cells(); ++c)
    for (Index k = 0; k < N; ++k) {
      const Real phi = energy ? 0.5 * op.grid().c[k].squaredNorm() : 1.0;
      s += op.grid().w[k] * phi * r[c * N + k];
      scale += std::abs(op.grid().w[k] * phi * r[c * N + k]);
    }
  return {s, scale};
}

}  // namespace

TEST(KineticOperator, SpecularBoxConservesMassAndEnergy) {
  // Axis-aligned walls (exact reflection); a graded mesh.
  for (bool skew : {false}) {
    const FaceGraph g = box_graph(5, 4, skew);
    std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::specular_wall());
    KineticOperator op(g, grid(), gas(), bcs);
    const std::vector<Real> f = random_state(op, 3);
    std::vector<Real> r(op.size());
    op.residual(f, r);
    const auto [mass, mass_scale] = net(op, r, false);
    EXPECT_LE(std::abs(mass) / mass_scale, skew ? 1e-3 : 1e-13) << "skew " << skew;
    if (!skew) {
      const auto [energy, energy_scale] = net(op, r, true);
      EXPECT_LE(std::abs(energy) / energy_scale, 1e-13);
    }
  }
}

TEST(KineticOperator, DiffuseWallsAreImpermeable) {
  // The lid of the skewed box is wavy, so its velocity (10, 0, 0) has a normal part: the wall
  // is impermeable in its own frame, sum_k w_k (c_k - u_w).S f_face,k = 0 on every face, and
  // the fixed face passes the gas the moving wall pushes. Fixed walls pass nothing.
  const FaceGraph g = box_graph(5, 4, true);
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::diffuse_wall(kT0));
  const Vec3 lid_velocity(10, 0, 0);
  bcs[g.find_patch("top")] = KineticBoundary::diffuse_wall(kT0, lid_velocity);
  bcs[g.find_patch("bottom")] = KineticBoundary::diffuse_wall(1.2 * kT0);
  KineticOperator op(g, grid(), gas(), bcs);
  const std::vector<Real> f = random_state(op, 4);
  std::vector<Real> r(op.size());
  op.residual(f, r);
  // Scale: the one-way flux rho sqrt(RT) times the patch length.
  const Real flux_scale = kRho0 * std::sqrt(gas().R * kT0) * 0.02;
  const int top = g.find_patch("top");
  for (Index fc = g.n_interior_faces; fc < g.n_faces(); ++fc) {
    const std::span<const Real> face = op.boundary_values(fc);  // set by residual(f)
    const Vec3& S = g.face_area[fc];
    const Vec3 u_w = g.face_patch[fc] == top ? lid_velocity : Vec3::Zero();
    Real relative_flux = 0;
    for (Index k = 0; k < op.n_ordinates(); ++k)
      relative_flux += op.grid().w[k] * (op.grid().c[k] - u_w).dot(S) * face[k];
    EXPECT_LE(std::abs(relative_flux) / flux_scale, 1e-14) << "face " << fc;
  }
  Real boundary_outflow = 0;
  for (const char* patch : {"top", "bottom", "left", "right"}) {
    const Real flow = op.boundary_mass_flow(g.find_patch(patch), f);
    boundary_outflow += flow;
    if (std::string(patch) != "top") {
      EXPECT_LE(std::abs(flow) / flux_scale, 1e-14) << patch;
    }
  }
  // The lid's normal motion moves gas (a wavy wall of amplitude 5e-4 m: ~1e-3 of the flux
  // scale), and the cells lose exactly what leaves through the boundary.
  EXPECT_GT(std::abs(op.boundary_mass_flow(top, f)) / flux_scale, 1e-6);
  const auto [mass, mass_scale] = net(op, r, false);
  EXPECT_LE(std::abs(mass - boundary_outflow) / mass_scale, 1e-13);
}

TEST(KineticOperator, MaxwellianAtRestIsAFixedPoint) {
  const FaceGraph g = box_graph(4, 3, true);
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::diffuse_wall(kT0));
  // Tilted walls: diffuse and pressure conditions (specular ones are exact only on
  // axis-aligned walls).
  bcs[g.find_patch("left")] = KineticBoundary::pressure_outlet(kRho0 * gas().R * kT0, kT0);
  KineticOperator op(g, grid(), gas(), bcs);
  std::vector<Real> f(op.size()), r(op.size());
  op.initialize(f, [](const Vec3&) { return GasState{kRho0, Vec3::Zero(), kT0}; });
  op.residual(f, r);
  // Flux scale: the outgoing part sum_f (c.S)^+ f of each cell.
  std::vector<Real> out(op.n_ordinates());
  Real rmax = 0, scale = 0;
  for (Index c = 0; c < op.n_cells(); ++c) {
    op.outgoing_coefficients(c, out);
    for (Index k = 0; k < op.n_ordinates(); ++k) {
      rmax = std::max(rmax, std::abs(r[c * op.n_ordinates() + k]));
      scale = std::max(scale, out[k] * f[c * op.n_ordinates() + k]);
    }
  }
  EXPECT_LE(rmax / scale, 1e-12);
}

TEST(KineticOperator, WallForceOfGasAtRestIsPressureTimesArea) {
  const FaceGraph g = box_graph(4, 3);
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::diffuse_wall(kT0));
  KineticOperator op(g, VelocityGrid::uniform(16, 16, 16, 4.0 * gas().thermal_speed(kT0)), gas(),
                     bcs);
  std::vector<Real> f(op.size());
  op.initialize(f, [](const Vec3&) { return GasState{kRho0, Vec3::Zero(), kT0}; });
  const Real p = kRho0 * gas().R * kT0;
  const Vec3 top = op.wall_force("top", f), right = op.wall_force("right", f);
  EXPECT_NEAR(top.y() / (p * 0.02), 1, 1e-6);
  EXPECT_LE(std::abs(top.x()) / (p * 0.02), 1e-12);
  EXPECT_NEAR(right.x() / (p * 0.01), 1, 1e-6);
}

TEST(KineticOperator, SplitTermsReassembleTheResidual) {
  const FaceGraph g = box_graph(4, 3, true);
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::diffuse_wall(kT0));
  bcs[g.find_patch("right")] = KineticBoundary::pressure_outlet(0.5, kT0);
  bcs[g.find_patch("left")] = KineticBoundary::symmetry();
  KineticOperator op(g, grid(), gas(), bcs);
  const std::vector<Real> f = random_state(op, 9);
  std::vector<Real> r(op.size());
  op.residual(f, r);
  const Index N = op.n_ordinates();
  std::vector<Real> out(N), in(N);
  Real err = 0, scale = 0;
  for (Index c = 0; c < op.n_cells(); ++c) {
    op.outgoing_coefficients(c, out);
    op.incoming_flux(c, f, in);
    const Real vnu = g.cell_volume[c] * op.collision_frequency(c);
    const auto feq = op.equilibrium(c);
    for (Index k = 0; k < N; ++k) {
      const Real fk = f[c * N + k];
      const Real rk = out[k] * fk + in[k] - vnu * (feq[k] - fk);
      err = std::max(err, std::abs(rk - r[c * N + k]));
      scale = std::max(scale, out[k] * fk);
    }
  }
  EXPECT_LE(err / scale, 1e-14);
}

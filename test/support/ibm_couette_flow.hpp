// Couette flow through the immersed boundary against the body-fitted solver on the same rows
// (the helpers of test/regression/test_ibm_couette.cpp, test_ibm_couette_second_order.cpp and
// test/study/test_ibm_couette_study.cpp; the set-up is described there), with first- or
// second-order transport in both.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/process_cpu_clock.hpp"
#include "ibm/immersed_kinetic_gas.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/gas/kinetic/sequential_solver.hpp"

namespace rfmems::test {

constexpr Real T0 = 273.15, U = 10, H = 1, theta = 0.4;
constexpr int columns = 4;

struct Profile {
  std::vector<Real> u;        // u_z of rows 0..m-1 (column 0 for the IBM)
  Real plate_shear = 0;       // z-force of the gas on the plate, N/m
  Real fixed_wall_shear = 0;  // on the wall at y = 0
  int iterations = 0;
  bool converged = false;
  double cpu = 0;  // CPU seconds of the run (set-up and solve)
};

inline VelocityGrid velocities(const KineticGas& gas, int nv) {
  return VelocityGrid::uniform(nv, nv, nv, 3.5 * gas.thermal_speed(T0));
}

inline SequentialOptions solver_options() {
  SequentialOptions o;
  o.tolerance = 1e-8;
  return o;
}

inline TransportScheme transport(TransportOrder order) {
  TransportScheme s;
  s.order = order;
  return s;
}

inline Profile body_fitted(Real kn, int m, int nv,
                           TransportOrder order = TransportOrder::FirstOrder) {
  const double t0 = process_cpu_seconds();
  const Real h = H / (m + theta), W = columns * h;
  BoxSpec spec;
  spec.upper = Vec3(W, m + 1, 0);
  // Second order: `columns` columns, so the LS stencils span the plane (one column's
  // neighbours are in line: no gradient, first order, in every cell).
  const int nx = order == TransportOrder::SecondOrder ? columns : 1;
  spec.n[0] = nx;
  spec.n[1] = m + 1;
  const Mesh mesh = make_structured_mesh(spec, [&](const Vec3& x) {
    return Vec3(x.x(), (x.y() < m + 0.5 ? x.y() : m + theta) * h, 0);
  });
  const FaceGraph g = face_graph_of(mesh);
  const KineticGas gas = KineticGas::argon();
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::specular_wall());
  bcs[g.find_patch("bottom")] = KineticBoundary::diffuse_wall(T0);
  bcs[g.find_patch("top")] = KineticBoundary::diffuse_wall(T0, Vec3(0, 0, U));
  KineticOperator op(g, velocities(gas, nv), gas, bcs);
  op.set_transport(transport(order));
  std::vector<Real> f(op.size());
  const Real rho = gas.density_for_knudsen(kn, T0, H);
  op.initialize(f, [&](const Vec3& x) { return GasState{rho, Vec3(0, 0, U * x.y() / H), T0}; });
  const KineticSolveResult r = solve_sequential(op, f, solver_options());
  Profile p;
  for (Index c = 0; c < nx * m; c += nx) p.u.push_back(op.macro(c).u.z());  // column 0
  p.plate_shear = op.wall_force("top", f).z();
  p.fixed_wall_shear = op.wall_force("bottom", f).z();
  p.iterations = r.iterations;
  p.converged = r.converged;
  p.cpu = process_cpu_seconds() - t0;
  return p;
}

inline Profile immersed(Real kn, int m, int nv, TransportOrder order = TransportOrder::FirstOrder) {
  const double t0 = process_cpu_seconds();
  const Real h = H / (m + theta), W = columns * h;
  BoxSpec spec;
  spec.upper = Vec3(W, (m + 2) * h, 0);
  spec.n[0] = columns;
  spec.n[1] = m + 2;
  const Mesh mesh = make_structured_mesh(spec);
  const FaceGraph g = face_graph_of(mesh);
  const KineticGas gas = KineticGas::argon();
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::specular_wall());
  bcs[g.find_patch("bottom")] = KineticBoundary::diffuse_wall(T0);
  ImmersedGasOptions o;
  o.ib.wall_temperature = T0;
  o.transport = transport(order);
  ImmersedKineticGas ibm(mesh, bcs, velocities(gas, nv), gas, o);
  // Segments of length h along the lower surface, reaching 2 h past each side.
  const ImmersedSurface plate =
      ImmersedSurface::rectangle({-2 * h, H, 0}, {W + 2 * h, (m + 6) * h, 0}, columns + 4, 4);
  ibm.set_body(plate, std::vector<Vec3>(plate.n_segments(), Vec3(0, 0, U)));
  const Real rho = gas.density_for_knudsen(kn, T0, H);
  ibm.initialize({rho, Vec3::Zero(), T0});
  EXPECT_EQ(ibm.kinetic().n_cells(), columns * m);
  const KineticSolveResult r = ibm.solve_steady(solver_options());
  Profile p;
  const KineticOperator& op = ibm.kinetic();
  for (Index c = 0; c < op.n_cells(); ++c) {
    const Index b = ibm.fluid().background_cell[c];
    if (b % columns == 0) p.u.push_back(op.macro(c).u.z());  // column 0, rows in order
  }
  for (const Vec3& F : ibm.segment_forces()) p.plate_shear += F.z();
  Real worst_factor = 0;
  for (Real a : ibm.face_values().flux_factors())
    worst_factor = std::max(worst_factor, std::abs(a - 1));
  std::printf(
      "   IBM: %lld one-sided of %lld step-(iii) fits, largest |a_i - 1| %.2e\n",
      static_cast<long long>(ibm.face_values().count_one_sided()),
      static_cast<long long>(ibm.face_values().n_ordinate_groups() * ibm.marking().ib_faces.size()),
      worst_factor);
  p.fixed_wall_shear = op.wall_force("bottom", ibm.distribution()).z();
  p.iterations = r.iterations;
  p.converged = r.converged;
  p.cpu = process_cpu_seconds() - t0;
  return p;
}

struct Comparison {
  Real profile = 0, shear = 0, balance = 0;
  Real ib_shear = 0, bf_shear = 0;            // N/m
  Real ib_slip_error = 0, bf_slip_error = 0;  // max |u - u_slip| / U over rows 0..m-1
  Real tau = 0;                               // slip theory's shear force, N/m
  std::vector<Real> ib_at, bf_at;             // u at y / H = 0.1, ..., 0.9
  Profile ib, bf;
};

// Linear interpolation of cell-centre values (rows at (i + 1/2) h) at y.
inline Real at(const std::vector<Real>& u, Real h, Real y) {
  const Real s = y / h - 0.5;
  const int i = std::clamp(static_cast<int>(std::floor(s)), 0, static_cast<int>(u.size()) - 2);
  return u[i] + (s - i) * (u[i + 1] - u[i]);
}

// First-order slip solution u = U (y / H + Kn) / (1 + 2 Kn) and its shear per width W.
inline Real slip_velocity(Real kn, Real y) { return U * (y / H + kn) / (1 + 2 * kn); }

inline Comparison compare(Real kn, int m, int nv,
                          TransportOrder order = TransportOrder::FirstOrder) {
  const Profile bf = body_fitted(kn, m, nv, order), ib = immersed(kn, m, nv, order);
  EXPECT_TRUE(bf.converged);
  EXPECT_TRUE(ib.converged);
  Comparison c;
  c.ib = ib;
  c.bf = bf;
  for (int i = 0; i < m; ++i) c.profile = std::max(c.profile, std::abs(ib.u[i] - bf.u[i]) / U);
  // Body-fitted: one column of width W; IBM: `columns` columns, the same width W.
  c.shear = ib.plate_shear / bf.plate_shear - 1;
  c.balance = std::abs(ib.plate_shear + ib.fixed_wall_shear) / std::abs(ib.plate_shear);
  c.ib_shear = ib.plate_shear;
  c.bf_shear = bf.plate_shear;
  const Real h = H / (m + theta);
  for (int i = 0; i < m; ++i) {
    const Real us = slip_velocity(kn, (i + 0.5) * h);
    c.ib_slip_error = std::max(c.ib_slip_error, std::abs(ib.u[i] - us) / U);
    c.bf_slip_error = std::max(c.bf_slip_error, std::abs(bf.u[i] - us) / U);
  }
  const KineticGas gas = KineticGas::argon();
  const Real tau = gas.viscosity(T0) * U / (H * (1 + 2 * kn)) * columns * h;
  c.tau = tau;
  for (int j = 1; j <= 9; ++j) {
    c.ib_at.push_back(at(ib.u, h, 0.1 * j * H));
    c.bf_at.push_back(at(bf.u, h, 0.1 * j * H));
  }
  std::printf(
      "   vs slip theory: profile IBM %.3e, body-fitted %.3e; shear IBM %+.3e, "
      "body-fitted %+.3e\n",
      c.ib_slip_error, c.bf_slip_error, -ib.plate_shear / tau - 1, -bf.plate_shear / tau - 1);
  std::printf(
      "%s, Kn = %.2f, m = %2d: max |du| / U = %.3e, shear IBM %.5e vs body-fitted %.5e N/m "
      "(%+.3e), IBM balance %.1e; sweeps IBM %d, body-fitted %d\n",
      transport_order_name(order), kn, m, c.profile, ib.plate_shear, bf.plate_shear, c.shear,
      c.balance, ib.iterations, bf.iterations);
  return c;
}

// First-order Richardson extrapolation of two runs (h ratio r = h_coarse / h_fine): shear
// per slip-theory shear, and the profiles at y / H = 0.1 .. 0.9; the largest IBM vs body-fitted
// difference of each.
struct Extrapolated {
  Real shear = 0, profile = 0;
};
inline Extrapolated extrapolate(const Comparison& coarse, const Comparison& fine, Real r) {
  auto ex = [r](Real c, Real f) { return (r * f - c) / (r - 1); };
  Extrapolated e;
  const Real ib = ex(coarse.ib_shear / coarse.tau, fine.ib_shear / fine.tau);
  const Real bf = ex(coarse.bf_shear / coarse.tau, fine.bf_shear / fine.tau);
  e.shear = ib / bf - 1;
  for (std::size_t j = 0; j < fine.ib_at.size(); ++j)
    e.profile = std::max(
        e.profile,
        std::abs(ex(coarse.ib_at[j], fine.ib_at[j]) - ex(coarse.bf_at[j], fine.bf_at[j])) / U);
  std::printf(
      "extrapolated (first order): shear IBM / body-fitted - 1 = %+.3e (IBM %.4f, "
      "body-fitted %.4f of slip theory), largest profile difference %.3e U\n",
      e.shear, -ib, -bf, e.profile);
  return e;
}

inline Real h_ratio(int m_coarse, int m_fine) { return (m_fine + theta) / (m_coarse + theta); }

}  // namespace rfmems::test

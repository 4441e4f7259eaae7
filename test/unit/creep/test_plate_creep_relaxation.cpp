// Creep relaxation of a plate's residual stress (physics/creep/plate_creep_system.hpp,
// "Relaxation of the residual stress"): the creep law acts on sigma0 + C (z kappa - eps_p),
// and the relaxed membrane force N = h sigma0 - C int eps_p dz replaces h sigma0 in the
// geometric stiffness.
//   - A flat plate held on all edges under an equibiaxial sigma0 relaxes uniformly as the
//     closed form of equibiaxial plane stress.
//   - A prestressed clamped strip under a constant pressure sags more as its tension relaxes,
//     between the static plate and the static membrane with the relaxed stress.
//   - The analytic Jacobian (the q rows at the new stress, the w rows' new dependence on the
//     plastic strains and the q-dependent w-w block) against central differences on the
//     distorted mesh, and a planted 1 % error in either new part is caught.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "../../support/clamped_rectangle.hpp"
#include "../../support/distorted_plate.hpp"
#include "../../support/jacobian_check.hpp"
#include "../../support/plate_creep_state.hpp"
#include "../../support/relaxing_film.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/creep/plate_creep_system.hpp"
#include "solvers/ida_integrator.hpp"
#include "solvers/klu_factorization.hpp"

using namespace rfmems;
using namespace rfmems::test;
using Kind = PlateBoundary::Kind;

namespace {

// The static sag (-w) at the centre cell of a plate of this section under pressure q.
Real static_centre_deflection(const Mesh& mesh, const PlateSection& section, Real q, Index centre) {
  PlateOperator plate(mesh, section, all_clamped(mesh), [q](const Vec3&, Real) { return q; });
  const std::vector<Real> zero(plate.size(), 0.0);
  std::vector<Real> r(plate.size()), k(plate.stiffness_pattern().nnz());
  plate.internal_residual(0, zero, r);
  plate.stiffness(0, zero, k);
  KluFactorization lu(plate.stiffness_pattern(), k);
  lu.solve(r);
  return r[3 * centre + PlateOperator::kW];  // the sag -w
}

Index nearest_cell(const Mesh& mesh, const Vec3& x) {
  Index best = 0;
  for (Index c = 1; c < mesh.n_cells(); ++c)
    if ((mesh.cell_centroid(c) - x).norm() < (mesh.cell_centroid(best) - x).norm()) best = c;
  return best;
}

}  // namespace

// Clamped all round, no load, sigma0 = 100 MPa equibiaxial: the plate stays flat and every
// cell's membrane force N = h sigma relaxes by the closed form, for a linear (m = 1) and a
// power law (m = 3). IDA at rtol 1e-8, with KLU and with SPGMR on the Schur-complement solve.
TEST(PlateCreepRelaxation, UniformFilmRelaxesAsTheEquibiaxialClosedForm) {
  const Real h = 1e-6, sigma0 = 100e6;
  const Mesh mesh = rectangle(100e-6, 80e-6, 5, 4);
  const PlateSection section = relaxing_film(h, sigma0);
  using Solver = IdaOptions::LinearSolver;
  for (auto [m, solver] : {std::pair{1.0, Solver::Direct}, std::pair{3.0, Solver::Direct},
                           std::pair{1.0, Solver::Spgmr}, std::pair{3.0, Solver::Spgmr}}) {
    PlateOperator plate(mesh, section, all_clamped(mesh));
    const CreepLaw law{1e-6, 0, m, 0, 100e6};  // time scale 2 (1-nu) sigma_y/(E A) = 900 s
    PlateCreepSystem system(plate, law, 6);
    ASSERT_TRUE(system.relaxes_membrane());
    ASSERT_TRUE(system.has_preconditioner());
    std::vector<Real> y, yp;
    system.initial_state(0, y, yp);
    IdaOptions options;
    options.rtol = 1e-8;
    options.atol = 1e-14;  // strains ~ 1e-4, deflections (zero) against h = 1e-6 m
    options.linear_solver = solver;
    IdaIntegrator ida(system, options);
    ida.initialize(0, y, yp);
    Real worst = 0, max_w = 0;
    for (Real t : {300.0, 900.0, 2700.0}) {
      ASSERT_NO_THROW(ida.advance(t));
      const std::span<const Real> state = ida.y();
      const Real exact = equibiaxial_relaxation(law, section.E, section.nu, sigma0, t);
      for (const Vec3& n : system.membrane_forces(state)) {
        worst = std::max(
            {worst, std::abs(n[0] / h - exact) / exact, std::abs(n[1] / h - exact) / exact});
        EXPECT_LT(std::abs(n[2]), 1e-12 * n[0]);
      }
      for (Index c = 0; c < mesh.n_cells(); ++c)
        max_w = std::max(max_w, std::abs(state[3 * c + PlateOperator::kW]));
      std::printf("m = %g, t = %g s: sigma/sigma0 %.8f (closed form %.8f)\n", m, t,
                  system.membrane_forces(state)[0][0] / (h * sigma0), exact / sigma0);
    }
    std::printf("m = %g, %s: worst relative error of N/h %.2e, max |w| %.2e m, %ld steps\n", m,
                solver == Solver::Direct ? "KLU" : "SPGMR", worst, max_w, ida.stats().steps);
    EXPECT_LT(worst, 2e-6);      // IDA's global error at rtol 1e-8
    EXPECT_LT(max_w, 1e-9 * h);  // flat to round-off (sum_i w_i z_i of Simpson's rule)
    // The relaxation is real: at t = 2700 s the stress is 0.05 (m = 1) or 0.38 (m = 3) of sigma0.
    EXPECT_LT(system.membrane_forces(ida.y())[0][0], 0.4 * h * sigma0);
  }
}

// A strip clamped all round (400 x 100 um, h = 0.2 um, sigma0 = 100 MPa: N W^2/D ~ 1700, the
// tension carries most of the load) under a constant pressure. With a linear law (m = 1,
// B = 0) the flow rule is linear in the stress, so the bending part of eps_p (odd in z) adds
// nothing to int eps_p dz: N relaxes uniformly by the closed form whatever the load, and the
// creep plate at t is the static plate with sigma(t) plus its own bending creep. Bending creep
// relaxes the moments, softening the plate towards the pure membrane with the same tension, so
//   w_static(sigma(t)) <= w_creep(t) <= w_membrane(sigma(t)),
// w_membrane the static deflection with the bending stiffness taken away (E / 1e4 at the same
// sigma: N W^2 / D ~ 1.7e7). The bounds are 6 % (t = tau/4) to 12.5 % (t = tau) of w apart,
// while w itself grows by 2.6x over the run as the tension relaxes to sigma0/e (measured: w
// 17 %, 26 %, 35 % of the way from the static plate to the membrane at tau/4, tau/2, tau).
TEST(PlateCreepRelaxation, ClampedStripSagsAsItsTensionRelaxes) {
  const Real h = 0.2e-6, sigma0 = 100e6, q = -100;
  const Mesh mesh = rectangle(400e-6, 100e-6, 24, 8);
  const Index centre = nearest_cell(mesh, Vec3(200e-6, 50e-6, 0));
  const PlateSection section = relaxing_film(h, sigma0);
  PlateOperator plate(mesh, section, all_clamped(mesh), [q](const Vec3&, Real) { return q; });
  const CreepLaw law{1e-6, 0, 1, 0, 100e6};
  const Real tau = 2 * (1 - section.nu) * law.sigma_y0 / (section.E * law.A);  // 900 s
  // KLU, and SPGMR on the Schur-complement solve (whose S then holds the relaxation's w-w part
  // and P_m D^-1 G at nonzero slopes): the same sags to IDA's tolerance.
  using Solver = IdaOptions::LinearSolver;
  std::vector<Real> final_sag;
  for (Solver solver : {Solver::Direct, Solver::Spgmr}) {
    PlateCreepSystem system(plate, law, 4);
    std::vector<Real> y, yp;
    system.initial_state(0, y, yp);
    IdaOptions options;
    options.linear_solver = solver;
    options.rtol = 1e-7;
    options.atol = 1e-15;
    IdaIntegrator ida(system, options);
    ida.initialize(0, y, yp);
    const Real w0 = -y[3 * centre];
    EXPECT_NEAR(w0, static_centre_deflection(mesh, section, q, centre), 1e-10 * w0);
    Real previous = w0;
    for (Real t : {0.25 * tau, 0.5 * tau, tau}) {
      ASSERT_NO_THROW(ida.advance(t));
      const std::span<const Real> state = ida.y();
      const Real sigma = equibiaxial_relaxation(law, section.E, section.nu, sigma0, t);
      for (const Vec3& n : system.membrane_forces(state))
        EXPECT_NEAR(n[0] / h, sigma, 1e-5 * sigma);
      PlateSection relaxed = relaxing_film(h, sigma), membrane = relaxing_film(h, sigma);
      membrane.E *= 1e-4;
      const Real w = -state[3 * centre],
                 w_static = static_centre_deflection(mesh, relaxed, q, centre),
                 w_membrane = static_centre_deflection(mesh, membrane, q, centre);
      std::printf(
          "t = %.0f s: sigma/sigma0 %.4f, w %.5e m (w/w0 %.4f), static %.5e, membrane %.5e: "
          "(w - static)/(membrane - static) = %.3f\n",
          t, sigma / sigma0, w, w / w0, w_static, w_membrane,
          (w - w_static) / (w_membrane - w_static));
      EXPECT_GT(w, previous);
      EXPECT_GE(w, w_static);
      EXPECT_LE(w, w_membrane);
      previous = w;
    }
    EXPECT_GT(previous, 2 * w0);  // the tension at sigma0/e: the sag more than doubles
    std::printf("%s: %ld steps\n", solver == Solver::Direct ? "KLU" : "SPGMR", ida.stats().steps);
    final_sag.push_back(previous);
  }
  EXPECT_NEAR(final_sag[1], final_sag[0], 1e-5 * final_sag[0]);
}

namespace {

// check_jacobian's entry-relative measure for given analytic values, over the w rows (where
// the relaxation enters the balances) or the q rows (the rates at sigma0 + C (z kappa - eps_p)).
Real max_entry_relative(PlateCreepSystem& system, Real c_j, const test::PlateCreepState& s,
                        const std::vector<Real>& values, bool w_rows) {
  const CsrPattern& pattern = system.jacobian_pattern();
  std::vector<Real> row_scaled(system.size(), 0.0);
  for (Index i = 0; i < system.size(); ++i)
    for (Index p = pattern.row_ptr[i]; p < pattern.row_ptr[i + 1]; ++p)
      row_scaled[i] = std::max(row_scaled[i], std::abs(values[p]) * s.scales[pattern.col_idx[p]]);
  Real worst = 0;
  test_support::for_each_jacobian_entry(
      system, 0.3, c_j, s.y, s.yp, s.steps, values, [&](Index i, Index j, Real fd, Real analytic) {
        const bool w_row = i < system.structural_size() && i % 3 == PlateOperator::kW;
        if (w_rows ? !w_row : i < system.structural_size()) return;
        const Real d = std::abs(fd - analytic) * s.scales[j];
        worst =
            std::max(worst, d / (std::abs(analytic) * s.scales[j] + 1e-6 * row_scaled[i] + 1e-300));
      });
  return worst;
}

PlateSection thick_section() {
  PlateSection s;
  s.E = 200e9;
  s.nu = 0.3;
  s.rho = 7854;
  s.thickness = 0.05;
  // Of the bending stress of the random state (~1e8 Pa), not symmetric in xx, yy.
  s.residual_stress << 8e7, 2e7, 0, 2e7, 5e7, 0, 0, 0, 0;
  return s;
}

}  // namespace

// The distorted mesh with clamped, hard simply supported, free and loaded edges (the free and
// loaded edges carry no membrane force: not in the relaxation's faces).
TEST(PlateCreepRelaxation, JacobianMatchesFiniteDifferencesAndCatchesAPlantedError) {
  const Mesh mesh = distorted_mesh(7, 5, 4);
  PlateOperator plate(mesh, thick_section(), mixed_boundaries(mesh),
                      [](const Vec3& x, Real) { return -1e4 * (1 + x.y()); });
  for (bool shear : {false, true}) {
    PlateCreepSystem system(plate, CreepLaw{1e-3, 3e3, 2.5, 1.5, 1e9}, 6, shear);
    ASSERT_TRUE(system.relaxes_membrane());
    const test::PlateCreepState s = test::random_plate_creep_state(system, 7);
    const Index ns = system.structural_size();
    const CsrPattern& pattern = system.jacobian_pattern();
    // The relaxed membrane force is a sizeable change of N at this state.
    Real dn = 0;
    for (const Vec3& n : system.membrane_forces(s.y))
      dn = std::max(dn, (n - thick_section().thickness * Vec3(8e7, 5e7, 2e7)).norm());
    EXPECT_GT(dn, 0.05 * thick_section().thickness * 8e7);
    for (Real c_j : {0.0, 2.5e2}) {
      const auto check =
          test_support::check_jacobian(system, 0.3, c_j, s.y, s.yp, s.steps, s.scales);
      std::printf("shear creep %d, c_j %g: entry-relative %.2e, row-relative %.2e\n", shear, c_j,
                  check.max_entry_relative, check.max_row_relative);
      EXPECT_LT(check.max_entry_relative, 1e-3)
          << "c_j " << c_j << " row " << check.worst_entry_row << " col " << check.worst_entry_col;
      EXPECT_LT(check.max_row_relative, 1e-6) << "c_j " << c_j << " row " << check.worst_row;
    }
    if (shear) continue;
    // Planted errors (c_j = 0): 1 % on dF_w/d eps_p (entries the relaxation alone creates),
    // 1 % of the relaxation's part of the w-w block (the Jacobian at the state minus that at
    // the same state without plastic strain), 1 % on the q rows' rotation columns.
    const std::vector<Real> exact = test_support::analytic_jacobian(system, 0.3, 0, s.y, s.yp);
    std::vector<Real> no_creep = s.y;
    for (Index k = ns; k < system.size(); ++k) no_creep[k] = 0;
    const std::vector<Real> base = test_support::analytic_jacobian(system, 0.3, 0, no_creep, s.yp);
    std::vector<Real> wq = exact, ww = exact, qy = exact;
    for (Index i = ns; i < system.size(); ++i)
      for (Index p = pattern.row_ptr[i]; p < pattern.row_ptr[i + 1]; ++p)
        if (pattern.col_idx[p] < ns) qy[p] *= 1.01;
    Index n_wq = 0, n_ww = 0;
    for (Index i = 0; i < ns; i += 3)
      for (Index p = pattern.row_ptr[i]; p < pattern.row_ptr[i + 1]; ++p) {
        const Index j = pattern.col_idx[p];
        if (j >= ns && (j - ns) % 4 < 3) {
          wq[p] *= 1.01;
          n_wq += exact[p] != 0;
        } else if (j < ns && j % 3 == 0) {
          ww[p] += 0.01 * (exact[p] - base[p]);
          n_ww += exact[p] != base[p];
        }
      }
    EXPECT_GT(n_wq, 0);
    EXPECT_GT(n_ww, 0);
    const Real clean = max_entry_relative(system, 0, s, exact, true),
               planted_wq = max_entry_relative(system, 0, s, wq, true),
               planted_ww = max_entry_relative(system, 0, s, ww, true),
               clean_q = max_entry_relative(system, 0, s, exact, false),
               planted_qy = max_entry_relative(system, 0, s, qy, false);
    std::printf(
        "w rows' entry-relative: exact %.2e, 1 %% on dF_w/deps_p %.2e, 1 %% of the relaxed w-w "
        "%.2e\n",
        clean, planted_wq, planted_ww);
    std::printf("q rows' entry-relative: exact %.2e, 1 %% on dF_q/dbeta %.2e\n", clean_q,
                planted_qy);
    EXPECT_LT(clean_q, 1e-3);
    EXPECT_GT(planted_qy, 5e-3);
    EXPECT_LT(clean, 1e-4);
    EXPECT_GT(planted_wq, 5e-3);
    EXPECT_GT(planted_ww, 5e-3);
  }
}

// initial_state from a state with plastic strain: the plate is in equilibrium with the relaxed
// membrane force (the tangent of equilibrate holds its w-w part), and y' keeps it so to first
// order: F_y(y + d y', q + d q') = O(d^2).
TEST(PlateCreepRelaxation, InitialStateIsConsistentWithTheRelaxedMembraneForce) {
  const Mesh mesh = distorted_mesh(6, 4, 9);
  PlateOperator plate(mesh, thick_section(), mixed_boundaries(mesh),
                      [](const Vec3&, Real) { return -3e5; });
  PlateCreepSystem system(plate, CreepLaw{1e-3, 3e3, 2.0, 2.0, 1e9}, 4);
  test::PlateCreepState s = test::random_plate_creep_state(system, 3);
  const Index ns = system.structural_size();
  std::vector<Real> state = s.y, state_dot;
  for (Index k = 0; k < ns; ++k) state[k] = 0;
  system.initial_state(0, state, state_dot);
  std::vector<Real> r(system.size());
  system.residual(0, state, state_dot, r);
  const Real force_scale = 3e5 * 2.0 * 1.2;
  Real worst = 0;
  for (Real v : r) worst = std::max(worst, std::abs(v));
  EXPECT_LT(worst, 1e-9 * force_scale);
  auto drift = [&](Real d) {
    return test_support::drift_along_derivative(system, 0.0, state, state_dot, ns, d);
  };
  // Measured on the time scale of the rates: d = 1e-3 / max |q'|.
  Real rate = 0;
  for (Index k = ns; k < system.size(); ++k) rate = std::max(rate, std::abs(state_dot[k]));
  const Real d = 1e-3 / rate, r1 = drift(d), r2 = drift(d / 2);
  std::printf("F_y drift: %.3e at d, %.3e at d/2 (ratio %.2f)\n", r1, r2, r1 / r2);
  EXPECT_GT(r1 / r2, 3.5);  // second order: 4
}

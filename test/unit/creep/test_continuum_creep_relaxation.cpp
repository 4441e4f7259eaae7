// Creep relaxation of the residual stress in the continuum (physics/creep/
// continuum_creep_system.hpp, "Relaxation of the residual stress"): the creep law acts on
// sigma0 + C (eps - eps_p) and the geometric stiffness's prestress relaxes to sigma0 - C eps_p.
//   - A plane-stress square held by symmetry planes under an equibiaxial sigma0 stays at rest
//     and its prestress relaxes as the closed form of equibiaxial plane stress.
//   - The analytic Jacobian against central differences in plane stress, plane strain and 3D
//     on distorted meshes with fixed, symmetry and loaded faces; a planted 1 % error in the
//     relaxation's u-q or u-u entries is caught; initial_state is consistent.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "../../support/creep_continuum_fixture.hpp"
#include "../../support/jacobian_check.hpp"
#include "../../support/relaxing_film.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/creep/continuum_creep_system.hpp"
#include "solvers/ida_integrator.hpp"

using namespace rfmems;
using Kind = ElasticityBoundary::Kind;

namespace {

// A residual stress of the size of the random state's stresses (~1e8 Pa), every component.
LinearElastic prestressed_steel(Hypothesis h, int dim) {
  LinearElastic m{200e9, 0.3, 7854, h};
  if (dim == 3)
    m.residual_stress << 8e7, 2e7, -1e7, 2e7, 5e7, 3e7, -1e7, 3e7, 4e7;
  else
    m.residual_stress << 8e7, 2e7, 0, 2e7, 5e7, 0, 0, 0, 0;
  return m;
}

// check_jacobian's entry-relative measure for given analytic values over the u rows.
Real max_entry_relative_u_rows(ContinuumCreepSystem& system, const std::vector<Real>& y,
                               const std::vector<Real>& yp, const std::vector<Real>& steps,
                               const std::vector<Real>& scales, const std::vector<Real>& values) {
  const CsrPattern& pattern = system.jacobian_pattern();
  const Index ns = system.structural_size();
  std::vector<Real> row_scaled(ns, 0.0);
  for (Index i = 0; i < ns; ++i)
    for (Index p = pattern.row_ptr[i]; p < pattern.row_ptr[i + 1]; ++p)
      row_scaled[i] = std::max(row_scaled[i], std::abs(values[p]) * scales[pattern.col_idx[p]]);
  Real worst = 0;
  test_support::for_each_jacobian_entry(
      system, 0.3, 0.0, y, yp, steps, values, [&](Index i, Index j, Real fd, Real analytic) {
        if (i >= ns) return;
        const Real d = std::abs(fd - analytic) * scales[j];
        worst =
            std::max(worst, d / (std::abs(analytic) * scales[j] + 1e-6 * row_scaled[i] + 1e-300));
      });
  return worst;
}

// The relaxation's part of the u-u block, delta = dF_u/du (y) - dF_u/du (y without plastic
// strain) in the pattern, against central differences of F_u(y) - F_u(y without plastic
// strain) (the elastic part cancels exactly, the plastic source is constant in u): the largest
// difference over the largest entry of delta. The relaxation is ~1e-4 of the elastic entries
// (C eps_p against C), below what the whole Jacobian's check resolves.
Real relaxed_uu_error(ContinuumCreepSystem& system, const std::vector<Real>& y,
                      const std::vector<Real>& no_creep, const std::vector<Real>& steps,
                      const std::vector<Real>& delta) {
  const CsrPattern& pattern = system.jacobian_pattern();
  const Index ns = system.structural_size(), n = system.size();
  const std::vector<Real> yp(n, 0.0);
  Real largest = 0, worst = 0;
  for (Index i = 0; i < ns; ++i)
    for (Index p = pattern.row_ptr[i]; p < pattern.row_ptr[i + 1]; ++p)
      if (pattern.col_idx[p] < ns) largest = std::max(largest, std::abs(delta[p]));
  std::vector<Real> a(y), b(no_creep), ra(n), rb(n), column(ns);
  for (Index j = 0; j < ns; ++j) {
    a[j] = y[j] + steps[j];
    b[j] = no_creep[j] + steps[j];
    system.residual(0.3, a, yp, ra);
    system.residual(0.3, b, yp, rb);
    for (Index i = 0; i < ns; ++i) column[i] = ra[i] - rb[i];
    a[j] = y[j] - steps[j];
    b[j] = no_creep[j] - steps[j];
    system.residual(0.3, a, yp, ra);
    system.residual(0.3, b, yp, rb);
    for (Index i = 0; i < ns; ++i) column[i] = (column[i] - (ra[i] - rb[i])) / (2 * steps[j]);
    a[j] = y[j];
    b[j] = no_creep[j];
    for (Index i = 0; i < ns; ++i) {
      const Index p = pattern.find(i, j);
      worst = std::max(worst, std::abs(column[i] - (p >= 0 ? delta[p] : 0.0)));
    }
  }
  return worst / largest;
}

void check_relaxation_jacobian(int dim, Hypothesis h) {
  const Mesh mesh =
      dim == 2 ? test::creep_test_mesh(2, 6, 4, 1, 4) : test::creep_test_mesh(3, 4, 3, 2, 5);
  ElasticityOperator op(mesh, prestressed_steel(h, dim), test::creep_test_boundaries(mesh));
  ContinuumCreepSystem system(op, CreepLaw{1e-3, 3e3, 2.5, 1.5, 1e9});
  ASSERT_TRUE(system.relaxes_prestress());
  const int nq = system.n_components(), np = system.n_plastic_components();
  const Index ns = system.structural_size();
  const auto [y, yp, steps, scales] = test::random_continuum_creep_state(system, 7);
  for (Real c_j : {0.0, 2.5e2}) {
    const auto check = test_support::check_jacobian(system, 0.3, c_j, y, yp, steps, scales);
    std::printf("dim %d, hypothesis %d, c_j %g: row-relative %.2e, entry-relative %.2e\n", dim,
                static_cast<int>(h), c_j, check.max_row_relative, check.max_entry_relative);
    EXPECT_LT(check.max_entry_relative, 1e-3)
        << "c_j " << c_j << " row " << check.worst_entry_row << " col " << check.worst_entry_col;
    EXPECT_LT(check.max_row_relative, 1e-6) << "c_j " << c_j << " row " << check.worst_row;
  }
  // Planted: 1 % of the part of dF_u/d eps_p that the displacements' face gradients make (the
  // Jacobian minus that at u = 0; the u rows' q columns also hold the constant plastic source),
  // and 1 % of the relaxation's part of the u-u block (the Jacobian minus that without plastic
  // strain).
  const CsrPattern& pattern = system.jacobian_pattern();
  const std::vector<Real> exact = test_support::analytic_jacobian(system, 0.3, 0, y, yp);
  std::vector<Real> rest(y);
  for (Index k = 0; k < ns; ++k) rest[k] = 0;
  std::vector<Real> no_creep(y);
  for (Index k = ns; k < system.size(); ++k) no_creep[k] = 0;
  const std::vector<Real> at_rest = test_support::analytic_jacobian(system, 0.3, 0, rest, yp),
                          without = test_support::analytic_jacobian(system, 0.3, 0, no_creep, yp);
  std::vector<Real> uq = exact, delta(exact.size(), 0.0);
  for (Index i = 0; i < ns; ++i)
    for (Index p = pattern.row_ptr[i]; p < pattern.row_ptr[i + 1]; ++p) {
      const Index j = pattern.col_idx[p];
      if (j >= ns && (j - ns) % nq < np)
        uq[p] += 0.01 * (exact[p] - at_rest[p]);
      else if (j < ns)
        delta[p] = exact[p] - without[p];
    }
  std::vector<Real> planted_delta(delta);
  for (Real& v : planted_delta) v *= 1.01;
  const Real clean = max_entry_relative_u_rows(system, y, yp, steps, scales, exact),
             planted_uq = max_entry_relative_u_rows(system, y, yp, steps, scales, uq),
             clean_uu = relaxed_uu_error(system, y, no_creep, steps, delta),
             planted_uu = relaxed_uu_error(system, y, no_creep, steps, planted_delta);
  std::printf(
      "u rows' entry-relative: exact %.2e, 1 %% on dF_u/deps_p %.2e; relaxed u-u block: "
      "exact %.2e, 1 %% planted %.2e\n",
      clean, planted_uq, clean_uu, planted_uu);
  EXPECT_LT(clean, 1e-4);
  EXPECT_GT(planted_uq, 5e-3);
  EXPECT_LT(clean_uu, 1e-4);
  EXPECT_GT(planted_uu, 5e-3);

  // initial_state from a state with plastic strain: F(t0, y0, y0') = 0 with the relaxed
  // prestress (its u-u part in equilibrate's tangent), and y0' keeps the balance to first order.
  std::vector<Real> state(y), state_dot, r(system.size());
  for (Index k = 0; k < ns; ++k) state[k] = 0;
  system.initial_state(0.0, state, state_dot);
  system.residual(0.0, state, state_dot, r);
  Real worst = 0, rate = 0;
  for (Index k = 0; k < ns; ++k) worst = std::max(worst, std::abs(r[k]));
  for (Index k = ns; k < system.size(); ++k) rate = std::max(rate, std::abs(state_dot[k]));
  EXPECT_LT(worst, 1e-9 * 5e7 * 2.0);  // force scale: the load times a face area
  auto drift = [&](Real d) {
    return test_support::drift_along_derivative(system, 0.0, state, state_dot, ns, d);
  };
  const Real d = 1e-3 / rate, r1 = drift(d), r2 = drift(d / 2);
  std::printf("F_u drift: %.3e at d, %.3e at d/2 (ratio %.2f)\n", r1, r2, r1 / r2);
  EXPECT_GT(r1 / r2, 3.5);  // second order: 4
}

}  // namespace

TEST(ContinuumCreepRelaxation, PlaneStressJacobianMatchesFiniteDifferences) {
  check_relaxation_jacobian(2, Hypothesis::PlaneStress);
}
TEST(ContinuumCreepRelaxation, PlaneStrainJacobianMatchesFiniteDifferences) {
  check_relaxation_jacobian(2, Hypothesis::PlaneStrain);
}
TEST(ContinuumCreepRelaxation, ThreeDJacobianMatchesFiniteDifferences) {
  check_relaxation_jacobian(3, Hypothesis::ThreeD);
}

// Plane stress (x, y), every edge a symmetry plane, sigma0 = 100 MPa equibiaxial, no load: u
// stays 0 and every cell's prestress sigma0 - C eps_p relaxes by the closed form of the plate's
// test (equibiaxial plane stress: d sigma/dt = -E/(2 (1-nu)) A (sigma/sigma_y)^m), m = 1 and 3.
TEST(ContinuumCreepRelaxation, UniformFilmRelaxesAsTheEquibiaxialClosedForm) {
  BoxSpec spec;
  spec.upper = Vec3(100e-6, 80e-6, 0);
  spec.n[0] = 5;
  spec.n[1] = 4;
  const Mesh mesh = make_structured_mesh(spec);
  std::vector<ElasticityBoundary> bcs(mesh.patches().size());
  for (auto& b : bcs) b.kind = Kind::Symmetry;
  LinearElastic film{160e9, 0.28, 2330, Hypothesis::PlaneStress};
  const Real sigma0 = 100e6;
  film.residual_stress(0, 0) = film.residual_stress(1, 1) = sigma0;
  for (Real m : {1.0, 3.0}) {
    ElasticityOperator op(mesh, film, bcs);
    const CreepLaw law{1e-6, 0, m, 0, 100e6};
    ContinuumCreepSystem system(op, law);
    std::vector<Real> y, yp;
    system.initial_state(0, y, yp);
    IdaOptions options;
    options.rtol = 1e-8;
    options.atol = 1e-14;
    IdaIntegrator ida(system, options);
    ida.initialize(0, y, yp);
    Real worst = 0, max_u = 0;
    for (Real t : {300.0, 900.0, 2700.0}) {
      ASSERT_NO_THROW(ida.advance(t));
      const Real exact = test::equibiaxial_relaxation(law, film.E, film.nu, sigma0, t);
      for (const Mat3& s : system.prestresses(ida.y()))
        worst =
            std::max({worst, std::abs(s(0, 0) - exact) / exact, std::abs(s(1, 1) - exact) / exact});
      for (Index k = 0; k < system.structural_size(); ++k)
        max_u = std::max(max_u, std::abs(ida.y()[k]));
    }
    std::printf("m = %g: worst relative error of the prestress %.2e, max |u| %.2e m\n", m, worst,
                max_u);
    EXPECT_LT(worst, 2e-6);
    EXPECT_LT(max_u, 1e-9 * 80e-6);
    EXPECT_LT(system.prestresses(ida.y())[0](0, 0), 0.4 * sigma0);
  }
}

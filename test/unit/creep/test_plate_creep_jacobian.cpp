// The analytic Jacobian of the plate creep system (physics/creep/plate_creep_system.hpp)
// against central differences of its residual, at a random state (rotations, plastic strains,
// effective strains) on an irregular non-orthogonal graded mesh with clamped, hard simply
// supported, free and loaded edges; also that initial_state is consistent (F(t0, y0, y0') = 0)
// and that the source vanishes for a plastic strain even in z (no moment).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <random>

#include "../../support/distorted_plate.hpp"
#include "../../support/jacobian_check.hpp"
#include "../../support/plate_creep_state.hpp"
#include "physics/creep/plate_creep_system.hpp"
#include "physics/plate/plate_scene.hpp"

using namespace rfmems;
using namespace rfmems::test;
using Kind = PlateBoundary::Kind;

namespace {

PlateSection section() {
  PlateSection s;
  s.E = 200e9;
  s.nu = 0.3;
  s.rho = 7854;
  s.thickness = 0.05;
  return s;
}

}  // namespace

TEST(PlateCreepSystem, JacobianMatchesFiniteDifferences) {
  const Mesh mesh = distorted_mesh(7, 5, 4);
  PlateOperator plate(mesh, section(), mixed_boundaries(mesh),
                      [](const Vec3& x, Real) { return -1e4 * (1 + x.y()); });
  // Moderate hardening so that every term of the rate Jacobian is visible at this state.
  const CreepLaw law{1e-3, 3e3, 2.5, 1.5, 1e9};
  PlateCreepSystem system(plate, law, 6);
  ASSERT_EQ(system.size(), 3 * mesh.n_cells() + 4 * 7 * mesh.n_cells());

  const auto [y, yp, steps, scales] = test::random_plate_creep_state(system, 7);
  for (Real c_j : {0.0, 2.5e2}) {
    const auto check = test_support::check_jacobian(system, 0.3, c_j, y, yp, steps, scales);
    // Round-off of the central differences (it scales as 1/step) bounds both measures: a
    // wrong term is O(1) off. Measured: row 1e-7, entry 3e-4 (small entries next to large).
    EXPECT_LT(check.max_entry_relative, 1e-3)
        << "c_j " << c_j << " row " << check.worst_entry_row << " col " << check.worst_entry_col;
    EXPECT_LT(check.max_row_relative, 1e-6) << "c_j " << c_j << " row " << check.worst_row;
  }
}

// With transverse shear creep (6 states per point): the stress of a point also carries
// tau(z) = phi(z) Q_el / h - 2 G eps_p,az (Q_el: the plate's cell shear force, a function of
// the w and beta of the cell's shear stencil), and the plastic shear force is a source in the
// w and beta rows. A thicker plate (L/h = 10) so that the shear terms are not round-off next
// to the bending ones; random plastic shear strains of the size of the bending ones.
TEST(PlateCreepSystem, JacobianWithShearCreepMatchesFiniteDifferences) {
  const Mesh mesh = distorted_mesh(7, 5, 4);
  PlateSection thick = section();
  thick.thickness = 0.2;
  PlateOperator plate(mesh, thick, mixed_boundaries(mesh),
                      [](const Vec3& x, Real) { return -1e6 * (1 + x.y()); });
  PlateCreepSystem system(plate, CreepLaw{1e-3, 3e3, 2.5, 1.5, 1e9}, 6, true);
  ASSERT_TRUE(system.shear_creep());
  ASSERT_FALSE(system.has_preconditioner());
  ASSERT_EQ(system.size(), 3 * mesh.n_cells() + 6 * 7 * mesh.n_cells());
  const Index ns = system.structural_size();

  std::mt19937 rng(17);
  std::uniform_real_distribution<Real> u(-1, 1);
  std::vector<Real> y(system.size()), yp(system.size()), steps(system.size()),
      scales(system.size());
  for (Index k = 0; k < system.size(); ++k) {
    const Real scale = k < ns ? (k % 3 == 0 ? 1e-4 : 2e-4) : 1e-4;
    y[k] = scale * u(rng);
    yp[k] = scale * u(rng);
    if (k >= ns && (k - ns) % 6 == PlateCreepSystem::kEff) y[k] = std::abs(y[k]);
    steps[k] = 1e-4 * scale;
    scales[k] = scale;
  }
  // The shear stress is a sizeable part of the von Mises stress at this state.
  Real q_p = 0, m_p = 0;
  for (const Vec3& q : system.plastic_shear_forces(y)) q_p = std::max(q_p, q.norm());
  for (const Vec3& m : system.plastic_moments(y)) m_p = std::max(m_p, m.norm());
  EXPECT_GT(q_p * thick.thickness, 0.1 * m_p);
  // Steps 1e-4 of the scales (the tiny entries of far stencil cells, ~1e-7 of their row's
  // largest, are at the round-off of smaller steps: entry-relative 1.7e-2 at 1e-5, 2.5e-3 at
  // 1e-4, scaling as 1/step; row-relative 4e-8).
  for (Real c_j : {0.0, 2.5e2}) {
    const auto check = test_support::check_jacobian(system, 0.3, c_j, y, yp, steps, scales);
    std::printf("shear creep, c_j %g: row-relative %.2e, entry-relative %.2e\n", c_j,
                check.max_row_relative, check.max_entry_relative);
    EXPECT_LT(check.max_entry_relative, 1e-2)
        << "c_j " << c_j << " row " << check.worst_entry_row << " col " << check.worst_entry_col;
    EXPECT_LT(check.max_row_relative, 1e-6) << "c_j " << c_j << " row " << check.worst_row;
  }
  // initial_state is consistent with the shear source in the balances.
  std::vector<Real> state, state_dot, r(system.size());
  system.initial_state(0.0, state, state_dot);
  system.residual(0.0, state, state_dot, r);
  Real worst = 0;
  for (Real v : r) worst = std::max(worst, std::abs(v));
  EXPECT_LT(worst, 1e-9 * 1e6 * 2.0 * 1.2);
}

TEST(PlateCreepSystem, InitialStateIsConsistentAndEvenPlasticStrainIsNoSource) {
  const Mesh mesh = distorted_mesh(6, 4, 9);
  PlateOperator plate(mesh, section(), mixed_boundaries(mesh),
                      [](const Vec3&, Real) { return -3e5; });
  PlateCreepSystem system(plate, CreepLaw{1e-3, 3e3, 2.0, 2.0, 1e9}, 4);
  std::vector<Real> state, state_dot;
  system.initial_state(0.0, state, state_dot);
  std::vector<Real> r(system.size());
  system.residual(0.0, state, state_dot, r);
  Real force_scale = 3e5 * 2.0 * 1.2, worst = 0;
  for (Index k = 0; k < system.size(); ++k) worst = std::max(worst, std::abs(r[k]));
  EXPECT_LT(worst, 1e-9 * force_scale);
  // A plastic strain even in z has no moment: same equilibrium as without it.
  std::vector<Real> even = state;
  for (Index c = 0; c < mesh.n_cells(); ++c)
    for (Index i = 0; i < system.n_points(); ++i)
      for (int j = 0; j < 3; ++j) even[system.creep_index(c, i, j)] = 1e-3 * (j + 1);
  system.residual(0.0, even, state_dot, r);
  worst = 0;
  for (Index k = 0; k < system.structural_size(); ++k) worst = std::max(worst, std::abs(r[k]));
  EXPECT_LT(worst, 1e-9 * force_scale);
}

namespace {

// Every cell faces the electrode (as PlateScene::gap_elements): its w moves it, its area.
CreepHoldVoltage hold_on_every_cell(const Mesh& mesh, Real gap, Real voltage,
                                    const ParallelPlateLaw& law = {}) {
  CreepHoldVoltage hold;
  hold.law = law;
  hold.initial_gap = gap;
  hold.voltage = voltage;
  for (Index c = 0; c < mesh.n_cells(); ++c)
    hold.elements.push_back(
        {3 * c + PlateOperator::kW, mesh.cell_volume(c), Vec3::Zero(), Vec3::Zero(), {}});
  return hold;
}

}  // namespace

// With a hold voltage the w rows carry V^2 A sum_q a_q p1(g0 + u_q), nonlinear in w: the
// Jacobian's w rows must follow the state. Gap 2e-4 m against random w up to 1e-4 m and 3 kV
// (p ~ 2e3-1.8e4 Pa, tangent ~ 4e8 A /m) make the term a visible part of the w rows. Twice:
// one point per cell at its own w (the diagonal only), and the plate's gap points (3 x 3
// Simpson points of the w reconstruction on these distorted quadrilaterals, as the pull-in
// samples the gap), whose tangent reaches the w of the reconstruction's stencil: the w rows'
// pattern must hold those columns with the right values (the check compares every entry,
// those outside the pattern against zero).
TEST(PlateCreepSystem, JacobianWithHoldVoltageMatchesFiniteDifferences) {
  const Mesh mesh = distorted_mesh(7, 5, 4);
  PlateOperator plate(mesh, section(), mixed_boundaries(mesh),
                      [](const Vec3& x, Real) { return -1e4 * (1 + x.y()); });
  ParallelPlateLaw law;
  law.dielectric_thickness = 1e-5;
  law.dielectric_permittivity = 7.5;
  for (bool at_points : {false, true}) {
    PlateCreepSystem system(plate, CreepLaw{1e-3, 3e3, 2.5, 1.5, 1e9}, 6);
    CreepHoldVoltage hold = hold_on_every_cell(mesh, 2e-4, 3e3, law);
    if (at_points) hold.elements = plate_gap_elements(mesh, plate);
    system.set_hold_voltage(hold);

    const auto [y, yp, steps, scales] = test::random_plate_creep_state(system, 11);
    // The w rows reach other cells' w only through the gap points (the plate's own w rows do
    // too, through its shear stencil: count the columns beyond the plate's pattern).
    Index widened = 0;
    const CsrPattern& k_plate = plate.stiffness_pattern();
    for (Index c = 0; c < mesh.n_cells(); ++c)
      widened += (system.jacobian_pattern().row_ptr[3 * c + 1] -
                  system.jacobian_pattern().row_ptr[3 * c]) -
                 (k_plate.row_ptr[3 * c + 1] - k_plate.row_ptr[3 * c]);
    std::printf("gap points %d: w rows widened by %ld entries\n", at_points,
                static_cast<long>(widened));
    if (at_points)
      EXPECT_GT(widened, 0);
    else
      EXPECT_EQ(widened, 0);
    for (Real c_j : {0.0, 2.5e2}) {
      const auto check = test_support::check_jacobian(system, 0.3, c_j, y, yp, steps, scales);
      std::printf("gap points %d, c_j %g: entry-relative %.2e, row-relative %.2e\n", at_points, c_j,
                  check.max_entry_relative, check.max_row_relative);
      EXPECT_LT(check.max_entry_relative, 1e-3)
          << "points " << at_points << " c_j " << c_j << " row " << check.worst_entry_row << " col "
          << check.worst_entry_col;
      EXPECT_LT(check.max_row_relative, 1e-6)
          << "points " << at_points << " c_j " << c_j << " row " << check.worst_row;
    }
    // The smallest gap: that of the most deflected element (one point), or of the lowest
    // point of the reconstructed surface, evaluated here by the plate itself (deflection_at
    // at the cells' nodes, which are gap points, and centroids): never above the first.
    Real w_min = 1e300, w_surface = 1e300;
    for (Index c = 0; c < mesh.n_cells(); ++c) {
      w_min = std::min(w_min, y[3 * c]);
      w_surface = std::min(w_surface, plate.deflection_at(c, mesh.cell_centroid(c), 0.0, y));
      for (Index node : mesh.cell_nodes(c))
        w_surface = std::min(w_surface, plate.deflection_at(c, mesh.nodes()[node], 0.0, y));
    }
    if (at_points) {
      EXPECT_LE(system.min_gap(y), 2e-4 + w_surface + 1e-18);
      EXPECT_LT(system.min_gap(y), 2e-4 + w_min);
    } else {
      EXPECT_DOUBLE_EQ(system.min_gap(y), 2e-4 + w_min);
    }
  }
}

// Equilibrium under a hold voltage (Newton in equilibrate) is consistent, and the load grows
// as the gap closes: the plate sags more than under the constant pressure V^2 p1(g0) that the
// voltage exerts on the flat plate, and less than under V^2 p1(g_min) everywhere. Without a
// hold voltage min_gap is +infinity.
TEST(PlateCreepSystem, HoldVoltageEquilibriumSoftensTheStructure) {
  const Mesh mesh = distorted_mesh(8, 5, 3);
  std::vector<PlateBoundary> bcs(mesh.patches().size());
  for (std::size_t p = 0; p < bcs.size(); ++p)
    bcs[p].kind = (mesh.patches()[p].name == "left" || mesh.patches()[p].name == "right")
                      ? Kind::Clamped
                      : Kind::Free;
  const Real gap = 2e-3, voltage = 7e4;  // p(g0) = 5.4 kPa, sag ~ 5 % of the gap
  const ParallelPlateLaw law;
  auto run = [&](Real pressure, bool hold) {
    PlateOperator plate(mesh, section(), bcs, [pressure](const Vec3&, Real) { return pressure; });
    PlateCreepSystem system(plate, CreepLaw{1e-3, 3e3, 2.0, 2.0, 1e9}, 4);
    std::vector<Real> state(system.size(), 0.0), state_dot;
    EXPECT_EQ(system.min_gap(state), std::numeric_limits<Real>::infinity());
    if (hold) system.set_hold_voltage(hold_on_every_cell(mesh, gap, voltage));
    system.initial_state(0.0, state, state_dot);
    std::vector<Real> r(system.size());
    system.residual(0.0, state, state_dot, r);
    Real worst = 0;
    for (Real v : r) worst = std::max(worst, std::abs(v));
    EXPECT_LT(worst, 1e-9 * voltage * voltage * law.pressure_per_volt2(gap) * 2.0 * 1.2);
    Real w_min = 1e300;
    for (Index c = 0; c < mesh.n_cells(); ++c) w_min = std::min(w_min, state[3 * c]);
    if (hold) {
      EXPECT_DOUBLE_EQ(system.min_gap(state), gap + w_min);
    }
    return w_min;
  };
  const Real p0 = voltage * voltage * law.pressure_per_volt2(gap);
  const Real w_hold = run(0.0, true), w_flat = run(-p0, false);
  const Real p_min = voltage * voltage * law.pressure_per_volt2(gap + w_hold);
  const Real w_max = run(-p_min, false);
  std::printf("max sag: hold %.5e m, constant p(g0) %.5e m, constant p(g_min) %.5e m\n", -w_hold,
              -w_flat, -w_max);
  EXPECT_LT(w_hold, 1.02 * w_flat);  // at least 2 % more sag (measured below)
  EXPECT_GT(w_hold, w_max);
}

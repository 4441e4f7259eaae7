// The scene validity report (physics/validity/scene_validity.hpp): scenes inside and
// outside each criterion's range give exactly the expected warnings, and the
// reported ranges are the criteria's values computed by hand (Kn = lambda_ref
// p_ref / (p g), L/h, g/b, the kinetic Kn = mu / (rho R T) sqrt(pi R T / 2) /
// L).
#include <gtest/gtest.h>

#include <cmath>

#include "physics/validity/scene_validity.hpp"

namespace rfmems {
namespace {

using C = ValidityCriteria;

// The default case, cases/switch_plate: 400 x 40 x 4 um plate 3.75 um above its
// electrode, air at 1 atm (lambda = 68 nm), the run reaching the 2 % contact
// gap, the fold at 0.40 g.
SceneDescription switch_plate() {
  SceneDescription s;
  s.analysis = SceneDescription::Analysis::Dynamic;
  s.length = 400e-6;
  s.width = 40e-6;
  s.thickness = 4e-6;
  s.gap = 3.75e-6;
  s.reynolds = true;
  s.min_gap = 0.02 * s.gap;
  s.equilibrium_displacement = 0.4 * s.gap;
  return s;
}

int count_containing(const ValidityReport &r, const std::string &text) {
  int n = 0;
  for (const std::string &w : r.warnings) n += w.find(text) != std::string::npos;
  return n;
}

TEST(SceneValidity, DefaultSwitchIsInsideEveryRange) {
  const ValidityReport r = check_scene_validity(switch_plate());
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  const ValidityRange *kn = r.find("film_knudsen");
  ASSERT_NE(kn, nullptr);
  EXPECT_NEAR(kn->min, 68e-9 / 3.75e-6, 1e-12);
  EXPECT_NEAR(kn->max, 68e-9 / 75e-9, 1e-9);
  EXPECT_DOUBLE_EQ(r.find("length_over_thickness")->min, 100);
  EXPECT_DOUBLE_EQ(r.find("width_over_thickness")->min, 10);
  EXPECT_DOUBLE_EQ(r.find("gap_over_width")->min, 3.75 / 40);
  EXPECT_DOUBLE_EQ(r.find("gap_over_length")->min, 3.75 / 400);
  EXPECT_DOUBLE_EQ(r.find("film_displacement_over_gap")->max, 0.4);
  const Json j = r.to_json();
  EXPECT_EQ(j["warnings"].size(), 0u);
  EXPECT_DOUBLE_EQ(j["ranges"]["film_knudsen"][1].get<double>(), kn->max);
}

TEST(SceneValidity, ReynoldsFilmBeyondVeijolasFitAtLowPressure) {
  SceneDescription s = switch_plate();
  // Kn at the contact gap equals 880 at this pressure.
  const Real p_limit = 68e-9 * 101325 / (C::kVeijolaMaxKnudsen * s.min_gap);
  s.gas.ambient_pressure = 1.01 * p_limit;
  EXPECT_TRUE(check_scene_validity(s).warnings.empty());
  s.gas.ambient_pressure = 0.99 * p_limit;
  const ValidityReport r = check_scene_validity(s);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(count_containing(r, "Veijola's fit range Kn <= 880"), 1);
  EXPECT_NEAR(r.find("film_knudsen")->max, C::kVeijolaMaxKnudsen / 0.99, 1e-6);
}

TEST(SceneValidity, ContinuumFilmNeedsSmallKnudsen) {
  SceneDescription s = switch_plate();
  s.gas.rarefaction = Rarefaction::None;
  s.min_gap = 0;  // the rest gap only: Kn = 0.0181 > 0.01
  ValidityReport r = check_scene_validity(s);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(count_containing(r, "continuum film's Kn <= 0.01"), 1);
  s.gas.ambient_pressure = 2 * 101325;  // Kn = 0.00907
  EXPECT_TRUE(check_scene_validity(s).warnings.empty());
}

TEST(SceneValidity, LargeDisplacementFilm) {
  SceneDescription s = switch_plate();
  s.equilibrium_displacement = 0.49 * s.gap;
  EXPECT_TRUE(check_scene_validity(s).warnings.empty());
  s.equilibrium_displacement = 0.51 * s.gap;
  const ValidityReport r = check_scene_validity(s);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(count_containing(r, "large-displacement film"), 1);
}

TEST(SceneValidity, GapNotThinAgainstWidthAndFringing) {
  SceneDescription s = switch_plate();
  s.width = 30e-6;  // g/b = 0.125: the film's edge correction, fringing still
                    // below 10 %
  ValidityReport r = check_scene_validity(s);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(count_containing(r, "open-edge correction"), 1);
  s.width = 20e-6;  // g/b = 0.1875 > 0.1/0.65: fringing adds 12 % to the force
  r = check_scene_validity(s);
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_EQ(count_containing(r, "without fringing: gap / width"), 1);
  EXPECT_EQ(count_containing(r, "adds 12 %"), 1);
  s.fringing_factor = 0.65;  // corrected, inside the correction's range
  r = check_scene_validity(s);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(count_containing(r, "open-edge correction"), 1);
  s.width = 6e-6;  // g/b = 0.625 > 0.5: beyond the first-order correction
  r = check_scene_validity(s);
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_EQ(count_containing(r, "first-order fringing correction's range"), 1);
}

TEST(SceneValidity, FringingAlongTheLength) {
  SceneDescription s = switch_plate();
  s.reynolds = false;
  s.width = 0;  // a plane beam's width is not modelled
  s.plate = false;
  s.length = 20e-6;  // g/L = 0.1875
  s.thickness = 2e-6;
  const ValidityReport r = check_scene_validity(s);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(count_containing(r, "gap / length"), 1);
  EXPECT_EQ(r.find("gap_over_width"), nullptr);
  EXPECT_EQ(r.find("film_knudsen"), nullptr);
}

TEST(SceneValidity, PlateSlendernessForStaticDynamicAndCreep) {
  SceneDescription s = switch_plate();
  s.thickness = 30e-6;  // L/h = 13.3: a Mindlin plate, not for creep
  EXPECT_TRUE(check_scene_validity(s).warnings.empty());
  s.analysis = SceneDescription::Analysis::Creep;
  ValidityReport r = check_scene_validity(s);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(count_containing(r, "plate creep: L/h = 13.3 below 20"), 1);
  EXPECT_EQ(count_containing(r, "creep.shear_creep: true includes it"), 1);
  s.plate_stretching = true;  // the von Karman plate: no shear creep to suggest
  r = check_scene_validity(s);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(count_containing(r, "the von Karman plate has no shear creep"), 1);
  EXPECT_EQ(count_containing(r, "creep.shear_creep"), 0);
  s.plate_stretching = false;
  s.plate_shear_creep = true;  // with shear creep the plate's limit is the Mindlin one
  EXPECT_TRUE(check_scene_validity(s).warnings.empty());
  s.thickness = 45e-6;  // L/h = 8.9
  r = check_scene_validity(s);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(count_containing(r, "plate: L/h = 8.89 below 10"), 1);
  s.plate_shear_creep = false;
  s.thickness = 19e-6;  // L/h = 21
  EXPECT_TRUE(check_scene_validity(s).warnings.empty());
  s.analysis = SceneDescription::Analysis::Static;
  s.thickness = 45e-6;  // L/h = 8.9
  r = check_scene_validity(s);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(count_containing(r, "plate: L/h = 8.89 below 10"), 1);
  s.plate = false;  // a plane (2D continuum) beam has no thin-plate assumption
  s.width = 0;
  s.reynolds = false;
  r = check_scene_validity(s);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_NEAR(r.find("length_over_thickness")->min, 400.0 / 45, 1e-12);
}

TEST(SceneValidity, KineticKnudsenRangeAndVelocityGridCover) {
  // Argon at 273.15 K (thesis sec. 5.5.1) over 1 m; the densities of Kn = 1 and
  // Kn = 0.1.
  SceneDescription s;
  s.kinetic.present = true;
  auto &k = s.kinetic;
  k.gas_constant = 208.13;
  k.temperature_min = k.temperature_max = 273.15;
  k.viscosity_min = k.viscosity_max = 2.117e-5;
  k.length = 1;
  const Real rt = k.gas_constant * k.temperature_min;
  auto density_of = [&](Real kn) {
    return k.viscosity_min * std::sqrt(M_PI * rt / 2) / (kn * rt * k.length);
  };
  k.density_min = density_of(1.0);
  k.density_max = density_of(0.1);
  const Real c = std::sqrt(2 * rt);
  k.velocity_extent = 3.5 * c;
  k.wall_temperature = k.temperature_min;
  ValidityReport r = check_scene_validity(s);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_NEAR(r.find("kinetic_knudsen")->min, 0.1, 1e-12);
  EXPECT_NEAR(r.find("kinetic_knudsen")->max, 1.0, 1e-12);
  EXPECT_NEAR(r.find("velocity_extent_over_needed")->min, 3.5 / 3, 1e-12);
  k.wall_speed = 0.6 * c;  // needs 3.6 c
  r = check_scene_validity(s);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(count_containing(r, "velocity grid half-extent"), 1);
  k.wall_speed = 0.4 * c;
  EXPECT_TRUE(check_scene_validity(s).warnings.empty());
  k.wall_temperature = 2 * k.temperature_min;  // needs 3 sqrt(2) c + 0.4 c = 4.64 c
  EXPECT_EQ(check_scene_validity(s).warnings.size(), 1u);
  // A grid of Gauss-Hermite rules only (velocity_extent 0) covers the whole line: no check.
  k.velocity_extent = 0;
  r = check_scene_validity(s);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.find("velocity_extent_over_needed"), nullptr);
}

// The cell size against the mean free path: argon at Kn = 0.1 over 1 m (lambda = 0.1 m) is
// inside on 80 cells (h / (2 lambda) = 0.0625) and on 10 (0.5); 4 cells (1.25) warn once, with
// the key; first-order transport warns of its wall-flux error above 1 %; the immersed switch's air
// at 1.36e4 Pa, 300 K (lambda = 0.463 um) on the 150 x 50 background (h = 0.2 um, the cells'
// smaller side: 0.22) is inside, at 1e5 Pa (lambda = 63 nm: 1.59) it warns.
TEST(SceneValidity, KineticCellSizeAgainstTheMeanFreePath) {
  SceneDescription s;
  s.kinetic.present = true;
  auto &k = s.kinetic;
  k.gas_constant = 208.13;
  k.temperature_min = k.temperature_max = 273.15;
  k.viscosity_min = k.viscosity_max = 2.117e-5;
  k.length = 1;
  const Real rt = k.gas_constant * k.temperature_min;
  k.density_min = k.density_max = k.viscosity_min * std::sqrt(M_PI * rt / 2) / (0.1 * rt);
  EXPECT_NEAR(mean_free_path(k.density_min, k.temperature_min, k.viscosity_min, k.gas_constant),
              0.1, 1e-12);
  k.velocity_extent = 3.5 * std::sqrt(2 * rt);
  k.wall_temperature = k.temperature_min;
  k.cell_size_key = "mesh.cells";
  // Second order: only the profile warning (mu_num / mu > 1). First order: below it the
  // wall-flux warning wherever h / (2 lambda) > 1 % (here 6.25 % and 50 %; 400 cells:
  // 1.25 %; 1000 cells: 0.5 %, none).
  for (const bool first_order : {false, true})
    for (int cells : {1000, 400, 80, 10, 4}) {
      k.first_order = first_order;
      k.cell_size = 1.0 / cells;
      const ValidityReport r = check_scene_validity(s);
      const Real ratio = 1.0 / cells / (2 * 0.1);
      EXPECT_NEAR(r.find("kinetic_upwind_viscosity_ratio")->max, ratio, 1e-12);
      const bool wall_warning = first_order && cells != 4 && cells != 1000;
      EXPECT_EQ(r.warnings.size(), cells == 4 || wall_warning ? 1u : 0u) << cells;
      EXPECT_EQ(count_containing(r, "mu_num / mu"), cells == 4 ? 1 : 0);
      EXPECT_EQ(count_containing(r, "wall shear and heat flux"), wall_warning ? 1 : 0) << cells;
      EXPECT_EQ(count_containing(r, "solver.transport: second_order"), wall_warning ? 1 : 0);
      EXPECT_EQ(count_containing(r, "refine mesh.cells"), cells == 4 || wall_warning ? 1 : 0);
    }
  k.cell_size = 0;  // not given: no range, no warning
  EXPECT_EQ(check_scene_validity(s).find("kinetic_upwind_viscosity_ratio"), nullptr);

  // Air (R = 287.05, mu = 1.712e-5 Pa s, 300 K) at the switch's pressure and at 1 atm.
  const Real R = 287.05, T = 300, mu = 1.712e-5;
  for (Real p : {1.36e4, 1e5}) {
    const Real lambda = mean_free_path(p / (R * T), T, mu, R);
    ValidityReport r;
    check_cell_size_against_mean_free_path(0.2e-6, lambda, lambda, "immersed.background.cells", r);
    EXPECT_EQ(r.warnings.size(), p > 5e4 ? 1u : 0u) << p;
    EXPECT_NEAR(r.find("kinetic_upwind_viscosity_ratio")->max, 0.2e-6 / (2 * lambda), 1e-12);
    if (p < 5e4) EXPECT_NEAR(lambda, 0.463e-6, 1e-9);
  }
}

}  // namespace
}  // namespace rfmems

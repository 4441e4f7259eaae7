// The per-kind error weights of a switch (coupling/state_tolerances.hpp) on the default case
// cases/switch_plate (plate 40 x 4, rotations quasi-static, Reynolds film): every unknown is
// classified as the system's layout says (the algebraic ones are exactly the quasi-static
// kind; one velocity and one film pressure per deflection), and the tolerances follow the
// scales d, d * rate, d * p_a / g0.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "coupling/state_tolerances.hpp"
#include "coupling/switch_scene.hpp"
#include "coupling/switch_system.hpp"
#include "io/case_file.hpp"

using namespace rfmems;

namespace {

struct Counts {
  int displacement = 0, quasi_static = 0, velocity = 0, pressure = 0;
};

Counts count(const std::vector<StateKind>& kinds) {
  Counts c;
  for (StateKind k : kinds) {
    c.displacement += k == StateKind::Displacement;
    c.quasi_static += k == StateKind::QuasiStatic;
    c.velocity += k == StateKind::Velocity;
    c.pressure += k == StateKind::Pressure;
  }
  return c;
}

}  // namespace

TEST(StateTolerances, KindsOfTheDefaultSwitchFollowItsLayout) {
  const std::string path = std::string(RFMEMS_SOURCE_DIR) + "/cases/switch_plate/case.yaml";
  for (const std::string gas : {"none", "reynolds"}) {
    const CaseFile cf = CaseFile::load(path, {"gas.model=" + gas});
    SwitchScene scene =
        build_switch_scene(cf.root(), std::filesystem::path(path).parent_path().string());
    const auto system = make_switch_system(scene);
    const std::vector<StateKind> kinds = system->state_kinds();
    ASSERT_EQ(static_cast<Index>(kinds.size()), system->size()) << gas;
    const Counts c = count(kinds);
    const int cells = 40 * 4;
    // Per plate cell: w (inertial), two rotations (quasi-static), v(w); a pressure with gas.
    EXPECT_EQ(c.displacement, cells) << gas;
    EXPECT_EQ(c.quasi_static, 2 * cells) << gas;
    EXPECT_EQ(c.velocity, cells) << gas;
    EXPECT_EQ(c.pressure, gas == "none" ? 0 : cells) << gas;
    // The algebraic unknowns IDA is told about are exactly the quasi-static ones.
    const std::vector<Real> id = system->differential_components();
    for (std::size_t i = 0; i < kinds.size(); ++i)
      EXPECT_EQ(id[i] == 0.0, kinds[i] == StateKind::QuasiStatic) << gas << " unknown " << i;
    // The displacement the driver controls is one.
    EXPECT_EQ(kinds[scene.control], StateKind::Displacement);
  }
}

TEST(StateTolerances, ScalesPerKind) {
  StateTolerances t;
  t.displacement = 2e-9;
  t.velocity_rate = 8e5;
  t.pressure = 50;
  t.quasi_static = 3e-4;
  const std::vector<StateKind> kinds{StateKind::Displacement, StateKind::QuasiStatic,
                                     StateKind::Velocity, StateKind::Pressure};
  const std::vector<Real> a = absolute_tolerances(kinds, t, 1e-12);
  ASSERT_EQ(a.size(), 4u);
  EXPECT_DOUBLE_EQ(a[0], 2e-9);
  EXPECT_DOUBLE_EQ(a[1], 3e-4);
  EXPECT_DOUBLE_EQ(a[2], 2e-9 * 8e5);
  EXPECT_DOUBLE_EQ(a[3], 50);
  // Unset scales fall back to the scalar atol.
  StateTolerances only_d;
  only_d.displacement = 2e-9;
  const std::vector<Real> b = absolute_tolerances(kinds, only_d, 1e-12);
  EXPECT_DOUBLE_EQ(b[0], 2e-9);
  EXPECT_DOUBLE_EQ(b[1], 1e-12);
  EXPECT_DOUBLE_EQ(b[2], 1e-12);
  EXPECT_DOUBLE_EQ(b[3], 1e-12);
}

TEST(StateTolerances, OffOrFixedStepLeavesTheOptionsAlone) {
  const std::string path = std::string(RFMEMS_SOURCE_DIR) + "/cases/switch_plate/case.yaml";
  const CaseFile cf = CaseFile::load(path, {"gas.model=none"});
  SwitchScene scene =
      build_switch_scene(cf.root(), std::filesystem::path(path).parent_path().string());
  const auto system = make_switch_system(scene);
  StateTolerances t;
  t.displacement = 1e-9;
  t.velocity_rate = 1e6;
  t.suppress_quasi_static = true;
  IdaOptions adaptive;
  const IdaOptions on = with_state_tolerances(adaptive, *system, t);
  EXPECT_EQ(static_cast<Index>(on.atols.size()), system->size());
  EXPECT_TRUE(on.suppress_algebraic);
  EXPECT_TRUE(with_state_tolerances(adaptive, *system, StateTolerances{}).atols.empty());
  IdaOptions fixed;
  fixed.fixed_step = 1e-8;
  EXPECT_TRUE(with_state_tolerances(fixed, *system, t).atols.empty());
}

// The scales of a scene (per_kind_tolerances): d on w, d x rate on v, the isothermal film's
// d p_a / g0 on p, and d over the mean cell size on the suppressed rotations; on the default
// 400 x 40 um plate of 40 x 4 cells and on a 20 x 8 mesh of it (cells 20 x 5 um: the mean
// size is sqrt(100 um^2)).
TEST(StateTolerances, PerKindScalesOfAScene) {
  const std::string path = std::string(RFMEMS_SOURCE_DIR) + "/cases/switch_plate/case.yaml";
  struct Variant {
    std::string gas, cells;
    Real cell_size;
  };
  for (const Variant& v : {Variant{"reynolds", "[40, 4]", 10e-6}, Variant{"none", "[40, 4]", 10e-6},
                           Variant{"reynolds", "[20, 8]", std::sqrt(20e-6 * 5e-6)}}) {
    const CaseFile cf = CaseFile::load(path, {"gas.model=" + v.gas, "mesh.cells=" + v.cells});
    SwitchScene scene =
        build_switch_scene(cf.root(), std::filesystem::path(path).parent_path().string());
    const Real d = 3e-9, rate = 8e5;
    const StateTolerances t = per_kind_tolerances(scene, d, rate);
    EXPECT_DOUBLE_EQ(t.displacement, d) << v.gas << v.cells;
    EXPECT_DOUBLE_EQ(t.velocity_rate, rate) << v.gas << v.cells;
    EXPECT_NEAR(t.quasi_static, d / v.cell_size, 1e-12 * d / v.cell_size) << v.gas << v.cells;
    EXPECT_TRUE(t.suppress_quasi_static);
    // 1 atm over the 3.75 um gap; no film, no pressure unknowns to weigh.
    EXPECT_NEAR(t.pressure, v.gas == "none" ? 0.0 : d * 101325.0 / 3.75e-6, 1e-9) << v.gas;
  }
}

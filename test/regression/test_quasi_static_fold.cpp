// The quasi-static fold to its stated tolerance (coupling/quasi_static_pull_in.hpp), on the
// default switch without gas (cases/switch_plate: plate 40 x 4 + parallel plate) and on the
// cantilever plate switch (cases/cantilever_switch_plate):
//  - whatever the sampling, the fold's voltage is within voltage_tolerance of a reference traced
//    with a tolerance 100x tighter, and no point of the curve lies above it. The fold search
//    used to stop when its two trial voltages agreed, and its Newton test was scaled by the
//    stiffness times the gap: with 4 samples and 1e-4 V it reported 188.26217 V against
//    188.26057 V (1.6e-3 V off, after 86 solves);
//  - the whole trace uses one solver: one factorisation with fresh pivoting, and far fewer
//    refactorisations than solves (the Jacobian kept from point to point while Newton
//    converges);
//  - the cantilever's fold converges monotonically as the mesh is refined along its length
//    (25 to 400 cells), each difference at least halving (observed order >= 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/switch_scene.hpp"
#include "io/case_file.hpp"

using namespace rfmems;

namespace {

struct Switch {
  CaseFile file;
  SwitchScene scene;
};

std::unique_ptr<Switch> load(const std::string& name, std::vector<std::string> overrides) {
  const std::string path = std::string(RFMEMS_SOURCE_DIR) + "/cases/" + name + "/case.yaml";
  overrides.push_back("gas.model=none");
  CaseFile cf = CaseFile::load(path, overrides);
  SwitchScene s = build_switch_scene(cf.root(), std::filesystem::path(path).parent_path().string());
  return std::make_unique<Switch>(Switch{std::move(cf), std::move(s)});
}

QuasiStaticPullIn trace(Switch& s, int points, double voltage_tolerance) {
  QuasiStaticOptions o;
  o.n_points = points;
  o.max_fraction = 0.9;
  o.voltage_tolerance = voltage_tolerance;
  return trace_pull_in(*s.scene.actuation, s.scene.control, o);
}

}  // namespace

TEST(QuasiStaticFold, WithinItsVoltageToleranceWhateverTheSampling) {
  auto s = load("switch_plate", {});
  const double reference = trace(*s, 40, 1e-6).pull_in_voltage;
  for (const double tolerance : {1e-2, 1e-4})
    for (const int points : {4, 5, 7, 40}) {
      const QuasiStaticPullIn r = trace(*s, points, tolerance);
      std::printf(
          "%2d points, tolerance %.0e V: V_PI = %.6f V (reference %.6f), %ld solves, "
          "%ld Newton, %ld fresh + %ld refactorisations\n",
          points, tolerance, r.pull_in_voltage, reference, r.solves, r.newton_iterations,
          r.last.fresh_factorizations, r.last.refactorizations);
      EXPECT_NEAR(r.pull_in_voltage, reference, tolerance) << points << " points";
      for (const PullInPoint& p : r.curve)
        EXPECT_LE(p.voltage, r.pull_in_voltage) << "a point above the fold at " << p.displacement;
      EXPECT_EQ(r.last.fresh_factorizations, 1);
      EXPECT_LT(r.last.refactorizations, r.solves / 2);
    }
}

TEST(QuasiStaticFold, CantileverFoldConvergesMonotonically) {
  std::vector<double> v;
  for (const int nx : {25, 50, 100, 200, 400}) {
    auto s = load("cantilever_switch_plate", {"mesh.cells=[" + std::to_string(nx) + ",2]"});
    const QuasiStaticPullIn r = trace(*s, 40, 1e-5);
    std::printf("%3d x 2: V_PI = %.6f V, %ld solves, %ld Newton\n", nx, r.pull_in_voltage, r.solves,
                r.newton_iterations);
    v.push_back(r.pull_in_voltage);
  }
  for (std::size_t k = 2; k < v.size(); ++k) {
    const double previous = v[k - 1] - v[k - 2], now = v[k] - v[k - 1];
    EXPECT_GT(previous, 0) << "refinement " << k - 1;
    EXPECT_GT(now, 0) << "refinement " << k;
    EXPECT_LT(now, 0.5 * previous) << "refinement " << k;
  }
}

// From 1000 unknowns the trace factorises with UMFPACK (its symmetric strategy on the
// nested-dissection order with the voltage last) instead of KLU: on the default switch at
// 80 x 8 (1921 unknowns) it must find KLU's fold, with the same Newton iterations (no solve is
// less accurate), one symbolic analysis for the whole trace and a sparser factor.
TEST(QuasiStaticFold, UmfpackFindsKlusFoldWithLessFill) {
  auto s = load("switch_plate", {"mesh.cells=[80,8]"});
  QuasiStaticOptions o;
  o.voltage_tolerance = 1e-3;
  ASSERT_GT(s->scene.actuation->size() + 1, o.umfpack_from);
  const QuasiStaticPullIn umfpack = trace_pull_in(*s->scene.actuation, s->scene.control, o);
  o.umfpack_from = std::numeric_limits<Index>::max();
  const QuasiStaticPullIn klu = trace_pull_in(*s->scene.actuation, s->scene.control, o);
  std::printf(
      "80 x 8: V_PI %.6f V (UMFPACK) against %.6f V (KLU); Newton %ld against %ld; "
      "L + U %ld against %ld\n",
      umfpack.pull_in_voltage, klu.pull_in_voltage, umfpack.newton_iterations,
      klu.newton_iterations, umfpack.last.factor_entries, klu.last.factor_entries);
  EXPECT_TRUE(umfpack.last.umfpack);
  EXPECT_FALSE(klu.last.umfpack);
  EXPECT_NEAR(umfpack.pull_in_voltage, klu.pull_in_voltage, o.voltage_tolerance);
  EXPECT_NEAR(static_cast<double>(umfpack.newton_iterations),
              static_cast<double>(klu.newton_iterations), 0.05 * klu.newton_iterations);
  EXPECT_EQ(umfpack.last.fresh_factorizations, 1);
  EXPECT_LT(umfpack.last.refactorizations, umfpack.solves / 2);
  EXPECT_LT(umfpack.last.factor_entries, klu.last.factor_entries);
}

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

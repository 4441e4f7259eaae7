// Plane Couette flow of argon at Kn = 0.01 on the thesis's finest verification mesh, 80 cells
// (thesis sec. 5.5.1, Fig. 5.9), sequential ESBGK solver: RMS error against the first-order slip
// solution <= 2 %, and the observed order from 20-40-80 cells. A study because source
// iteration needs ~2500 sweeps at 80 cells (~22 s; 34 s with the 20- and 40-cell runs): the
// slow near-continuum convergence that COMET removes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../unit/kinetic/couette_flow.hpp"

using namespace rfmems;
using namespace rfmems::test_support;

TEST(KineticCouetteStudy, Knudsen001At80Cells) {
  std::vector<CouetteRun> runs;
  for (int ny : {20, 40, 80}) {
    runs.push_back(run_couette(0.01, ny));
    const CouetteRun& r = runs.back();
    std::printf("Kn = 0.01, %2d cells: RMS error %.3f %%, %d iterations, %.1f s\n", ny,
                100 * r.rms_error, r.solve.iterations, r.solve.seconds);
    EXPECT_TRUE(r.solve.converged);
  }
  EXPECT_LE(runs.back().rms_error, 0.02);
  const Real order = std::log2(coarse_fine_difference(runs[0], runs[1]) /
                               coarse_fine_difference(runs[1], runs[2]));
  std::printf("observed order %.3f\n", order);
  EXPECT_NEAR(order, 1.0, 0.25);
}

// Couette flow through the immersed boundary (the "IBM accuracy" check): argon
// between a fixed diffuse wall (y = 0, a background boundary) and an immersed plate whose lower
// surface is at y = H = (m + theta) h, off the grid (theta = 0.4), moving along z at U = 10 m/s
// (the invariant direction, as in test/unit/kinetic/couette_flow.hpp; specular sides). The
// plate reaches past the background's top and sides, so the FLUID cells are rows 0..m-1 and the
// IB faces lie on y = m h, 0.4 h below the surface.
//
// Reference: the same solver (sequential, ESBGK, 10^3 velocities) body-fitted on the same rows
// 0..m-1 plus a last cell [m h, H] of 0.4 h, with the moving diffuse wall at y = H.
// Compared: the velocity u_z of rows 0..m-1 (largest difference / U) and the shear force on the
// plate (IBM: the sum of the segment forces from ForceTransfer; body-fitted: wall_force).
//
// Asserted (numbers printed; docs/ibm.md has the table). Why first order: both runs share the
// first-order upwind interior scheme (its numerical diffusion h |c| / 2), and each converges
// to the common limit at first order (measured, own order of the shear from m = 20, 40, 80:
// IBM 0.91, body-fitted 0.92; their first-order extrapolations agree to 8e-5). The IB side is
// not the limiting approximation (the step-(iii) fits are quadratic, the velocity transfer
// exact for the rigid plate, the mass-flux factors 1 to 2e-7), so the IBM cannot be made
// second order there; the 1 % holds at m = 80 (h = H / 80.4). With second-order
// transport in both it holds at m = 10: test_ibm_couette_second_order.cpp.
//  - Kn = 0.1, m = 20, 40, 80 (10^3 velocities): the IBM - body-fitted shear difference falls
//    at an observed order in [0.6, 1.5] (measured 0.88, 0.94), the profile difference at
//    >= 0.4 (0.74, 0.83); each scheme's own shear order in [0.8, 1.3]; at m = 80 shear and
//    profile within 1 % (measured -0.62 %, 0.68 % U); extrapolated (m = 40, 80) within 1 %
//    (measured 8.4e-5 and 7.5e-4 U);
//  - Kn = 0.01, m = 10, 20 (8^3 velocities): within 3 % at m = 20 (measured -1.42 %, 1.27 %
//    U); extrapolated within 1 % (measured 5.0e-3 and 9.0e-3 U); m = 40 within 1 % is the
//    study test/study/test_ibm_couette_study.cpp (the continuum sweeps cost ~3x m = 20's);
//  - the plate's shear equals minus the fixed wall's (momentum balance of the steady state) to
//    1e-6 relative (measured <= 3.6e-7).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/ibm_couette_flow.hpp"

namespace rfmems {
namespace {
using namespace rfmems::test;

TEST(IbmCouette, Knudsen01MatchesBodyFittedWithObservedOrder) {
  std::vector<Comparison> runs;
  const int ms[] = {20, 40, 80};
  for (int m : ms) runs.push_back(compare(0.1, m, 10));
  for (const Comparison& c : runs) EXPECT_LE(c.balance, 1e-6);
  const Real r1 = h_ratio(20, 40), r2 = h_ratio(40, 80);
  const Real o1 = std::log(std::abs(runs[0].shear) / std::abs(runs[1].shear)) / std::log(r1);
  const Real o2 = std::log(std::abs(runs[1].shear) / std::abs(runs[2].shear)) / std::log(r2);
  const Real p1 = std::log(runs[0].profile / runs[1].profile) / std::log(r1);
  const Real p2 = std::log(runs[1].profile / runs[2].profile) / std::log(r2);
  // Each scheme's own order, from its three shears (per slip-theory shear): the differences of
  // successive meshes fall as r^p.
  auto own_order = [&](auto shear) {
    const Real d1 = shear(runs[0]) - shear(runs[1]), d2 = shear(runs[1]) - shear(runs[2]);
    return std::log(std::abs(d1 / d2)) / std::log(r2);
  };
  const Real ib_order = own_order([](const Comparison& c) { return c.ib_shear / c.tau; });
  const Real bf_order = own_order([](const Comparison& c) { return c.bf_shear / c.tau; });
  std::printf(
      "observed order of the IBM - body-fitted difference: shear %.2f %.2f, profile "
      "%.2f %.2f; own order of the shear: IBM %.2f, body-fitted %.2f\n",
      o1, o2, p1, p2, ib_order, bf_order);
  RecordProperty("difference_order_shear", std::to_string(o2));
  RecordProperty("ibm_own_order", std::to_string(ib_order));
  RecordProperty("body_fitted_own_order", std::to_string(bf_order));
  // Both schemes are first order (upwind interior, the same in both): each converges at about
  // first order and so does their difference.
  EXPECT_GE(o2, 0.6);
  EXPECT_LE(o2, 1.5);
  EXPECT_GE(p2, 0.4);
  EXPECT_GE(ib_order, 0.8);
  EXPECT_LE(ib_order, 1.3);
  EXPECT_GE(bf_order, 0.8);
  EXPECT_LE(bf_order, 1.3);
  // The 1 %, at m = 80 (h = H / 80.4).
  EXPECT_LE(runs[2].profile, 0.01);
  EXPECT_LE(std::abs(runs[2].shear), 0.01);
  const Extrapolated e = extrapolate(runs[1], runs[2], r2);
  EXPECT_LE(std::abs(e.shear), 0.01);
  EXPECT_LE(e.profile, 0.01);
}

TEST(IbmCouette, Knudsen001MatchesBodyFitted) {
  // 8^3 velocities (both solvers) to keep the near-continuum sweeps under a minute.
  const Comparison c10 = compare(0.01, 10, 8), c20 = compare(0.01, 20, 8);
  EXPECT_LE(c20.balance, 1e-6);
  EXPECT_LE(std::abs(c20.shear), 0.03);
  EXPECT_LE(c20.profile, 0.03);
  const Extrapolated e = extrapolate(c10, c20, h_ratio(10, 20));
  EXPECT_LE(std::abs(e.shear), 0.01);
  EXPECT_LE(e.profile, 0.01);
}

}  // namespace
}  // namespace rfmems

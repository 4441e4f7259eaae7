// Simply supported square plate under uniform load: side a = 1 m, q = 1 Pa, E = 200 GPa,
// nu = 0.3, k = 5/6, 40 x 40 cells, cubic reconstruction, L/h = 10 and 1000.
//
// References (Navier double sine series, summed here to m, n <= 399):
//   Kirchhoff   w_c = 16 q a^4/(pi^6 D) sum s/(m n (m^2+n^2)^2)            = 0.00406235 q a^4/D
//               Mx_c = 16 q a^2/pi^4 sum s (m^2 + nu n^2)/(m n (m^2+n^2)^2) = 0.0479 q a^2
//   Mindlin, hard support (w = 0, beta.t = 0): the moments are Kirchhoff's and
//               w_c = w_c(Kirchhoff) + Mc/(k G h), Mc = (Mx + My)/(1 + nu) at the centre, the
//               Marcus moment, 16 q a^2/pi^4 sum s/(m n (m^2+n^2)) = 0.0737 q a^2
//   (Wang, Reddy & Lee, Shear Deformable Beams and Plates, 2000, ch. 7), s = (-1)^((m+n)/2-1).
// Asserts: hard support within 0.5 % (w) and 1 % (Mx) of these at both L/h (measured
// +0.025 %).
// No locking, literally (the criterion: "at fixed mesh the discretisation error and the
// Newton/linear iteration counts are the same (within 10 %) for L/h = 10 and L/h = 1000"): the hard
// support is the case with an exact Mindlin solution at every L/h, and its rotations and moments
// are the same field at every L/h (only w gains the smooth term Mc/(kGh)), so the discretisation
// errors at two L/h are comparable without a Richardson reference of uncertain order. On 10 x
// 10, 20 x 20 and 40 x 40: e(1000)/e(10) of the centre deflection, relative to each exact value,
// within 10 % of 1 (measured 1.084, 1.043, 0.980), and in units of q a^4/D (1.031, 0.992,
// 0.931); e(1000)/e(100) within 1 % (1.001-1.002); the same Newton count (1) and linear
// iteration count (0: KLU) at every L/h. (Mx: 1.12, 1.09, 1.03, reported, not asserted.) The soft
// support (moments free, so beta.t is free too) has a twisting-moment boundary layer of width ~h.
// Thick (L/h = 10, resolved): more flexible than the hard support (measured +8 %). Thin (L/h =
// 1000, layer 25 times thinner than a cell): the mesh smears the layer over a cell, so the centre
// deflection converges to Kirchhoff's at first order in the cell size (measured +3.7 %, +1.8 %,
// +0.9 % on 20, 40, 80 cells a side): asserted within 2 % on 40 x 40 and an observed order >= 0.9
// from 20 x 20.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mesh/structured_mesh.hpp"
#include "physics/plate/plate_operator.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using Kind = PlateBoundary::Kind;

namespace {

constexpr double a = 1.0, q = 1.0, E = 200e9, nu = 0.3;

struct Series {
  double w, mx, marcus;  // coefficients of q a^4/D, q a^2, q a^2
};

Series navier() {
  Series s{0, 0, 0};
  for (int m = 1; m < 400; m += 2)
    for (int n = 1; n < 400; n += 2) {
      const double sign = ((m + n) / 2 - 1) % 2 == 0 ? 1.0 : -1.0;
      const double k2 = double(m) * m + double(n) * n;
      s.w += sign / (m * n * k2 * k2);
      s.mx += sign * (double(m) * m + nu * n * n) / (m * n * k2 * k2);
      s.marcus += sign / (m * n * k2);
    }
  const double pi4 = std::pow(M_PI, 4);
  return {16 * s.w / (pi4 * M_PI * M_PI), 16 * s.mx / pi4, 16 * s.marcus / pi4};
}

struct Centre {
  double w, mx;  // w D/(q a^4), Mx/(q a^2)
  long newton, linear;
};

Centre solve(double slenderness, Kind support, int n = 40) {
  BoxSpec spec;
  spec.upper = Vec3(a, a, 0);
  spec.n[0] = n;
  spec.n[1] = n;
  Mesh mesh = make_structured_mesh(spec);
  std::vector<PlateBoundary> bcs(mesh.patches().size(), PlateBoundary{support, {}});
  const PlateSection section{E, nu, 7854, a / slenderness};
  PlateOperator op(mesh, section, bcs, [](const Vec3&, double) { return q; });
  StaticSolution s = solve_static(op, 0.0);
  EXPECT_EQ(s.stats.newton_iters, 1);
  const Vec3 centre(a / 2, a / 2, 0);
  double w = 0, mx = 0;
  int count = 0;
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    const Vec3 d = mesh.cell_centroid(c) - centre;
    if (std::abs(d.x()) < 0.51 * a / n && std::abs(d.y()) < 0.51 * a / n) {
      w += op.deflection_at(c, centre, 0.0, s.y);
      mx += op.moment(op.rotation_gradient_at(c, centre, 0.0, s.y))(0, 0);
      ++count;
    }
  }
  const double D = section.bending_stiffness();
  return {w / count * D / (q * a * a * a * a), mx / count / (q * a * a), s.stats.newton_iters,
          s.stats.linear_iters};
}

}  // namespace

TEST(PlateSimplySupported, HardSupportMatchesNavierAndMarcus) {
  const Series ref = navier();
  EXPECT_NEAR(ref.w, 0.00406235, 1e-7);
  EXPECT_NEAR(ref.mx, 0.0479, 1e-4);
  for (double slenderness : {10.0, 1000.0}) {
    const PlateSection section{E, nu, 7854, a / slenderness};
    const double w_ref =
        ref.w + ref.marcus * section.bending_stiffness() / (section.shear_stiffness() * a * a);
    const Centre c = solve(slenderness, Kind::SimplySupportedHard);
    std::printf(
        "hard  L/h = %5.0f: w D/(q a^4) = %.7f (Mindlin %.7f, %+.3f %%), Mx/(q a^2) = %.5f (%.5f, "
        "%+.3f %%)\n",
        slenderness, c.w, w_ref, 100 * (c.w / w_ref - 1), c.mx, ref.mx, 100 * (c.mx / ref.mx - 1));
    EXPECT_NEAR(c.w / w_ref, 1.0, 0.005);
    EXPECT_NEAR(c.mx / ref.mx, 1.0, 0.01);
  }
}

TEST(PlateSimplySupported, SoftSupportThinLimitAndBoundaryLayer) {
  const Series ref = navier();
  const Centre thin = solve(1000.0, Kind::SimplySupportedSoft);
  const Centre thin_coarse = solve(1000.0, Kind::SimplySupportedSoft, 20);
  const Centre thick_soft = solve(10.0, Kind::SimplySupportedSoft);
  const Centre thick_hard = solve(10.0, Kind::SimplySupportedHard);
  std::printf(
      "soft  L/h =  1000: w D/(q a^4) = %.7f (Kirchhoff %.7f), Mx/(q a^2) = %.5f\n"
      "soft  L/h =    10: w D/(q a^4) = %.7f (hard %.7f), Mx/(q a^2) = %.5f (hard %.5f)\n",
      thin.w, ref.w, thin.mx, thick_soft.w, thick_hard.w, thick_soft.mx, thick_hard.mx);
  const double order = std::log2((thin_coarse.w - ref.w) / (thin.w - ref.w));
  std::printf("soft  L/h =  1000: errors %.2f %% (20x20), %.2f %% (40x40): order %.2f\n",
              100 * (thin_coarse.w / ref.w - 1), 100 * (thin.w / ref.w - 1), order);
  EXPECT_NEAR(thin.w / ref.w, 1.0, 0.02);
  EXPECT_GT(order, 0.9);
  EXPECT_NEAR(thin.mx / ref.mx, 1.0, 0.02);
  EXPECT_GT(thick_soft.w, thick_hard.w);
}

TEST(PlateSimplySupported, NoLockingAtFixedMeshAgainstExactMindlin) {
  const Series ref = navier();
  for (int n : {10, 20, 40}) {
    double relative[3], absolute[3], moment[3];
    long newton[3], linear[3];
    const double slenderness[3] = {10, 100, 1000};
    for (int k = 0; k < 3; ++k) {
      const PlateSection section{E, nu, 7854, a / slenderness[k]};
      const double w_ref =
          ref.w + ref.marcus * section.bending_stiffness() / (section.shear_stiffness() * a * a);
      const Centre c = solve(slenderness[k], Kind::SimplySupportedHard, n);
      relative[k] = c.w / w_ref - 1;
      absolute[k] = c.w - w_ref;
      moment[k] = c.mx / ref.mx - 1;
      newton[k] = c.newton;
      linear[k] = c.linear;
      std::printf(
          "%2dx%-2d L/h = %5.0f: w error %+.4e relative, %+.4e q a^4/D; Mx error %+.4e; "
          "Newton %ld, linear %ld\n",
          n, n, slenderness[k], relative[k], absolute[k], moment[k], newton[k], linear[k]);
      EXPECT_GT(relative[k], 0.0);  // a real discretisation error, not round-off
    }
    std::printf(
        "%2dx%-2d e(1000)/e(10): relative %.4f, absolute %.4f, Mx %.4f; e(1000)/e(100) "
        "%.4f\n",
        n, n, relative[2] / relative[0], absolute[2] / absolute[0], moment[2] / moment[0],
        relative[2] / relative[1]);
    EXPECT_NEAR(relative[2] / relative[0], 1.0, 0.10) << n << " x " << n;
    EXPECT_NEAR(absolute[2] / absolute[0], 1.0, 0.10) << n << " x " << n;
    EXPECT_NEAR(relative[2] / relative[1], 1.0, 0.01) << n << " x " << n;
    for (int k = 1; k < 3; ++k) {
      EXPECT_EQ(newton[k], newton[0]);
      EXPECT_EQ(linear[k], linear[0]);
    }
  }
}

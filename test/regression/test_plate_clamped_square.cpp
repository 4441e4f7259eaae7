// Clamped square plate under uniform load (thesis sec. 3.6.2, Tables 3.2-3.3, Figs. 3.6-3.7):
// side a = 1 m, all edges clamped (w = 0, beta = 0), q = 1 Pa, E = 200 GPa, nu = 0.3,
// k = 5/6, L/h = a/h = 5, 10, 100, 200, 1000. Cubic reconstruction, uniform n x n meshes; the
// centre is a mesh vertex for even n, where the four surrounding cells' reconstructions are
// averaged. w_ref = q a^4/(1000 D), M_ref = q a^2.
//
// Asserts:
//  - on 40 x 40 (the thesis's mesh for Fig. 3.7; 1.3 s a solve): centre deflection within 1 %
//    of Table 3.2 (2.172, 1.505, 1.269, 1.267 for L/h = 5 ... 200) and of the Kirchhoff value
//    1.26 at L/h = 1000; centre moment Mx within 2 % of Table 3.3 (0.0235 ... 0.0229; at
//    L/h = 1000 of 0.0229 and of the Kirchhoff 0.0231); every solve one Newton step.
//  - no locking, at a fixed 20 x 20 mesh. Discretisation errors against converged references
//    (Richardson from 40 x 40 and 80 x 80, test/study/test_plate_clamped_study.cpp):
//    L/h = 10: 1.50462; L/h = 100: 1.26785; L/h = 1000: 1.26533 (the Kirchhoff series value
//    is 1.26532). Locking would multiply the thin plate's error by ~(L/h)^2; here
//      * e(1000)/e(100) within 10 % of 1 (measured 1.02): the two solutions differ by 0.2 %,
//        so this ratio isolates the dependence of the error on L/h;
//      * e(1000)/e(10) within 20 % of 1 (measured 1.13, both in units of w_ref): not the
//        issue's 10 %, because the L/h = 10 solution is another function (shear deformation is
//        16 % of its deflection, with boundary layers), not because of locking; the issue's
//        literal 10 % is asserted where an exact Mindlin solution exists at every L/h, the
//        hard simply supported plate (test_plate_simply_supported.cpp: 0.98-1.08 on 10 x 10
//        to 40 x 40);
//      * the Newton iteration counts equal (1; direct linear solves, no linear iterations);
//      * the observed orders over 10 x 10 -> 40 x 40 agree within 10 % (thesis: "an aspect
//        ratio independent convergence rate"), and are >= 1.8.
//  - the same on a curved, non-orthogonal mesh (x += 0.06 a sin(pi x) sin(2 pi y), y likewise,
//    which leaves the edges and the centre in place and shears the cells around the centre so
//    that the centroid line of a face is ~40 degrees off its normal),
//    so the tangential shear correction is active: 40 x 40 within 0.1 % of the references at
//    L/h = 10 and 1000 (measured 0.03 % and 0.05 %).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

#include "mesh/structured_mesh.hpp"
#include "physics/plate/plate_operator.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using Kind = PlateBoundary::Kind;

namespace {

constexpr double a = 1.0, q = 1.0, E = 200e9, nu = 0.3;

struct Centre {
  double w, mx, edge_mx;  // w/w_ref, Mx/M_ref at the centre and at the edge midpoint (0, a/2)
  long newton;
  double seconds;
};

// Average over the cells whose centroids lie within half a cell of x (one cell, two or four)
// of f(cell).
template <class F>
double average_near(const Mesh& mesh, const Vec3& x, int n, F f) {
  double sum = 0;
  int count = 0;
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    const Vec3 d = mesh.cell_centroid(c) - x;
    if (std::abs(d.x()) < 0.51 * a / n && std::abs(d.y()) < 0.51 * a / n) {
      sum += f(c);
      ++count;
    }
  }
  return sum / count;
}

// Uniform mesh, or the curved one (edges and centre fixed).
Mesh square_mesh(int n, double distortion) {
  BoxSpec spec;
  spec.upper = Vec3(a, a, 0);
  spec.n[0] = n;
  spec.n[1] = n;
  return make_structured_mesh(spec, [distortion](const Vec3& x) {
    Vec3 y = x;
    y.x() += distortion * a * std::sin(M_PI * x.x() / a) * std::sin(2 * M_PI * x.y() / a);
    y.y() += distortion * a * std::sin(2 * M_PI * x.x() / a) * std::sin(M_PI * x.y() / a);
    return y;
  });
}

Centre solve(int n, double slenderness, double distortion = 0) {
  auto t0 = std::chrono::steady_clock::now();
  Mesh mesh = square_mesh(n, distortion);
  std::vector<PlateBoundary> bcs(mesh.patches().size(), PlateBoundary{Kind::Clamped, {}});
  const PlateSection section{E, nu, 7854, a / slenderness};
  PlateOperator op(mesh, section, bcs, [](const Vec3&, double) { return q; });
  StaticSolution s = solve_static(op, 0.0);
  const Vec3 centre(a / 2, a / 2, 0), edge(0, a / 2, 0);
  const double w =
      average_near(mesh, centre, n, [&](Index c) { return op.deflection_at(c, centre, 0.0, s.y); });
  const double mx = average_near(mesh, centre, n, [&](Index c) {
    return op.moment(op.rotation_gradient_at(c, centre, 0.0, s.y))(0, 0);
  });
  // The two cells touching the edge midpoint.
  const double edge_mx = average_near(mesh, edge + Vec3(0.5 * a / n, 0, 0), n, [&](Index c) {
    return op.moment(op.rotation_gradient_at(c, edge, 0.0, s.y))(0, 0);
  });
  const double D = section.bending_stiffness();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {w / (q * a * a * a * a / (1000 * D)), mx / (q * a * a), edge_mx / (q * a * a),
          s.stats.newton_iters, seconds};
}

// Solves once per (n, L/h) for the whole file.
const Centre& cached(int n, double slenderness) {
  static std::map<std::pair<int, double>, Centre> cache;
  auto it = cache.find({n, slenderness});
  if (it == cache.end()) {
    it = cache.emplace(std::make_pair(n, slenderness), solve(n, slenderness)).first;
    const Centre& c = it->second;
    std::printf(
        "L/h = %6.0f  %2dx%-2d  w/wref = %.5f  Mx/qa2 = %.5f  edge Mx/qa2 = %.5f  Newton %ld  %.2f "
        "s\n",
        slenderness, n, n, c.w, c.mx, c.edge_mx, c.newton, c.seconds);
  }
  return it->second;
}

}  // namespace

TEST(PlateClampedSquare, MatchesThesisTables32And33On40x40) {
  struct Row {
    double slenderness, w, mx;
  };
  // Thesis "present formulation"; L/h = 1000: the Kirchhoff values (Table 3.3 lists 0.0229
  // for thin plates, Kirchhoff's is 0.0231).
  const Row rows[] = {{5, 2.172, 0.0235},
                      {10, 1.505, 0.0232},
                      {100, 1.269, 0.0229},
                      {200, 1.267, 0.0229},
                      {1000, 1.26, 0.0229}};
  for (const Row& row : rows) {
    const Centre& c = cached(40, row.slenderness);
    EXPECT_NEAR(c.w / row.w, 1.0, 0.01) << "L/h = " << row.slenderness;
    EXPECT_NEAR(c.mx / row.mx, 1.0, 0.02) << "L/h = " << row.slenderness;
    EXPECT_EQ(c.newton, 1);
  }
  EXPECT_NEAR(cached(40, 1000).mx / 0.0231, 1.0, 0.02);
  // Table 3.4 (max moment, at the edge midpoint; Kirchhoff -0.0513): reported, not asserted
  // against the thesis, whose 0.046 is 10 % below Kirchhoff; ours must be within 3 % of it.
  EXPECT_NEAR(cached(40, 1000).edge_mx / -0.0513, 1.0, 0.03);
}

TEST(PlateClampedSquare, NoLockingAtFixedMesh) {
  const double reference_10 = 1.50462, reference_100 = 1.26785, reference_1000 = 1.26533;
  const Centre &thick = cached(20, 10), &thin = cached(20, 100), &thinnest = cached(20, 1000);
  const double e10 = thick.w - reference_10, e100 = thin.w - reference_100,
               e1000 = thinnest.w - reference_1000;
  std::printf(
      "20x20 errors in w/wref: L/h = 10: %.5f (%.3f %%), 100: %.5f (%.3f %%), 1000: %.5f (%.3f "
      "%%); "
      "e(1000)/e(100) = %.3f, e(1000)/e(10) = %.3f\n",
      e10, 100 * e10 / reference_10, e100, 100 * e100 / reference_100, e1000,
      100 * e1000 / reference_1000, e1000 / e100, e1000 / e10);
  EXPECT_GT(e1000, 0.0);
  EXPECT_NEAR(e1000 / e100, 1.0, 0.10);
  EXPECT_NEAR(e1000 / e10, 1.0, 0.20);
  EXPECT_EQ(thick.newton, 1);
  EXPECT_EQ(thinnest.newton, thick.newton);
}

TEST(PlateClampedSquare, ConvergenceOrderIndependentOfAspectRatio) {
  const double references[] = {1.50462, 1.26533};
  const double slenderness[] = {10, 1000};
  double orders[2];
  for (int k = 0; k < 2; ++k) {
    const double e10 = cached(10, slenderness[k]).w - references[k];
    const double e20 = cached(20, slenderness[k]).w - references[k];
    const double e40 = cached(40, slenderness[k]).w - references[k];
    orders[k] = std::log(e10 / e40) / std::log(4.0);
    std::printf(
        "L/h = %5.0f: errors %.2e, %.2e, %.2e on 10, 20, 40 cells a side: orders %.2f, %.2f (fit "
        "%.2f)\n",
        slenderness[k], e10, e20, e40, std::log2(e10 / e20), std::log2(e20 / e40), orders[k]);
    EXPECT_GT(orders[k], 1.8);
  }
  EXPECT_NEAR(orders[1] / orders[0], 1.0, 0.10);
}

TEST(PlateClampedSquare, NonOrthogonalMesh) {
  const double references[] = {1.50462, 1.26533};
  const double slenderness[] = {10, 1000};
  for (int k = 0; k < 2; ++k) {
    const Centre c = solve(40, slenderness[k], 0.06);
    std::printf(
        "curved 40x40, L/h = %5.0f: w/wref = %.5f (%+.3f %% from the reference), Newton %ld\n",
        slenderness[k], c.w, 100 * (c.w / references[k] - 1), c.newton);
    EXPECT_NEAR(c.w / references[k], 1.0, 0.001);
    EXPECT_EQ(c.newton, 1);
  }
}

// The stopping test scaled to the problem (solvers/kinsol_solver.hpp): a linear plate takes one
// Newton step at any aspect ratio, a/h = 5 to 1e5, though at a/h = 1e4 the residual's terms
// cancel by ~1e8 and a relative reduction of 1e-6 lies below its round-off floor (measured:
// 48 Newton iterations before the floor entered the test). The deflection stays the thin
// plate's (Kirchhoff series 1.26532, 20 x 20 mesh error ~1 %): round-off has not polluted it.
TEST(PlateClampedSquare, OneNewtonStepAtAnyAspectRatio) {
  for (const double slenderness : {5.0, 1e3, 1e4, 1e5}) {
    const Centre c = solve(20, slenderness);
    std::printf("a/h = %.0e  w/wref = %.6f  Newton %ld\n", slenderness, c.w, c.newton);
    EXPECT_EQ(c.newton, 1) << "a/h = " << slenderness;
    if (slenderness >= 1e3) {
      EXPECT_NEAR(c.w / 1.26532, 1.0, 0.02) << "a/h = " << slenderness;
    }
  }
}

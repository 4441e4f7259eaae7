// Cantilever plate under end shear (thesis sec. 3.6.1, Table 3.1): a square plate L x L,
// clamped at x = 0, free long edges y = 0, L, and a uniform transverse shear force
// P = -100 N/m per unit width on the edge x = L. E = 200 GPa, k = 5/6, L/h = 10 and 100.
//
// Reference: beam theory with shear, w_tip = P L^3/(3 D) + P L/(k G h), D = E h^3/12.
// Why nu = 0: with nu != 0 and free long edges a cantilever plate bends anticlastically and its
// tip deflection lies between beam (E) and plate (E/(1-nu^2)) stiffness, with Mindlin boundary
// layers of width ~h along the free edges, so beam theory is not its exact solution. With
// nu = 0 the plate solution is exactly cylindrical and is the Timoshenko beam solution. The
// thesis did the same: its references w = -2.012e-6 m (L/h = 10) and -2.00012e-3 m (L/h = 100)
// are reproduced only with G = E/2, i.e. nu = 0.
//
// The exact solution has w cubic and beta quadratic in x. So:
//  - the default cubic reconstruction (Simpson's shear-strain rule is exact for cubic beta) must
//    reproduce it to round-off on every mesh, 5 x 5 included (thesis: 0.5 %);
//  - the linear reconstruction (degree 1, the thesis's classical scheme) must converge at
//    second order: measured 1.49 %, 0.497 %, 0.140 %, 0.037 % on 5 x 5 ... 40 x 40 (local
//    orders 1.58, 1.83, 1.92; thesis: 0.497 % -> 0.008 %, order 1.99). Asserted: fitted order
//    over 10 x 10 -> 40 x 40 >= 1.8, last local order >= 1.85, 5 x 5 error < 2 %.
// Every solve is one Newton step, for both aspect ratios.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/analytic_elasticity.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/plate/plate_operator.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using Kind = PlateBoundary::Kind;

namespace {

constexpr double L = 1.0, E = 200e9, P = -100.0;

double reference_tip(double h) {
  PlateSection s{E, 0.0, 7854, h};
  return P * L * L * L / (3 * s.bending_stiffness()) + P * L / s.shear_stiffness();
}

struct Result {
  double tip, error;  // error relative to the reference
  long newton;
};

Result solve(int n, double slenderness, int degree) {
  const double h = L / slenderness;
  BoxSpec spec;
  spec.upper = Vec3(L, L, 0);
  spec.n[0] = n;
  spec.n[1] = n;
  Mesh mesh = make_structured_mesh(spec);
  std::vector<PlateBoundary> bcs(mesh.patches().size());
  for (std::size_t p = 0; p < bcs.size(); ++p) {
    const std::string& name = mesh.patches()[p].name;
    if (name == "left")
      bcs[p].kind = Kind::Clamped;
    else if (name == "right")
      bcs[p] = {Kind::Load, [](const Vec3&, double) { return Vec3(P, 0, 0); }};
    else
      bcs[p].kind = Kind::Free;
  }
  PlateOperator op(mesh, {E, 0.0, 7854, h}, bcs, {}, degree);
  StaticSolution s = solve_static(op, 0.0);
  // Tip deflection: mean over the loaded edge of the reconstructed w at the face centroids.
  const Patch& right = mesh.patches()[mesh.find_patch("right")];
  double tip = 0;
  for (Index f = right.first_face; f < right.first_face + right.n_faces; ++f)
    tip += op.deflection_at(mesh.face_owner(f), mesh.face_centroid(f), 0.0, s.y);
  tip /= right.n_faces;
  const double ref = reference_tip(h);
  return {tip, std::abs(tip / ref - 1), s.stats.newton_iters};
}

}  // namespace

TEST(PlateCantilever, ReferenceMatchesThesis) {
  EXPECT_NEAR(reference_tip(L / 10), -2.012e-6, 1e-10);
  EXPECT_NEAR(reference_tip(L / 100), -2.00012e-3, 1e-9);
}

TEST(PlateCantilever, CubicReconstructionIsExactForBeamWithShear) {
  for (double slenderness : {10.0, 100.0})
    for (int n : {5, 10, 20, 40}) {
      Result r = solve(n, slenderness, 3);
      std::printf(
          "cubic  L/h = %5.0f  %2dx%-2d  w_tip = %.8e (ref %.8e)  error %.3e %%  Newton %ld\n",
          slenderness, n, n, r.tip, reference_tip(L / slenderness), 100 * r.error, r.newton);
      EXPECT_LT(r.error, 1e-7);
      EXPECT_EQ(r.newton, 1);
    }
}

TEST(PlateCantilever, LinearReconstructionConvergesAtSecondOrder) {
  for (double slenderness : {10.0, 100.0}) {
    std::vector<double> errors;
    for (int n : {5, 10, 20, 40}) {
      Result r = solve(n, slenderness, 1);
      std::printf("linear L/h = %5.0f  %2dx%-2d  w_tip = %.8e  error %.4f %%  Newton %ld\n",
                  slenderness, n, n, r.tip, 100 * r.error, r.newton);
      errors.push_back(r.error);
      EXPECT_EQ(r.newton, 1);
    }
    const double order = test_support::observed_order(errors[1], errors[3], 4.0);
    const double last = test_support::observed_order(errors[2], errors[3]);
    std::printf("linear L/h = %5.0f  observed order 10x10 -> 40x40 %.3f, 20x20 -> 40x40 %.3f\n",
                slenderness, order, last);
    EXPECT_GT(order, 1.8);
    EXPECT_GT(last, 1.85);
    EXPECT_LT(errors.front(), 0.02);
  }
}

// The MAC Stokes solve (lib/physics/gas/stokes) on plane channels, and its force balance.
//  1. Plane Couette between a wall at rest (y = 0) and one sliding at U (y = H), open ends at
//     p_a = 0, no slip and Maxwell slip l: u = U (l + y) / (H + 2 l), p = 0. Linear profiles
//     are reproduced to round-off (the slip ghost is exact for them), and so is the wall
//     shear force -+ mu U L / (H + 2 l), for both tangential conditions that developed flow
//     satisfies (ZeroGradient, Velocity 0); ZeroStress is not exact there (asserted: the
//     documented reason it is not the default).
//  2. Plane Poiseuille, open ends at p_a = dP and 0: u = G/(2 mu) (y (H - y) + l H),
//     p = dP (1 - x / L), G = dP / L. The discrete solution is that parabola plus the uniform
//     offset G h^2 / (8 mu) (the ghost's linear interpolation across the wall of a quadratic,
//     derived in the test), and the linear pressure exactly; each wall's drag is dP H / 2 to
//     round-off (a conservative scheme: the pressure force on the gas is carried by the walls).
//  3. A beam over a substrate (the damping case in miniature, slip on): the forces on all
//     walls and sides sum to zero and the sides' net outflow is zero, to round-off.
//  4. The continuum limit of the kinetic pressure boundary on an open side (normal impedance
//     Z, slip length l on u_t = 0): a wall injecting V through it (uniform flow, p = p_a + Z V,
//     the wall's normal force -(p_a + Z V) L), and Couette flow under it (u = U (H + l - y) /
//     (H + l), the wall shear mu U / (H + l)), both to round-off; without the impedance the
//     pressure is p_a.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/gas/stokes/stokes_force.hpp"
#include "physics/gas/stokes/stokes_solve.hpp"

using namespace rfmems;

namespace {

constexpr Real kMu = 2.117e-5, kL = 4e-6, kH = 1e-6, kU = 0.3;

StokesBoundaries channel(Real slip, Real top_speed, Real p_left, OpenTangential t) {
  StokesBoundaries b;
  b.sides[static_cast<int>(Side::Left)] = StokesSide::open(p_left, t);
  b.sides[static_cast<int>(Side::Right)] = StokesSide::open(0.0, t);
  b.sides[static_cast<int>(Side::Bottom)] = StokesSide::make_wall({.slip_length = slip});
  b.sides[static_cast<int>(Side::Top)] =
      StokesSide::make_wall({[top_speed](const Point2&) { return Point2(top_speed, 0); }, slip});
  return b;
}

struct ChannelRun {
  Real u_error = 0, v_max = 0, p_error = 0;  // max over faces / cells
  Point2 bottom, top;                        // wall forces
};

template <class U, class P>
ChannelRun run(const MacGrid& g, const StokesBoundaries& b, U exact_u, P exact_p) {
  StokesOperator op(g, {kMu, b, {}});
  const std::vector<Real> x = solve_stokes(op);
  ChannelRun r;
  for (int j = 0; j < g.ny(); ++j)
    for (int i = 0; i <= g.nx(); ++i)
      r.u_error = std::max(r.u_error, std::abs(op.u(i, j)->evaluate(x) - exact_u(g.u_face(i, j))));
  for (int j = 0; j <= g.ny(); ++j)
    for (int i = 0; i < g.nx(); ++i) r.v_max = std::max(r.v_max, std::abs(op.v(i, j)->evaluate(x)));
  for (int j = 0; j < g.ny(); ++j)
    for (int i = 0; i < g.nx(); ++i)
      r.p_error = std::max(r.p_error,
                           std::abs(op.pressure(i, j).evaluate(x) - exact_p(g.cell_centre(i, j))));
  r.bottom = boundary_force(op, x, Across::side(Side::Bottom));
  r.top = boundary_force(op, x, Across::side(Side::Top));
  return r;
}

}  // namespace

TEST(StokesChannel, CouetteExactWithAndWithoutSlip) {
  const MacGrid g(kL, kH, kH / 8);
  for (Real slip : {0.0, 0.1 * kH}) {
    const Real rate = kU / (kH + 2 * slip), drag = kMu * rate * kL;
    auto exact_u = [&](const Point2& p) { return rate * (slip + p.y()); };
    auto zero = [](const Point2&) { return 0.0; };
    for (OpenTangential t : {OpenTangential::ZeroGradient, OpenTangential::Velocity}) {
      const ChannelRun r = run(g, channel(slip, kU, 0.0, t), exact_u, zero);
      EXPECT_LT(r.u_error, 1e-12 * kU) << "slip " << slip;
      EXPECT_LT(r.v_max, 1e-12 * kU);
      EXPECT_LT(r.p_error, 1e-12 * kMu * rate);
      EXPECT_NEAR(r.bottom.x(), drag, 1e-11 * drag);
      EXPECT_NEAR(r.top.x(), -drag, 1e-11 * drag);
      EXPECT_NEAR(r.bottom.y(), 0.0, 1e-11 * drag);
    }
    const ChannelRun r = run(g, channel(slip, kU, 0.0, OpenTangential::ZeroStress), exact_u, zero);
    EXPECT_GT(r.u_error, 1e-3 * kU) << "zero shear at the ends is not Couette flow";
  }
}

TEST(StokesChannel, PoiseuilleParabolaPlusUniformOffsetAndExactDrag) {
  const Real dp = 50.0, grad = dp / kL;
  for (int n : {4, 8}) {
    const Real h = kH / n;
    const MacGrid g(kL, kH, h);
    for (Real slip : {0.0, 0.1 * kH}) {
      // The discrete parabola q = u + delta: the ghost condition (q(h/2) + q(-h/2))/2 - u_w =
      // l (q(h/2) - q(-h/2))/h reads q(0) + q'' h^2/8 - u_w = l q'(0), so delta = G h^2/(8 mu).
      const Real offset = grad * h * h / (8 * kMu);
      auto discrete_u = [&](const Point2& p) {
        return grad / (2 * kMu) * (p.y() * (kH - p.y()) + slip * kH) + offset;
      };
      auto exact_p = [&](const Point2& p) { return dp * (1 - p.x() / kL); };
      const ChannelRun r =
          run(g, channel(slip, 0.0, dp, OpenTangential::ZeroGradient), discrete_u, exact_p);
      const Real u_scale = grad * kH * kH / kMu;
      EXPECT_LT(r.u_error, 1e-11 * u_scale) << "n " << n << " slip " << slip;
      EXPECT_LT(r.v_max, 1e-11 * u_scale);
      EXPECT_LT(r.p_error, 1e-11 * dp);
      EXPECT_NEAR(r.bottom.x(), dp * kH / 2, 1e-10 * dp * kH);
      EXPECT_NEAR(r.top.x(), dp * kH / 2, 1e-10 * dp * kH);
      // The substrate carries the mean pressure: -(dP / 2) L.
      EXPECT_NEAR(r.bottom.y(), -dp * kL / 2, 1e-10 * dp * kL);
    }
  }
}

TEST(StokesChannel, BeamForcesAndFlowsBalance) {
  // 12 x 9 cells of 0.5 um, a beam [0, 3] x [1.5, 2.5] um moving at -0.1 m/s, symmetry at
  // x = 0, open right and top (each tangential condition), slip on every wall.
  const Real h = 0.5e-6, slip = 0.2 * h;
  const MacGrid g(6e-6, 4.5e-6, h, {{0, 3e-6, 1.5e-6, 2.5e-6}});
  for (OpenTangential t :
       {OpenTangential::ZeroGradient, OpenTangential::ZeroStress, OpenTangential::Velocity}) {
    StokesBoundaries b;
    b.sides[static_cast<int>(Side::Left)] = StokesSide::symmetry();
    b.sides[static_cast<int>(Side::Right)] = StokesSide::open(0.0, t);
    b.sides[static_cast<int>(Side::Top)] = StokesSide::open(0.0, t);
    b.sides[static_cast<int>(Side::Bottom)] = StokesSide::make_wall({.slip_length = slip});
    b.blocks = {{[](const Point2&) { return Point2(0, -0.1); }, slip}};
    StokesOperator op(g, {kMu, b, {}});
    const std::vector<Real> x = solve_stokes(op);
    const Point2 beam = boundary_force(op, x, Across::block(0));
    EXPECT_GT(beam.y(), 0) << "the gas resists the beam";
    Point2 total = beam;
    for (Side s : {Side::Left, Side::Right, Side::Bottom, Side::Top})
      total += boundary_force(op, x, Across::side(s));
    EXPECT_LT(total.norm(), 1e-12 * beam.norm());
    const Real q = side_outflow(op, x, Side::Right) + side_outflow(op, x, Side::Top);
    EXPECT_LT(std::abs(q), 1e-12 * 0.1 * 3e-6);
    EXPECT_GT(side_outflow(op, x, Side::Right), 0) << "the gap's gas leaves sideways";
  }
}

TEST(StokesChannel, OpenSideImpedanceAndSlipAreExact) {
  const MacGrid g(kL, kH, kH / 8);
  const Real p_a = 3.0, z = 600.0, v = 0.1, l = 0.1 * kH;
  for (Real impedance : {0.0, z}) {
    // A wall at the bottom injects v; the open top carries it out against p_a + Z v.
    StokesBoundaries b;
    b.sides[static_cast<int>(Side::Left)] = StokesSide::symmetry();
    b.sides[static_cast<int>(Side::Right)] = StokesSide::symmetry();
    b.sides[static_cast<int>(Side::Bottom)] =
        StokesSide::make_wall({[v](const Point2&) { return Point2(0, v); }, 0.0});
    b.sides[static_cast<int>(Side::Top)] = StokesSide::open(p_a, OpenTangential::Velocity);
    b.sides[static_cast<int>(Side::Top)].normal_impedance = impedance;
    const Real p = p_a + impedance * v;
    StokesOperator op(g, {kMu, b, {}});
    const std::vector<Real> x = solve_stokes(op);
    for (int j = 0; j < g.ny(); ++j)
      for (int i = 0; i < g.nx(); ++i)
        EXPECT_NEAR(op.pressure(i, j).evaluate(x), p, 1e-10 * p) << "Z " << impedance;
    const Point2 bottom = boundary_force(op, x, Across::side(Side::Bottom));
    EXPECT_NEAR(bottom.y(), -p * kL, 1e-10 * p * kL);
    EXPECT_NEAR(side_outflow(op, x, Side::Top), v * kL, 1e-12 * v * kL);
  }
  // Couette flow under an open top with u_t = 0 and slip length l: the slip wall's profile.
  StokesBoundaries b;
  b.sides[static_cast<int>(Side::Left)] = StokesSide::open(0.0);
  b.sides[static_cast<int>(Side::Right)] = StokesSide::open(0.0);
  b.sides[static_cast<int>(Side::Bottom)] =
      StokesSide::make_wall({[](const Point2&) { return Point2(kU, 0); }, 0.0});
  b.sides[static_cast<int>(Side::Top)] = StokesSide::open(0.0, OpenTangential::Velocity);
  b.sides[static_cast<int>(Side::Top)].tangential_slip_length = l;
  b.sides[static_cast<int>(Side::Top)].normal_impedance = z;
  auto exact_u = [&](const Point2& q) { return kU * (kH + l - q.y()) / (kH + l); };
  const ChannelRun r = run(g, b, exact_u, [](const Point2&) { return 0.0; });
  const Real drag = kMu * kU / (kH + l) * kL;
  EXPECT_LT(r.u_error, 1e-12 * kU);
  EXPECT_LT(r.v_max, 1e-12 * kU);
  EXPECT_NEAR(r.bottom.x(), -drag, 1e-11 * drag);
}

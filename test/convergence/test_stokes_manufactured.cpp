// Manufactured solution for the MAC Stokes solve (lib/physics/gas/stokes) on the unit square
// with a solid block [0.375, 0.625] x [0.375, 0.5] inside, mu = 1:
//
//   psi = sin(a x + 0.2) sin(b y + 0.3),  u = psi_y,  v = -psi_x  (div u = 0),
//   p = cos(c x + 0.5) sin(d y) + x y,   f = -mu Lap u + grad p = mu (a^2 + b^2) u + grad p,
//
// a = 1.3 pi, b = 1.1 pi, c = 1.7, d = 2.1. Boundaries: left a no-slip wall (the exact
// velocity), bottom a Maxwell slip wall l = 0.05 (wall velocity u - l du/dy, v), top a slip
// wall l = 0.08 (u + l du/dy, n = -y), right open with the exact normal stress
// p_a = p - 2 mu du/dx and the exact tangential velocity, the block a no-slip wall with the
// exact velocity (its corners are re-entrant). Grids 16^2 ... 128^2.
//
// Asserted: observed order (least squares over the four grids) of the velocity L2 error
// (RMS over the unknown faces) >= 1.8, of the velocity max error >= 1.5, of the pressure L2
// error (over the cells) >= 1.5 (measured and printed).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/convergence_order.hpp"
#include "physics/gas/stokes/stokes_solve.hpp"

using namespace rfmems;

namespace {

using rfmems::test_support::fitted_order;

const Real a = 1.3 * M_PI, b = 1.1 * M_PI, c = 1.7, d = 2.1;

Point2 velocity(const Point2& q) {
  const Real x = q.x(), y = q.y();
  return {b * std::sin(a * x + 0.2) * std::cos(b * y + 0.3),
          -a * std::cos(a * x + 0.2) * std::sin(b * y + 0.3)};
}
Real du_dx(const Point2& q) {
  return a * b * std::cos(a * q.x() + 0.2) * std::cos(b * q.y() + 0.3);
}
Real du_dy(const Point2& q) {
  return -b * b * std::sin(a * q.x() + 0.2) * std::sin(b * q.y() + 0.3);
}
Real pressure(const Point2& q) {
  return std::cos(c * q.x() + 0.5) * std::sin(d * q.y()) + q.x() * q.y();
}
Point2 body_force(const Point2& q) {
  const Real x = q.x(), y = q.y();
  const Point2 grad_p(-c * std::sin(c * x + 0.5) * std::sin(d * y) + y,
                      d * std::cos(c * x + 0.5) * std::cos(d * y) + x);
  return (a * a + b * b) * velocity(q) + grad_p;
}

struct Errors {
  Real velocity_l2 = 0, velocity_max = 0, pressure_l2 = 0;
};

Errors solve_on(int n) {
  const Real h = 1.0 / n;
  const MacGrid g(1, 1, h, {{0.375, 0.625, 0.375, 0.5}});
  StokesBoundaries bc;
  const Real l_bottom = 0.05, l_top = 0.08;
  bc.sides[static_cast<int>(Side::Left)] = StokesSide::make_wall({velocity, 0.0});
  bc.sides[static_cast<int>(Side::Bottom)] = StokesSide::make_wall(
      {[=](const Point2& q) {
         return Point2(velocity(q).x() - l_bottom * du_dy(q), velocity(q).y());
       },
       l_bottom});
  bc.sides[static_cast<int>(Side::Top)] = StokesSide::make_wall(
      {[=](const Point2& q) { return Point2(velocity(q).x() + l_top * du_dy(q), velocity(q).y()); },
       l_top});
  StokesSide open = StokesSide::open(0.0, OpenTangential::Velocity);
  open.ambient_pressure = [](const Point2& q) { return pressure(q) - 2 * du_dx(q); };
  open.tangential_velocity = [](const Point2& q) { return velocity(q).y(); };
  bc.sides[static_cast<int>(Side::Right)] = open;
  bc.blocks = {{velocity, 0.0}};
  StokesOperator op(g, {1.0, bc, body_force});
  const std::vector<Real> x = solve_stokes(op);
  Errors e;
  Real count = 0;
  auto add = [&](const std::optional<AffineForm>& f, Real exact) {
    if (!f || f->terms.empty()) return;  // no gas, or a known wall value
    const Real err = std::abs(f->evaluate(x) - exact);
    e.velocity_l2 += err * err;
    e.velocity_max = std::max(e.velocity_max, err);
    count += 1;
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i <= n; ++i) add(op.u(i, j), velocity(g.u_face(i, j)).x());
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i < n; ++i) add(op.v(i, j), velocity(g.v_face(i, j)).y());
  e.velocity_l2 = std::sqrt(e.velocity_l2 / count);
  Real cells = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (g.fluid(i, j)) {
        const Real err = op.pressure(i, j).evaluate(x) - pressure(g.cell_centre(i, j));
        e.pressure_l2 += err * err;
        cells += 1;
      }
  e.pressure_l2 = std::sqrt(e.pressure_l2 / cells);
  return e;
}

}  // namespace

TEST(StokesManufactured, SecondOrderVelocityWithSlipWallsOpenSideAndBlock) {
  std::vector<double> hs, ev, em, ep;
  for (int n : {16, 32, 64, 128}) {
    const Errors e = solve_on(n);
    hs.push_back(1.0 / n);
    ev.push_back(e.velocity_l2);
    em.push_back(e.velocity_max);
    ep.push_back(e.pressure_l2);
    std::printf("n %4d  velocity L2 %.3e  max %.3e  pressure L2 %.3e\n", n, e.velocity_l2,
                e.velocity_max, e.pressure_l2);
  }
  const double ov = fitted_order(hs, ev), om = fitted_order(hs, em), op = fitted_order(hs, ep);
  std::printf("observed orders: velocity L2 %.2f, max %.2f; pressure L2 %.2f\n", ov, om, op);
  EXPECT_GE(ov, 1.8);
  EXPECT_GE(om, 1.5);
  EXPECT_GE(op, 1.5);
}

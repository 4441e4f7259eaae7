// The property that makes the plate locking-free: a Kirchhoff field (beta = -grad w) carries no
// discrete transverse shear. The shear part of the residual is isolated as the difference of
// two residuals whose sections differ only in the shear factor k (the residual is linear in k
// G h), and compared with the shear residual of a field that is not Kirchhoff (beta = 0), on
// an irregular non-orthogonal mesh (so the tangential correction with the cell strains is
// active), with the exact field prescribed on the boundary (Displacement on every edge).
//  - w quartic: the face strains (w_N - w_P)/|d| + Simpson's mean of beta.e, with the cubic
//    reconstruction at the segment midpoint, are exact, so the shear residual vanishes to
//    round-off: asserted < 1e-9 of the non-Kirchhoff one.
//  - w smooth, not polynomial: the defect is already small on 8 x 6 cells (7e-4 of the
//    non-Kirchhoff one) and shrinks at high order (measured 3.2 to 16 x 12, 2.8 to 32 x 24 on
//    these randomly jittered meshes; asserted >= 2.5).
//  - a control: the same quartic field with beta off by 1 % is not Kirchhoff and must show it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>

#include "mesh/structured_mesh.hpp"
#include "physics/plate/plate_operator.hpp"

using namespace rfmems;
using Kind = PlateBoundary::Kind;

namespace {

struct Field {
  std::function<double(const Vec3&)> w;
  std::function<Vec3(const Vec3&)> grad_w;
};

const Field quartic{[](const Vec3& x) {
                      const double X = x.x(), Y = x.y();
                      return 1e-3 *
                             (1 + X + 0.5 * Y + X * X - X * Y + 0.3 * Y * Y + 0.2 * X * X * X -
                              0.1 * X * X * Y + 0.05 * X * Y * Y + 0.1 * Y * Y * Y +
                              0.02 * X * X * X * X - 0.03 * X * X * Y * Y + 0.01 * Y * Y * Y * Y);
                    },
                    [](const Vec3& x) -> Vec3 {
                      const double X = x.x(), Y = x.y();
                      return 1e-3 * Vec3(1 + 2 * X - Y + 0.6 * X * X - 0.2 * X * Y + 0.05 * Y * Y +
                                             0.08 * X * X * X - 0.06 * X * Y * Y,
                                         0.5 - X + 0.6 * Y - 0.1 * X * X + 0.1 * X * Y +
                                             0.3 * Y * Y - 0.06 * X * X * Y + 0.04 * Y * Y * Y,
                                         0.0);
                    }};

const Field smooth{
    [](const Vec3& x) { return 1e-3 * std::sin(2.0 * x.x() + 0.3) * std::cos(1.5 * x.y() - 0.2); },
    [](const Vec3& x) -> Vec3 {
      return 1e-3 * Vec3(2.0 * std::cos(2.0 * x.x() + 0.3) * std::cos(1.5 * x.y() - 0.2),
                         -1.5 * std::sin(2.0 * x.x() + 0.3) * std::sin(1.5 * x.y() - 0.2), 0.0);
    }};

Mesh irregular_mesh(int nx, int ny) {
  auto rng = std::make_shared<std::mt19937>(17);
  const double jitter = 0.15 / nx;
  BoxSpec spec;
  spec.upper = Vec3(2.0, 1.5, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  return make_structured_mesh(spec, [=](const Vec3& x) {
    std::uniform_real_distribution<double> u(-jitter, jitter);
    Vec3 y = x;
    const bool edge_x = x.x() < 1e-12 || x.x() > 2.0 - 1e-12,
               edge_y = x.y() < 1e-12 || x.y() > 1.5 - 1e-12;
    y.x() += 0.1 * std::sin(2.0 * x.y()) * x.x() * (2.0 - x.x()) + (edge_x ? 0.0 : u(*rng));
    y.y() += 0.08 * std::sin(3.0 * x.x()) * x.y() * (1.5 - x.y()) + (edge_y ? 0.0 : u(*rng));
    return y;
  });
}

// Max |shear residual| for the cell values (w, beta_scale * (-grad w)) of the field.
double shear_residual(const Mesh& mesh, const Field& field, double beta_scale) {
  std::vector<PlateBoundary> bcs(mesh.patches().size());
  for (auto& bc : bcs) {
    bc.kind = Kind::Displacement;
    bc.value = [field, beta_scale](const Vec3& x, double) {
      const Vec3 g = field.grad_w(x);
      return Vec3(field.w(x), -beta_scale * g.x(), -beta_scale * g.y());
    };
  }
  std::vector<double> y(3 * mesh.n_cells());
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    const Vec3& x = mesh.cell_centroid(c);
    const Vec3 g = field.grad_w(x);
    y[3 * c] = field.w(x);
    y[3 * c + 1] = -beta_scale * g.x();
    y[3 * c + 2] = -beta_scale * g.y();
  }
  std::vector<double> r1(y.size()), r2(y.size());
  PlateOperator op1(mesh, {200e9, 0.3, 7854, 0.01, 5.0 / 6}, bcs);
  PlateOperator op2(mesh, {200e9, 0.3, 7854, 0.01, 10.0 / 6}, bcs);
  op1.internal_residual(0.0, y, r1);
  op2.internal_residual(0.0, y, r2);
  double worst = 0;
  for (std::size_t i = 0; i < y.size(); ++i) worst = std::max(worst, std::abs(r2[i] - r1[i]));
  return worst;
}

}  // namespace

TEST(PlateKirchhoff, QuarticKirchhoffFieldCarriesNoShear) {
  Mesh mesh = irregular_mesh(8, 6);
  const double kirchhoff = shear_residual(mesh, quartic, 1.0);
  const double not_kirchhoff = shear_residual(mesh, quartic, 0.0);
  const double control = shear_residual(mesh, quartic, 1.01);
  std::printf("quartic: shear residual %.3e (Kirchhoff), %.3e (beta = 0), %.3e (beta 1 %% off)\n",
              kirchhoff, not_kirchhoff, control);
  EXPECT_LT(kirchhoff, 1e-9 * not_kirchhoff);
  EXPECT_GT(control, 1e-3 * not_kirchhoff);
}

TEST(PlateKirchhoff, SmoothKirchhoffFieldDefectIsHighOrder) {
  const double coarse = shear_residual(irregular_mesh(8, 6), smooth, 1.0);
  const double coarse_ref = shear_residual(irregular_mesh(8, 6), smooth, 0.0);
  const double fine = shear_residual(irregular_mesh(16, 12), smooth, 1.0);
  const double fine_ref = shear_residual(irregular_mesh(16, 12), smooth, 0.0);
  const double order = std::log2((coarse / coarse_ref) / (fine / fine_ref));
  std::printf("smooth: relative shear defect %.3e (8x6), %.3e (16x12): order %.2f\n",
              coarse / coarse_ref, fine / fine_ref, order);
  EXPECT_LT(coarse / coarse_ref, 1e-3);
  EXPECT_GT(order, 2.5);
}

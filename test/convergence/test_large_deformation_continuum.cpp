// The total Lagrangian St Venant-Kirchhoff continuum (ElasticityOperator with geometric
// nonlinearity) against the closed forms of slender beams, plane stress.
//
// 1. The cantilever elastica (Bisshopp & Drucker, Large deflection of cantilever beams, Q. Appl.
//    Math. 3 (1945) 272): a cantilever of length L, bending stiffness EI, clamped at x = 0,
//    under a dead tip load P across its axis. With theta(s) the slope, EI theta'' = -P cos theta,
//    theta(0) = 0, theta'(L) = 0, whose first integral EI theta'^2 / 2 = P (sin theta_L -
//    sin theta) gives, with alpha = P L^2 / (EI) and sin theta = s (1 - t^2), s = sin theta_L,
//      sqrt(2 alpha) = int_0^1 2 sqrt(s) / cos theta dt              (the length: fixes s)
//      delta / L    = int_0^1 2 s^(3/2) (1 - t^2) / cos theta dt / sqrt(2 alpha)   (deflection)
//      x_L / L      = 2 sqrt(s) / sqrt(2 alpha)                      (the tip's abscissa)
//    the integrals (Bisshopp & Drucker's elliptic integrals in another variable) by Simpson's
//    rule, s by bisection; alpha -> 0 gives delta/L = alpha/3, and alpha = 1, 2, 3 give
//    Bisshopp & Drucker's 0.3017, 0.4935, 0.6033. The beam: L/H = 40, nu = 0.3, 160 x 4, 8, 16
//    cells (the error of the fully fixed end face goes as the cells across the thickness: 3 %
//    on 4 cells already in the linear limit), the load a traction on the end face, ramped in 8
//    steps of Newton (continuation). alpha = 1, 2, 3 (tip rotations 27-57 degrees).
// 2. A clamped-clamped beam with stretching: the strip of test_von_karman_plate.cpp with
//    D = E H^3/12 and C = E H (plane stress): fixed end faces (immovable), a uniform dead load
//    on its top face, L/H = 50, 200 x 4, 8, 16 cells; loads for centre deflections of 1.5 and 3
//    H, one Newton solve from rest. The continuum converges to within a few 1e-3 of the beam:
//    its transverse shear, which the beam leaves out, adds 48 D/(k G H L^2) = 0.5 % to the
//    deflection of the linear clamped beam at this slenderness, less under tension. Checked:
//    second order in the layers (from the successive differences) and the finest within 3e-3
//    of the closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "../support/convergence_order.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/elasticity/elasticity_operator.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using Kind = ElasticityBoundary::Kind;

namespace {

constexpr double E = 200e9;

double bisect(const std::function<double(double)>& f, double lo, double hi) {
  const bool rising = f(hi) > f(lo);
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((f(mid) > 0) == rising ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// int_0^1 g(t) dt by Simpson's rule on 2000 intervals.
double simpson(const std::function<double(double)>& g) {
  const int n = 2000;
  double sum = 0;
  for (int i = 0; i <= n; ++i) sum += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * g(double(i) / n);
  return sum / (3 * n);
}

struct Elastica {
  double deflection, abscissa;  // delta / L, x_L / L
};
Elastica elastica(double alpha) {
  auto cos_theta = [](double s, double t) {
    const double sin_theta = s * (1 - t * t);
    return std::sqrt(1 - sin_theta * sin_theta);
  };
  auto length = [&](double s) {
    return simpson([&](double t) { return 2 * std::sqrt(s) / cos_theta(s, t); }) -
           std::sqrt(2 * alpha);
  };
  const double s = bisect(length, 1e-12, 1 - 1e-12);
  const double deflection =
      simpson([&](double t) { return 2 * std::pow(s, 1.5) * (1 - t * t) / cos_theta(s, t); }) /
      std::sqrt(2 * alpha);
  return {deflection, 2 * std::sqrt(s) / std::sqrt(2 * alpha)};
}

Mesh beam_mesh(double L, double H, int nx, int ny) {
  BoxSpec spec;
  spec.dim = 2;
  spec.upper = Vec3(L, H, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  return make_structured_mesh(spec);
}

// The displacement at x: the mean of the reconstructions of the cells within a cell of it.
Vec3 displacement(const ElasticityOperator& op, const Vec3& x, std::span<const double> u, double dx,
                  double dy) {
  const std::vector<Mat3> gradients = op.cell_gradients(0.0, u);
  Vec3 sum = Vec3::Zero();
  int count = 0;
  for (Index c = 0; c < op.mesh().n_cells(); ++c) {
    const Vec3 d = op.mesh().cell_centroid(c) - x;
    if (std::abs(d.x()) < dx && std::abs(d.y()) < dy) {
      sum += op.displacement_at(c, x, u, gradients);
      ++count;
    }
  }
  EXPECT_GT(count, 0);
  return sum / count;
}

}  // namespace

TEST(LargeDeformationContinuum, CantileverElasticaUnderATipLoad) {
  EXPECT_NEAR(elastica(1e-4).deflection, 1e-4 / 3, 1e-9);  // the small-deflection limit
  const double L = 1e-3, H = L / 40, I = H * H * H / 12;
  const int nx = 160, layers[3] = {4, 8, 16};
  for (double alpha : {1.0, 2.0, 3.0}) {
    const Elastica exact = elastica(alpha);
    const double P = alpha * E * I / (L * L);  // per unit depth
    double error[3], error_x[3];
    for (int m = 0; m < 3; ++m) {
      const int ny = layers[m];
      Mesh mesh = beam_mesh(L, H, nx, ny);
      std::vector<ElasticityBoundary> bcs(mesh.patches().size());
      for (std::size_t p = 0; p < bcs.size(); ++p) {
        const std::string& name = mesh.patches()[p].name;
        if (name == "left") bcs[p] = {Kind::Fixed, {}};
        if (name == "right")
          bcs[p] = {Kind::Traction,
                    [P, H](const Vec3&, double t) { return Vec3(0, -t * P / H, 0); }};
      }
      ElasticityOperator op(mesh, LinearElastic{E, 0.3, 7854, Hypothesis::PlaneStress}, bcs);
      op.set_geometric_nonlinearity(true);
      std::vector<double> y;
      std::string iterations;
      const int steps = 8;
      for (int k = 1; k <= steps; ++k) {
        StaticSolution sol = solve_static(op, double(k) / steps, {}, y);
        y = std::move(sol.y);
        iterations += std::to_string(sol.stats.newton_iters) + (k < steps ? "," : "");
        EXPECT_LE(sol.stats.newton_iters, 8);
      }
      const Vec3 tip = displacement(op, Vec3(L, H / 2, 0), y, L / nx, H / ny);
      error[m] = std::abs(-tip.y() / L / exact.deflection - 1);
      error_x[m] = std::abs((1 + tip.x() / L) / exact.abscissa - 1);
      std::printf(
          "elastica alpha = %.0f, %d x %2d: delta/L = %.5f (Bisshopp-Drucker %.5f, error %.2e), "
          "x_L/L = %.5f (%.5f, error %.2e), Newton iterations per load step %s\n",
          alpha, nx, ny, -tip.y() / L, exact.deflection, error[m], 1 + tip.x() / L, exact.abscissa,
          error_x[m], iterations.c_str());
    }
    const double p = test_support::fitted_order({4.0, 2.0, 1.0}, {error[0], error[1], error[2]});
    std::printf("  observed order of delta %.2f\n", p);
    EXPECT_GE(p, 1.8);
    EXPECT_LT(error[2], 2e-3);
    EXPECT_LT(error_x[2], 1e-3);
  }
}

// The clamped strip's centre deflection under q (test_von_karman_plate.cpp, 1.), for the beam's
// D and C, at tension parameter u: (q, w0).
std::pair<double, double> clamped_strip_at(double u, double L, double D, double C) {
  const double k = 2 * u / L, S = D * k * k;
  auto slope = [&](double x) { return (L / 2 * std::sinh(k * x) / std::sinh(u) - x) / S; };
  const double integral = L * simpson([&](double t) { return std::pow(slope(-L / 2 + L * t), 2); });
  const double q = std::sqrt(S * L / C / (0.5 * integral));
  return {q, q / S * (L * L / 8 - L / (2 * k) * (std::cosh(u) - 1) / std::sinh(u))};
}

TEST(LargeDeformationContinuum, ClampedClampedBeamWithStretching) {
  const double L = 1e-3, H = L / 50, D = E * H * H * H / 12, C = E * H;
  const int nx = 200, layers[3] = {4, 8, 16};
  for (double target : {1.5, 3.0}) {
    const double u = bisect(
        [&](double u) { return clamped_strip_at(u, L, D, C).second - target * H; }, 1e-2, 50);
    const auto [q, exact] = clamped_strip_at(u, L, D, C);
    double error[3], w[3];
    for (int m = 0; m < 3; ++m) {
      const int ny = layers[m];
      Mesh mesh = beam_mesh(L, H, nx, ny);
      std::vector<ElasticityBoundary> bcs(mesh.patches().size());
      for (std::size_t p = 0; p < bcs.size(); ++p) {
        const std::string& name = mesh.patches()[p].name;
        if (name == "left" || name == "right") bcs[p] = {Kind::Fixed, {}};
        if (name == "top")
          bcs[p] = {Kind::Traction, [q](const Vec3&, double) { return Vec3(0, -q, 0); }};
      }
      ElasticityOperator op(mesh, LinearElastic{E, 0.3, 7854, Hypothesis::PlaneStress}, bcs);
      op.set_geometric_nonlinearity(true);
      const StaticSolution sol = solve_static(op, 0.0);
      const Vec3 centre = displacement(op, Vec3(L / 2, H / 2, 0), sol.y, L / nx, H / ny);
      w[m] = -centre.y();
      error[m] = std::abs(w[m] / exact - 1);
      std::printf(
          "clamped-clamped beam, u = %.3f, %d x %2d: w_c/H = %.5f (closed form %.5f, error "
          "%.2e), Newton iterations %ld\n",
          u, nx, ny, -centre.y() / H, exact / H, error[m], sol.stats.newton_iters);
    }
    // The order in the layers from the successive differences (the limit is not the beam's).
    const double p = std::log2((w[1] - w[0]) / (w[2] - w[1]));
    std::printf("  observed order (successive differences) %.2f\n", p);
    EXPECT_GE(p, 1.8);
    EXPECT_LT(error[2], 3e-3);
  }
}

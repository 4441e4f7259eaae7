// Squeeze-film damping in the incompressible limit (small squeeze number), quasi-static
// linearised Reynolds equation (physics/gas/reynolds_quasi_static.hpp), continuum gas:
//
// 1. Infinite strip of width W (Open long sides at x = 0, W; Wall ends), rigid plate moving
//    with gap rate g' (g' < 0: closing). p'' = 12 mu g' / g^3 with p(0) = p(W) = p_a:
//      p - p_a = -6 mu g' x (W - x) / g^3,    force per length F = -mu W^3 g' / g^3
//    (Griffin 1966, Starr 1990). For this quadratic the cell values are exact up to a uniform
//    shift -k h^2/8 (k = 12 mu g'/g^3; from the half-cell two-point flux at the Open edges)
//    and the cell sum is the midpoint rule (-k h^2 W/24), so the force error is exactly
//    2 (h/W)^2: 0.5 % on 20 cells, observed order 2.
// 2. Rectangular plate a x b, all edges Open (Blech 1983; Bao, "Micro mechanical
//    transducers", ch. 3): laplace(p) = k, p = 0 on the edges, by the double sine series
//      p = -(16 k / pi^4) sum_{m,n odd} sin(m pi x/a) sin(n pi y/b) / (m n (m^2/a^2 + n^2/b^2))
//    integrated over the plate, F = -c g' with
//      c = (768 mu a b^3 / (pi^6 g^3)) sum_{m,n odd} 1 / (m^2 n^2 (m^2 (b/a)^2 + n^2)),
//    which tends to the strip's mu a b^3 / g^3 as a/b -> infinity (sum -> pi^6/768).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesh/structured_mesh.hpp"
#include "physics/gas/reynolds_film.hpp"
#include "physics/gas/reynolds_quasi_static.hpp"

using namespace rfmems;
using std::numbers::pi;

namespace {

// Closing at 0.1 um/s: p - p_a ~ 4 mPa, so the cross term (p - p_a) g' that the first Newton
// step keeps (relative size (p - p_a)/p_a ~ 4e-8) is far below the discretisation error.
constexpr double kGap = 2e-6, kGapRate = -1e-7;

GasProperties continuum_air() {
  GasProperties gas;
  gas.rarefaction = Rarefaction::None;
  return gas;
}

std::vector<FilmBoundary> boundaries(const Mesh& mesh, FilmBoundary::Kind left_right,
                                     FilmBoundary::Kind bottom_top) {
  std::vector<FilmBoundary> bcs(mesh.patches().size());
  for (std::size_t i = 0; i < bcs.size(); ++i) {
    const std::string& name = mesh.patches()[i].name;
    bcs[i].kind = (name == "left" || name == "right") ? left_right : bottom_top;
  }
  return bcs;
}

// Quasi-static film force for a rigid plate over [0, lx] x [0, ly].
double rigid_plate_force(double lx, double ly, int nx, int ny, FilmBoundary::Kind left_right,
                         FilmBoundary::Kind bottom_top) {
  BoxSpec spec;
  spec.upper = Vec3(lx, ly, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  Mesh mesh = make_structured_mesh(spec);
  ReynoldsFilm film(mesh, continuum_air(), boundaries(mesh, left_right, bottom_top));
  std::vector<double> gap(film.size(), kGap), rate(film.size(), kGapRate);
  auto p = quasi_static_pressure(film, gap, rate);
  return film.total_force(p);
}

double blech_incompressible_damping(double mu, double a, double b, double g) {
  double sum = 0;
  const double beta2 = (b / a) * (b / a);
  for (int m = 1; m < 4000; m += 2)
    for (int n = 1; n < 4000; n += 2)
      sum += 1.0 / (double(m) * m * n * n * (m * m * beta2 + double(n) * n));
  return 768.0 * mu * a * b * b * b / (std::pow(pi, 6) * g * g * g) * sum;
}

TEST(ReynoldsIncompressible, StripForceAndSecondOrderConvergence) {
  const double W = 100e-6, length = 10e-6, mu = continuum_air().viscosity;
  const double exact = -mu * W * W * W * kGapRate / (kGap * kGap * kGap);  // per length, > 0
  std::vector<double> errors;
  for (int nx : {10, 20, 40, 80}) {
    // Long in y: one cell between the Wall ends makes the film exactly one-dimensional.
    double force =
        rigid_plate_force(W, length, nx, 1, FilmBoundary::Kind::Open, FilmBoundary::Kind::Wall) /
        length;
    double error = std::abs(force / exact - 1);
    std::printf("strip nx = %d: F = %.6e N/m (exact %.6e), error %.3e, 2 (h/W)^2 = %.3e\n", nx,
                force, exact, error, 2.0 / (nx * nx));
    EXPECT_GT(force, 0);  // a closing gap pushes the plate away from the substrate
    EXPECT_NEAR(error, 2.0 / (nx * nx), 1e-6);
    errors.push_back(error);
  }
  EXPECT_LE(errors[1], 0.01);  // 20 cells across
  for (std::size_t k = 1; k < errors.size(); ++k) {
    double order = std::log2(errors[k - 1] / errors[k]);
    std::printf("observed order %.3f\n", order);
    EXPECT_NEAR(order, 2.0, 0.01);
  }
  // The same strip turned by 90 degrees (Open bottom/top, Wall left/right).
  double turned =
      rigid_plate_force(length, W, 1, 40, FilmBoundary::Kind::Wall, FilmBoundary::Kind::Open) /
      length;
  EXPECT_NEAR(turned / exact - 1, 2.0 / (40 * 40), 1e-6);
}

TEST(ReynoldsIncompressible, RectangularPlateMatchesBlechSeries) {
  const double a = 200e-6, b = 100e-6, mu = continuum_air().viscosity;
  const double c = blech_incompressible_damping(mu, a, b, kGap);
  // The series against its long-plate limit: aspect 2 loses ~ 0.63 b/a of the strip value.
  const double strip = mu * a * b * b * b / (kGap * kGap * kGap);
  std::printf("Blech c = %.6e N s/m, strip limit %.6e, ratio %.4f\n", c, strip, c / strip);
  EXPECT_NEAR(blech_incompressible_damping(mu, 200 * b, b, kGap) /
                  (mu * 200 * b * b * b * b / (kGap * kGap * kGap)),
              1.0, 0.01);  // 1 - 0.63/200
  std::vector<double> errors;
  for (int n : {10, 20, 40}) {
    double force =
        rigid_plate_force(a, b, 2 * n, n, FilmBoundary::Kind::Open, FilmBoundary::Kind::Open);
    double damping = -force / kGapRate;
    double error = std::abs(damping / c - 1);
    std::printf("plate %d x %d: c = %.6e, error %.3e\n", 2 * n, n, damping, error);
    errors.push_back(error);
  }
  EXPECT_LE(errors[1], 0.01);  // 40 x 20 cells
  EXPECT_LE(errors[2], 0.003);
  for (std::size_t k = 1; k < errors.size(); ++k) {
    double order = std::log2(errors[k - 1] / errors[k]);
    std::printf("observed order %.3f\n", order);
    EXPECT_GE(order, 1.9);
  }
}

}  // namespace

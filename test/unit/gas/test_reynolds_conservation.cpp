// Mass conservation of the squeeze film with sealed (Wall) edges:
//  1. the flux part of the residual sums to zero over the cells to round-off, on a skewed
//     mesh with Veijola rarefaction and random p and gap (each interior flux leaves one cell
//     and enters its neighbour);
//  2. the film mass sum_c A_c p_c g_c stays constant to ~1e-12 relative over an IDA run in
//     which a non-uniform gap (a bending plate, amplitude 30 % of the gap) pumps gas around,
//     when IDA integrates the conserved variable y = p g / g_ref; with y = p (the product rule
//     on BDF derivatives) the drift is at the truncation-error level, which is printed and
//     bounded too.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>

#include "mesh/structured_mesh.hpp"
#include "physics/gas/reynolds_film.hpp"
#include "physics/gas/reynolds_prescribed_motion.hpp"
#include "solvers/ida_integrator.hpp"

using namespace rfmems;

namespace {

constexpr double kLength = 200e-6, kWidth = 100e-6, kGap = 2e-6;

Mesh skewed_mesh(int nx, int ny) {
  BoxSpec spec;
  spec.upper = Vec3(kLength, kWidth, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  spec.grading[1] = 1.4;
  auto rng = std::make_shared<std::mt19937>(11);
  return make_structured_mesh(spec, [rng](const Vec3& x) {
    std::uniform_real_distribution<double> jitter(-1e-6, 1e-6);
    Vec3 y = x;
    y.x() += 0.3 * x.y() + jitter(*rng);
    y.y() += 4e-6 * std::sin(x.x() / kLength * 5.0) + jitter(*rng);
    return y;
  });
}

std::vector<FilmBoundary> walls(const Mesh& mesh) {
  return std::vector<FilmBoundary>(mesh.patches().size(), {FilmBoundary::Kind::Wall});
}

TEST(ReynoldsConservation, FluxesCancelToRoundOff) {
  Mesh mesh = skewed_mesh(15, 9);
  ReynoldsFilm film(mesh, GasProperties{}, walls(mesh));
  const Index n = film.size();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> pressure(5e4, 2e5), gap(0.5e-6, 3e-6);
  std::vector<double> p(n), g(n), zero(n, 0.0), r(n);
  for (Index c = 0; c < n; ++c) {
    p[c] = pressure(rng);
    g[c] = gap(rng);
  }
  film.residual(p, zero, g, zero, r);  // r_c = -sum_f flux_f
  double sum = 0, scale = 0;
  for (double v : r) {
    sum += v;
    scale += std::abs(v);
  }
  ASSERT_GT(scale, 0);
  std::printf("|sum flux| / sum |flux| = %.2e\n", std::abs(sum) / scale);
  EXPECT_LE(std::abs(sum), 1e-14 * scale);
}

struct MassHistory {
  double max_relative_drift = 0;
  double max_pressure_swing = 0;  // max |p - p_a| / p_a seen
  long steps = 0;
};

MassHistory run(ReynoldsPrescribedMotion::Unknown unknown) {
  Mesh mesh = skewed_mesh(15, 9);
  GasProperties gas;
  ReynoldsFilm film(mesh, gas, walls(mesh));
  // A plate bending in its first mode along x, sigma ~ 10 at the plate length.
  const double omega = 4.5e5, amplitude = 0.3;
  auto shape = [](const Vec3& x) { return std::cos(std::numbers::pi * x.x() / kLength); };
  auto gap = [&](const Vec3& x, double t) {
    return kGap * (1 + amplitude * shape(x) * std::sin(omega * t));
  };
  auto gap_rate = [&](const Vec3& x, double t) {
    return kGap * amplitude * shape(x) * omega * std::cos(omega * t);
  };
  ReynoldsPrescribedMotion op(film, gap, gap_rate, unknown);
  std::vector<double> p0(op.size(), gas.ambient_pressure);
  auto y0 = op.state(0, p0);
  IdaOptions options;
  options.rtol = 1e-6;
  options.atol = 1e-6 * gas.ambient_pressure;
  IdaIntegrator ida(op, options);
  ida.initialize(0, y0, op.consistent_rate(0, y0));
  const double mass0 = op.mass(0, y0);
  MassHistory h;
  const double period = 2 * std::numbers::pi / omega;
  for (int k = 1; k <= 80; ++k) {
    double t = k * 2 * period / 80;
    ida.advance(t);
    std::vector<double> y(ida.y().begin(), ida.y().end());
    h.max_relative_drift = std::max(h.max_relative_drift, std::abs(op.mass(t, y) / mass0 - 1));
    for (double p : op.pressure(t, y))
      h.max_pressure_swing = std::max(h.max_pressure_swing, std::abs(p / gas.ambient_pressure - 1));
  }
  h.steps = ida.stats().steps;
  return h;
}

TEST(ReynoldsConservation, IdaRunKeepsTheFilmMassWithTheConservedUnknown) {
  MassHistory h = run(ReynoldsPrescribedMotion::Unknown::GapPressure);
  std::printf("y = p g / g_ref: %ld steps, pressure swing %.3f, mass drift %.2e\n", h.steps,
              h.max_pressure_swing, h.max_relative_drift);
  EXPECT_GT(h.max_pressure_swing, 0.05);  // the gas really moves
  EXPECT_LE(h.max_relative_drift, 1e-12);
}

TEST(ReynoldsConservation, IdaRunWithThePressureUnknownDriftsOnlyAtTruncationLevel) {
  MassHistory h = run(ReynoldsPrescribedMotion::Unknown::Pressure);
  std::printf("y = p: %ld steps, pressure swing %.3f, mass drift %.2e\n", h.steps,
              h.max_pressure_swing, h.max_relative_drift);
  EXPECT_GT(h.max_pressure_swing, 0.05);
  EXPECT_LE(h.max_relative_drift, 1e-4);
}

}  // namespace

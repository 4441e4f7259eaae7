// Compressible squeeze film under harmonic plate motion: spring and damping forces against
// Blech's series (J. J. Blech, "On isothermal squeeze films", J. Lubrication Technology 105
// (1983) 615-620; Bao, "Micro mechanical transducers", ch. 3).
//
// Rigid rectangular plate a x b, all edges Open, gap g = g0 (1 + eps sin(w t)) (gap increase
// z = g0 eps sin(w t)). Linearising p = p_a (1 + psi), the film obeys
//   (g0^2 p_a / (12 mu)) laplace(psi) = psi' + eps w cos(w t),
// and with the squeeze number sigma = 12 mu w b^2 / (p_a g0^2), K_mn = m^2 (b/a)^2 + n^2,
// the force F = -k_s z - c z' has (m, n odd)
//   k_s = (64 sigma^2 p_a a b / (pi^4 g0)) sum 1 / (m^2 n^2 (pi^4 K_mn^2 + sigma^2))
//   c w = (64 sigma p_a a b / (pi^2 g0)) sum K_mn / (m^2 n^2 (pi^4 K_mn^2 + sigma^2)).
// At small sigma the film is a damper (c -> the incompressible Blech value); as sigma grows
// the gas cannot escape in one period and the spring force takes over.
//
// The full nonlinear film (y = p) is integrated by IDA from p = p_a for enough periods that
// the start-up transient (slowest decay exp(-pi^2 K_11 w t / sigma)) is below 1e-8; k_s and
// c are the sin and cos Fourier coefficients of the force over the last period (64 uniform
// samples: exact for the harmonics below 32 w). eps = 1 % keeps the nonlinear part of the
// first harmonic at ~eps^2.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesh/structured_mesh.hpp"
#include "physics/gas/reynolds_film.hpp"
#include "physics/gas/reynolds_prescribed_motion.hpp"
#include "solvers/ida_integrator.hpp"

using namespace rfmems;
using std::numbers::pi;

namespace {

constexpr double kA = 200e-6, kB = 100e-6, kGap = 2e-6, kEps = 0.01;

struct SpringDamper {
  double spring;   // k_s [N/m]
  double damping;  // c [N s/m]
};

SpringDamper blech(double sigma, double omega, double pa) {
  double s_spring = 0, s_damping = 0;
  const double beta2 = (kB / kA) * (kB / kA);
  for (int m = 1; m < 2000; m += 2)
    for (int n = 1; n < 2000; n += 2) {
      double K = m * m * beta2 + double(n) * n;
      double den = double(m) * m * n * n * (std::pow(pi, 4) * K * K + sigma * sigma);
      s_spring += 1.0 / den;
      s_damping += K / den;
    }
  return {64 * sigma * sigma * pa * kA * kB / (std::pow(pi, 4) * kGap) * s_spring,
          64 * sigma * pa * kA * kB / (pi * pi * kGap) * s_damping / omega};
}

SpringDamper simulate(double sigma, int periods, int nx, int ny) {
  BoxSpec spec;
  spec.upper = Vec3(kA, kB, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  Mesh mesh = make_structured_mesh(spec);
  GasProperties gas;
  gas.rarefaction = Rarefaction::None;
  const double pa = gas.ambient_pressure;
  const double omega = sigma * pa * kGap * kGap / (12 * gas.viscosity * kB * kB);
  ReynoldsFilm film(mesh, gas,
                    std::vector<FilmBoundary>(mesh.patches().size(), {FilmBoundary::Kind::Open}));
  auto gap = [&](const Vec3&, double t) { return kGap * (1 + kEps * std::sin(omega * t)); };
  auto gap_rate = [&](const Vec3&, double t) { return kGap * kEps * omega * std::cos(omega * t); };
  ReynoldsPrescribedMotion op(film, gap, gap_rate);
  std::vector<double> p0(op.size(), pa);
  IdaOptions options;
  options.rtol = 1e-9;  // on p ~ p_a: 1e-4 Pa against a ~1 kPa pressure swing
  options.atol = 1e-9 * pa;
  IdaIntegrator ida(op, options);
  ida.initialize(0, p0, op.consistent_rate(0, p0));
  const double period = 2 * pi / omega;
  const int samples = 64;
  ida.advance((periods - 1) * period);
  double fs = 0, fc = 0;
  for (int k = 1; k <= samples; ++k) {
    double t = (periods - 1) * period + k * period / samples;
    ida.advance(t);
    double force = film.total_force(ida.y());
    fs += 2.0 / samples * force * std::sin(omega * t);
    fc += 2.0 / samples * force * std::cos(omega * t);
  }
  std::printf("sigma = %g: %ld IDA steps\n", sigma, ida.stats().steps);
  // F = -k_s z - c z',  z = g0 eps sin(w t).
  return {-fs / (kGap * kEps), -fc / (kGap * kEps * omega)};
}

struct Errors {
  double spring, damping;
};

Errors compare(double sigma, int periods, int nx, int ny, SpringDamper* out = nullptr) {
  const double pa = GasProperties{}.ambient_pressure;
  const double mu = GasProperties{}.viscosity;
  const double omega = sigma * pa * kGap * kGap / (12 * mu * kB * kB);
  SpringDamper exact = blech(sigma, omega, pa);
  SpringDamper fv = simulate(sigma, periods, nx, ny);
  Errors e{fv.spring / exact.spring - 1, fv.damping / exact.damping - 1};
  std::printf(
      "sigma = %g, %d x %d: k_s = %.5e N/m (Blech %.5e, %+.2f %%), c = %.5e N s/m "
      "(Blech %.5e, %+.2f %%)\n",
      sigma, nx, ny, fv.spring, exact.spring, 100 * e.spring, fv.damping, exact.damping,
      100 * e.damping);
  if (out) *out = fv;
  return e;
}

TEST(ReynoldsCompressible, SpringAndDampingForcesFollowBlech) {
  // sigma = 5: damping and spring of the same order.
  SpringDamper low, high;
  Errors e5 = compare(5.0, 4, 40, 20, &low);
  EXPECT_LE(std::abs(e5.spring), 0.01);
  EXPECT_LE(std::abs(e5.damping), 0.01);
  // sigma = 50: mostly a spring; the damping (~1/40 of the incompressible value) comes from
  // the edge layers, of width ~ b sqrt(pi^2/sigma), so it needs a finer mesh for 1 %.
  Errors e50 = compare(50.0, 16, 40, 20, &high);
  EXPECT_LE(std::abs(e50.spring), 0.01);
  EXPECT_LE(std::abs(e50.damping), 0.025);
  Errors e50_fine = compare(50.0, 16, 80, 40);
  EXPECT_LE(std::abs(e50_fine.spring), 0.005);
  EXPECT_LE(std::abs(e50_fine.damping), 0.01);
  EXPECT_GT(std::log2(e50.damping / e50_fine.damping), 1.8);  // second order
  // From a damper to a gas spring: k_s grows ~7-fold from sigma = 5 to 50, c drops ~10-fold.
  EXPECT_GT(high.spring, 5 * low.spring);
  EXPECT_LT(high.damping, 0.2 * low.damping);
}

}  // namespace

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
//
// The same film's harmonic response (solvers/harmonic_response.hpp: the linearised film, one
// complex solve per frequency) gives k_s = -Re F and c = -Im F / w of the force per unit gap
// amplitude directly: against Blech for sigma = 0.5 to 500 on 40 x 20 to 160 x 80 cells (orders
// 1.93-2.06), and against the transient on the same mesh (4.6e-4 and 2.7e-5 apart: the
// transient's eps^2 nonlinearity).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesh/structured_mesh.hpp"
#include "physics/gas/reynolds_film.hpp"
#include "physics/gas/reynolds_prescribed_motion.hpp"
#include "solvers/harmonic_response.hpp"
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

// The plate's a x b mesh, the continuum gas, and w of a squeeze number.
Mesh plate_mesh(int nx, int ny) {
  BoxSpec spec;
  spec.upper = Vec3(kA, kB, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  return make_structured_mesh(spec);
}

GasProperties continuum_gas() {
  GasProperties gas;
  gas.rarefaction = Rarefaction::None;
  return gas;
}

double squeeze_frequency(double sigma, const GasProperties& gas) {
  return sigma * gas.ambient_pressure * kGap * kGap / (12 * gas.viscosity * kB * kB);
}

SpringDamper simulate(double sigma, int periods, int nx, int ny) {
  const Mesh mesh = plate_mesh(nx, ny);
  const GasProperties gas = continuum_gas();
  const double pa = gas.ambient_pressure, omega = squeeze_frequency(sigma, gas);
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
  const double omega = squeeze_frequency(sigma, continuum_gas());
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

// k_s and c of the linearised film on nx x ny cells: the force's complex amplitude per unit
// amplitude of the gap g = g0 + Re(dg exp(i w t)), F = -(k_s + i w c) dg.
SpringDamper harmonic(double sigma, int nx, int ny, long* factorizations = nullptr) {
  const Mesh mesh = plate_mesh(nx, ny);
  const GasProperties gas = continuum_gas();
  const double pa = gas.ambient_pressure, omega = squeeze_frequency(sigma, gas);
  ReynoldsFilm film(mesh, gas,
                    std::vector<FilmBoundary>(mesh.patches().size(), {FilmBoundary::Kind::Open}));
  double gap = kGap, rate = 0;
  ReynoldsPrescribedMotion op(film, [&](double, std::span<double> g, std::span<double> gr) {
    std::fill(g.begin(), g.end(), gap);
    std::fill(gr.begin(), gr.end(), rate);
  });
  const Index n = op.size();
  const std::vector<double> p0(n, pa), zero(n, 0.0);
  // The forcing per unit gap amplitude: F's change with the gap and with its rate, by
  // differences (F is linear in g' and has no g-derivative at uniform pressure: exact).
  std::vector<double> r0(n), r(n), b_value(n), b_rate(n);
  const double step = 1e-6 * kGap;
  op.residual(0, p0, zero, r0);
  gap = kGap + step;
  op.residual(0, p0, zero, r);
  for (Index c = 0; c < n; ++c) b_value[c] = (r[c] - r0[c]) / step;
  gap = kGap;
  rate = step;
  op.residual(0, p0, zero, r);
  for (Index c = 0; c < n; ++c) b_rate[c] = (r[c] - r0[c]) / step;
  rate = 0;
  HarmonicResponse response(op, 0.0, p0);
  const std::vector<std::complex<double>> x = response.solve(omega, b_value, b_rate);
  std::complex<double> force = 0;
  for (Index c = 0; c < n; ++c) force += mesh.cell_volume(c) * x[c];
  if (factorizations) *factorizations = response.fresh_factorizations();
  return {-force.real(), -force.imag() / omega};
}

}  // namespace

TEST(ReynoldsCompressible, HarmonicResponseFollowsBlechAtSecondOrder) {
  const double pa = GasProperties{}.ambient_pressure;
  for (const double sigma : {0.5, 5.0, 50.0, 500.0}) {
    const double omega = squeeze_frequency(sigma, continuum_gas());
    const SpringDamper exact = blech(sigma, omega, pa);
    double spring[3], damping[3];
    const int meshes[3] = {20, 40, 80};
    for (int m = 0; m < 3; ++m) {
      const SpringDamper h = harmonic(sigma, 2 * meshes[m], meshes[m]);
      spring[m] = std::abs(h.spring / exact.spring - 1);
      damping[m] = std::abs(h.damping / exact.damping - 1);
      std::printf(
          "harmonic sigma = %5g, %3d x %2d: k_s = %.6e (Blech %.6e, %.2e), c = %.6e "
          "(Blech %.6e, %.2e)\n",
          sigma, 2 * meshes[m], meshes[m], h.spring, exact.spring, spring[m], h.damping,
          exact.damping, damping[m]);
    }
    const double p_spring = std::log2(spring[1] / spring[2]);
    const double p_damping = std::log2(damping[1] / damping[2]);
    std::printf("harmonic sigma = %5g: observed orders %.2f (k_s), %.2f (c)\n", sigma, p_spring,
                p_damping);
    EXPECT_GT(p_spring, 1.8) << "sigma " << sigma;
    EXPECT_GT(p_damping, 1.8) << "sigma " << sigma;
    // At sigma = 500 the damping lives in edge layers ~ b pi/sqrt(sigma) wide, 5 cells of the
    // finest mesh (measured 1.0e-2 there, 3.4e-4 to 1.2e-3 otherwise).
    EXPECT_LT(spring[2], 2e-3) << "sigma " << sigma;
    EXPECT_LT(damping[2], sigma < 100 ? 2e-3 : 0.015) << "sigma " << sigma;
  }
  // One factorisation per frequency.
  long factorizations = 0;
  harmonic(5.0, 40, 20, &factorizations);
  EXPECT_EQ(factorizations, 1);
}

TEST(ReynoldsCompressible, HarmonicResponseIsTheTransientsPeriodicState) {
  SpringDamper transient;
  compare(5.0, 4, 40, 20, &transient);
  const SpringDamper h = harmonic(5.0, 40, 20);
  std::printf("sigma = 5, 40 x 20: harmonic k_s %.6e, c %.6e; transient %+.2e, %+.2e\n", h.spring,
              h.damping, transient.spring / h.spring - 1, transient.damping / h.damping - 1);
  // The transient's own nonlinearity is of order eps^2 = 1e-4.
  EXPECT_NEAR(transient.spring / h.spring, 1.0, 1e-3);
  EXPECT_NEAR(transient.damping / h.damping, 1.0, 1e-3);
}

// The first natural frequencies of the two vibration cases from the modal analysis (the cases'
// structures as rfmems-solid builds them, analysis.type modal), against the references their
// transients are checked against.
//
// cases/plate_vibration (fixed-fixed Mindlin plate strip, L/h = 200, nu = 0, 40 x 4 cells, a
// step pressure: the modes are those about the loaded static state, the same for this linear
// model): the thesis's 1.03 (h/L^2) sqrt(E/rho) = 6.497e4 Hz (the transient test asserts 0.5 %)
// and Euler-Bernoulli 4.7300^2 / (2 pi sqrt 12) (h/L^2) sqrt(E/rho) = 6.4839e4 Hz. Measured:
// 6.48416e4 Hz, -0.20 % and +0.003 %; the transient of the same case gives 6.4880e4 Hz
// (python/probe_frequency.py on its 'centre' probe; docs/modal.md).
//
// cases/cantilever_vibration (plane stress, L = 2 m, h = 0.04 m, 160 x 16 cells): Euler-
// Bernoulli f1 = 1.8751^2 / (2 pi L^2) sqrt(E h^2 / (12 rho)) = 8.1518 Hz, and the Timoshenko
// beam (shear with Cowper's kappa = 10 (1 + nu) / (12 + 11 nu) and rotary inertia), whose
// clamped-free frequency is found here by shooting: the 4 x 4 first-order system
//   w' = phi + Q / (kappa G A),  phi' = M / (E I),  M' = -Q - rho I omega^2 phi,
//   Q' = -rho A omega^2 w,
// integrated (RK4, 4000 steps) from the clamped end (w = phi = 0) for two independent starts,
// the determinant of (M, Q) at the free end a function of omega whose root (secant) is the
// frequency. Measured: 8.1601 Hz modal, +0.10 % vs Euler-Bernoulli, +0.13 % vs Timoshenko
// (8.1492 Hz, -0.03 % from Euler-Bernoulli). Asserted: within 0.5 % of both, and the mode
// is real and, the structure's default Kelvin-Voigt grid damping included, a damping ratio
// beta omega / 2 below 1e-4.
//
// cases/clamped_plate (clamped square Mindlin plate, a = 400 um, a/h = 100, nu = 0.3, 40 x 40
// cells; the case's pressure only sets the state): omega a^2 sqrt(rho h / D) = 35.985 for the
// first mode and 73.394 for the degenerate second and third (Leissa, "Vibration of Plates",
// NASA SP-160, 1969, clamped square plate, thin-plate theory). Measured: -0.10 % and -0.15 %
// (shear and the mesh lower them), modes 2 and 3 equal to 1e-9. Asserted: within 0.5 %, the
// pair equal to 1e-6.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "io/case_file.hpp"
#include "physics/structure/modal_analysis.hpp"
#include "physics/structure/structure_from_case.hpp"

using namespace rfmems;

namespace {

StructuralModes case_modes(const std::string& name, Index modes,
                           const std::vector<std::string>& sets = {}) {
  const std::string dir = std::string(RFMEMS_SOURCE_DIR) + "/cases/" + name;
  const CaseFile cf = CaseFile::load(dir + "/case.yaml", sets);
  std::unique_ptr<StructuralModel> model = build_structure(cf.root(), dir, AnalysisType::Modal);
  return structural_modes(*model, modes, 0.0);
}

// The Timoshenko cantilever's first angular frequency (see the banner).
double timoshenko_cantilever(double L, double h, double E, double nu, double rho) {
  const double A = h, I = h * h * h / 12, G = E / (2 * (1 + nu));
  const double kappa = 10 * (1 + nu) / (12 + 11 * nu);
  auto end_determinant = [&](double omega) {
    const double w2 = omega * omega;
    auto rhs = [&](const Eigen::Vector4d& y) {  // (w, phi, M, Q)
      return Eigen::Vector4d(y[1] + y[3] / (kappa * G * A), y[2] / (E * I),
                             -y[3] - rho * I * w2 * y[1], -rho * A * w2 * y[0]);
    };
    Eigen::Matrix2d end;
    for (int start = 0; start < 2; ++start) {
      Eigen::Vector4d y(0, 0, start == 0 ? 1.0 : 0.0, start == 1 ? 1.0 : 0.0);
      const int steps = 4000;
      const double dx = L / steps;
      for (int i = 0; i < steps; ++i) {
        const Eigen::Vector4d k1 = rhs(y), k2 = rhs(y + 0.5 * dx * k1), k3 = rhs(y + 0.5 * dx * k2),
                              k4 = rhs(y + dx * k3);
        y += dx / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      }
      end.col(start) = Eigen::Vector2d(y[2], y[3]);
    }
    return end.determinant();
  };
  // Secant from the Euler-Bernoulli value and 1 % below it.
  const double eb = 1.875104068711961 * 1.875104068711961 / (L * L) * std::sqrt(E * I / (rho * A));
  double a = eb, b = 0.99 * eb, fa = end_determinant(a), fb = end_determinant(b);
  for (int i = 0; i < 50 && std::abs(b - a) > 1e-13 * eb; ++i) {
    const double c = b - fb * (b - a) / (fb - fa);
    a = b;
    fa = fb;
    b = c;
    fb = end_determinant(b);
  }
  return b;
}

}  // namespace

TEST(ModalCases, PlateVibrationFirstFrequency) {
  const StructuralModes r = case_modes("plate_vibration", 3);
  const double L = 400e-6, h = 2e-6, E = 200e9, rho = 7854;
  const double thesis = 1.03 * h / (L * L) * std::sqrt(E / rho);
  const double bL = 4.730040744862704;
  const double euler_bernoulli =
      bL * bL / (2 * std::numbers::pi * std::sqrt(12.0)) * h / (L * L) * std::sqrt(E / rho);
  const StructuralMode& first = r.stats.modes[0];
  std::printf(
      "plate_vibration: f1 = %.6e Hz, %+.3e vs the thesis's %.6e, %+.3e vs "
      "Euler-Bernoulli %.6e; loaded state: %s\n",
      first.frequency, first.frequency / thesis - 1, thesis, first.frequency / euler_bernoulli - 1,
      euler_bernoulli, r.stats.at_rest ? "no" : "yes");
  EXPECT_FALSE(r.stats.at_rest);  // the case's pressure: linearised about its static state
  EXPECT_LT(std::abs(first.frequency / thesis - 1), 5e-3);
  EXPECT_LT(std::abs(first.frequency / euler_bernoulli - 1), 1e-3);
  EXPECT_FALSE(first.complex);
  EXPECT_EQ(first.damping_ratio, 0.0);
  // The second bending mode (antisymmetric) of the clamped-clamped beam: b L = 7.8532.
  const double bL2 = 7.853204624095838;
  EXPECT_LT(std::abs(r.stats.modes[1].frequency / (euler_bernoulli * std::pow(bL2 / bL, 2)) - 1),
            5e-3);
}

TEST(ModalCases, CantileverVibrationFirstFrequency) {
  const double L = 2.0, h = 0.04, E = 200e9, nu = 0.31, rho = 7854;
  const double euler_bernoulli = 1.875104068711961 * 1.875104068711961 /
                                 (2 * std::numbers::pi * L * L) * std::sqrt(E * h * h / (12 * rho));
  const double timoshenko = timoshenko_cantilever(L, h, E, nu, rho) / (2 * std::numbers::pi);
  EXPECT_LT(timoshenko, euler_bernoulli);
  EXPECT_GT(timoshenko, 0.998 * euler_bernoulli);  // shear and rotary inertia: ~(h/L)^2
  const StructuralModes r = case_modes("cantilever_vibration", 2);
  const StructuralMode& first = r.stats.modes[0];
  std::printf(
      "cantilever_vibration: f1 = %.6f Hz, Euler-Bernoulli %.6f (%+.3e), Timoshenko %.6f "
      "(%+.3e), damping ratio %.3e\n",
      first.frequency, euler_bernoulli, first.frequency / euler_bernoulli - 1, timoshenko,
      first.frequency / timoshenko - 1, first.damping_ratio);
  EXPECT_LT(std::abs(first.frequency / euler_bernoulli - 1), 5e-3);
  EXPECT_LT(std::abs(first.frequency / timoshenko - 1), 5e-3);
  EXPECT_FALSE(first.complex);
  EXPECT_GE(first.damping_ratio, 0.0);
  EXPECT_LT(first.damping_ratio, 1e-4);
  EXPECT_LT(first.residual, 1e-6);
}

TEST(ModalCases, ClampedSquarePlateAgainstLeissa) {
  const double a = 400e-6, h = 4e-6, E = 200e9, nu = 0.3, rho = 7854;
  const double D = E * h * h * h / (12 * (1 - nu * nu));
  const double scale = std::sqrt(D / (rho * h)) / (a * a * 2 * std::numbers::pi);
  const StructuralModes r = case_modes("clamped_plate", 3);
  const auto& m = r.stats.modes;
  std::printf("clamped_plate: f = %.6e, %.6e, %.6e Hz; Leissa %.6e (%+.3e), %.6e (%+.3e)\n",
              m[0].frequency, m[1].frequency, m[2].frequency, 35.985 * scale,
              m[0].frequency / (35.985 * scale) - 1, 73.394 * scale,
              m[1].frequency / (73.394 * scale) - 1);
  EXPECT_LT(std::abs(m[0].frequency / (35.985 * scale) - 1), 5e-3);
  EXPECT_LT(std::abs(m[1].frequency / (73.394 * scale) - 1), 5e-3);
  EXPECT_LT(std::abs(m[2].frequency / m[1].frequency - 1), 1e-6);  // the degenerate pair
  for (const StructuralMode& mode : m) EXPECT_LT(mode.residual, 1e-8);
}

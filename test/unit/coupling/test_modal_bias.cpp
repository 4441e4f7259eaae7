// Natural frequency against DC bias (physics/structure/modal_analysis.hpp, linearised_modes,
// on the parallel-plate actuation's exact Jacobian about its biased static state).
//
// Three independent 1-DOF parallel-plate actuators (springs k, 2k, 3k, each mass m under its
// own plate of area A, gap g0; the eigensolver needs at least three unknowns with mass): at a
// voltage V the softest settles at the gap g solving k (g0 - g) = eps0 A V^2 / (2 g^2), and
// its small oscillations about it have
//   omega^2 = (k - eps0 A V^2 / g^3) / m,
// which falls to zero at the pull-in voltage V_PI = sqrt(8 k g0^3 / (27 eps0 A)) (g = 2 g0 / 3).
// The gap g is found here independently (bisection on the cubic), the static state by Newton
// (KINSOL) on the actuation operator. Asserted at V / V_PI = 0, 0.3, 0.6, 0.9, 0.99: relative
// error of omega below 1e-6; and the linearised stiffness against central differences of the
// operator's residual at the biased state.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../../support/jacobian_check.hpp"
#include "core/structural_systems.hpp"
#include "physics/electrostatics/parallel_plate_actuation.hpp"
#include "physics/electrostatics/permittivity.hpp"
#include "physics/structure/modal_analysis.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;

namespace {

constexpr double kK = 20.0, kMass = 5e-10, kArea = 1.6e-8, kGap = 3.75e-6;

// m_i x_i'' + (i + 1) k x_i = f_i: three uncoupled springs (positive x: opening).
class ThreeSprings : public SecondOrderOperator {
 public:
  ThreeSprings() {
    pattern_.col_idx = {0, 1, 2};
    pattern_.row_ptr = {0, 1, 2, 3};
  }
  Index size() const override { return 3; }
  void internal_residual(Real, std::span<const Real> y, std::span<Real> r) override {
    for (int i = 0; i < 3; ++i) r[i] = (i + 1) * kK * y[i];
  }
  const CsrPattern& stiffness_pattern() const override { return pattern_; }
  void stiffness(Real, std::span<const Real>, std::span<Real> values) override {
    for (int i = 0; i < 3; ++i) values[i] = (i + 1) * kK;
  }
  std::vector<Real> mass_diagonal() const override { return {kMass, kMass, kMass}; }

 private:
  CsrPattern pattern_;
};

// The gap of the softest actuator at V: k (g0 - g) = eps0 A V^2 / (2 g^2) on (2 g0 / 3, g0].
double equilibrium_gap(double V) {
  auto f = [&](double g) {
    return kK * (kGap - g) - kVacuumPermittivity * kArea * V * V / (2 * g * g);
  };
  double lo = 2 * kGap / 3, hi = kGap;  // f(lo) <= 0 below pull-in, f(hi) <= 0: the stable root
  if (f(hi) == 0) return hi;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST(ModalBias, ParallelPlateActuatorFrequencyAgainstVoltage) {
  ThreeSprings springs;
  std::vector<GapElement> elements;
  for (Index i = 0; i < 3; ++i) elements.push_back({i, kArea, Vec3::Zero(), Vec3::Zero(), {}});
  ParallelPlateActuation actuation(springs, elements, kGap, ParallelPlateLaw{});
  const double pull_in = std::sqrt(8 * kK * std::pow(kGap, 3) / (27 * kVacuumPermittivity * kArea));
  const std::vector<Real> mass = actuation.mass_diagonal();
  for (const double fraction : {0.0, 0.3, 0.6, 0.9, 0.99}) {
    const double V = fraction * pull_in;
    actuation.set_voltage_squared([V](Real) { return V * V; });
    KinsolOptions options;
    options.relative_tolerance = 1e-12;
    options.residual_scale = kK * kGap;
    const StaticSolution state = solve_static(actuation, 0.0, options);
    const double g = equilibrium_gap(V);
    EXPECT_NEAR(kGap + state.y[0], g, 1e-9 * kGap) << "V/V_PI " << fraction;

    // The linearised stiffness (springs and the actuation's softening) against central
    // differences of the residual, every entry, at the biased state.
    StaticSystem system(actuation);
    const test_support::JacobianCheck check = test_support::check_jacobian(
        system, 0.0, 0.0, state.y, std::vector<Real>(3, 0.0), 1e-6 * kGap);
    EXPECT_LT(check.relative(), 1e-7) << "V/V_PI " << fraction;

    const StructuralModes modes = linearised_modes(actuation, mass, 0.0, state.y, 1);
    const double exact =
        std::sqrt((kK - kVacuumPermittivity * kArea * V * V / (g * g * g)) / kMass);
    const double omega = modes.stats.modes[0].angular_frequency;
    std::printf("V / V_PI = %.2f: gap %.6e m, omega = %.10e rad/s, closed form %.10e (%+.2e)\n",
                fraction, g, omega, exact, omega / exact - 1);
    EXPECT_NEAR(omega / exact, 1.0, 1e-6) << "V/V_PI " << fraction;
    EXPECT_FALSE(modes.stats.modes[0].complex);
  }
}

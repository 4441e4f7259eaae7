// Natural frequency against DC bias (physics/structure/modal_analysis.hpp, linearised_modes,
// on the parallel-plate actuation's exact Jacobian about its biased static state).
//
// Three independent 1-DOF parallel-plate actuators (test/support/parallel_plate_springs.hpp): at
// a voltage V the softest settles at the gap g solving k (g0 - g) = eps0 A V^2 / (2 g^2), and
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
#include "../../support/parallel_plate_springs.hpp"
#include "core/structural_systems.hpp"
#include "physics/electrostatics/parallel_plate_actuation.hpp"
#include "physics/electrostatics/permittivity.hpp"
#include "physics/structure/modal_analysis.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;

using test::kPlateArea;
using test::kSpringGap;
using test::kSpringK;
using test::kSpringMass;

TEST(ModalBias, ParallelPlateActuatorFrequencyAgainstVoltage) {
  test::ThreeSprings springs;
  ParallelPlateActuation actuation(springs, test::spring_plates(), kSpringGap, ParallelPlateLaw{});
  const double pull_in = test::springs_pull_in_voltage();
  const std::vector<Real> mass = actuation.mass_diagonal();
  for (const double fraction : {0.0, 0.3, 0.6, 0.9, 0.99}) {
    const double V = fraction * pull_in;
    actuation.set_voltage_squared([V](Real) { return V * V; });
    KinsolOptions options;
    options.relative_tolerance = 1e-12;
    options.residual_scale = kSpringK * kSpringGap;
    const StaticSolution state = solve_static(actuation, 0.0, options);
    const double g = test::softest_equilibrium_gap(V);
    EXPECT_NEAR(kSpringGap + state.y[0], g, 1e-9 * kSpringGap) << "V/V_PI " << fraction;

    // The linearised stiffness (springs and the actuation's softening) against central
    // differences of the residual, every entry, at the biased state.
    StaticSystem system(actuation);
    const test_support::JacobianCheck check = test_support::check_jacobian(
        system, 0.0, 0.0, state.y, std::vector<Real>(3, 0.0), 1e-6 * kSpringGap);
    EXPECT_LT(check.relative(), 1e-7) << "V/V_PI " << fraction;

    const StructuralModes modes = linearised_modes(actuation, mass, 0.0, state.y, 1);
    const double exact = std::sqrt(
        (kSpringK - kVacuumPermittivity * kPlateArea * V * V / (g * g * g)) / kSpringMass);
    const double omega = modes.stats.modes[0].angular_frequency;
    std::printf("V / V_PI = %.2f: gap %.6e m, omega = %.10e rad/s, closed form %.10e (%+.2e)\n",
                fraction, g, omega, exact, omega / exact - 1);
    EXPECT_NEAR(omega / exact, 1.0, 1e-6) << "V/V_PI " << fraction;
    EXPECT_FALSE(modes.stats.modes[0].complex);
  }
}

// The small-signal response to an AC voltage about a DC bias (coupling/harmonic_under_bias.hpp)
// against the 1-DOF parallel-plate actuator's closed form.
//
// The softest of three independent actuators (test/support/parallel_plate_springs.hpp) settles
// at the gap g of k (g0 - g) = eps0 A V^2 / (2 g^2) under V_dc; with V = V_dc + Re(v exp(i w t))
// its force -eps0 A V^2 / (2 g^2) changes by -eps0 A V_dc v / g^2 at first order, against the
// softened stiffness, so
//   x / v = -(eps0 A V_dc / g^2) / (k - eps0 A V_dc^2 / g^3 - m w^2),
// real (no damping), in phase below the biased resonance and in antiphase above it. Asserted
// at V / V_PI = 0.3, 0.6, 0.9 and w / w_bias = 0.01 ... 3 (relative error below 1e-6), with the
// biased equilibrium (found from the quasi-static curve) against the cubic's root; and a bias
// at or above the fold is bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../../support/parallel_plate_springs.hpp"
#include "core/error.hpp"
#include "coupling/harmonic_under_bias.hpp"
#include "coupling/switch_system.hpp"

using namespace rfmems;
using test::kPlateArea;
using test::kSpringGap;
using test::kSpringK;
using test::kSpringMass;

TEST(HarmonicBias, ParallelPlateActuatorResponseAgainstClosedForm) {
  test::ThreeSprings springs;
  ParallelPlateActuation actuation(springs, test::spring_plates(), kSpringGap, ParallelPlateLaw{});
  ActuatedStructureSystem system(actuation, {false, false, false});
  QuasiStaticOptions options;
  options.voltage_tolerance = 1e-6;
  const QuasiStaticPullIn curve = trace_pull_in(actuation, 0, options);
  const double pull_in = test::springs_pull_in_voltage();
  EXPECT_NEAR(curve.pull_in_voltage / pull_in, 1.0, 1e-6);

  const double eps_a = kVacuumPermittivity * kPlateArea;
  for (const double fraction : {0.3, 0.6, 0.9}) {
    const double V = fraction * pull_in;
    const std::vector<Real> state = equilibrium_at_voltage(actuation, 0, curve, V, options);
    const double g = test::softest_equilibrium_gap(V);
    EXPECT_NEAR(kSpringGap + state[0], g, 1e-10 * kSpringGap) << "V/V_PI " << fraction;

    const double stiffness = kSpringK - eps_a * V * V / (g * g * g);
    const double omega_bias = std::sqrt(stiffness / kSpringMass);
    std::vector<Real> frequencies;
    for (const double r : {0.01, 0.5, 0.9, 1.1, 2.0, 3.0})
      frequencies.push_back(r * omega_bias / (2 * M_PI));
    const HarmonicUnderBias h = harmonic_under_bias(system, 0, V, state, frequencies, nullptr, {});
    ASSERT_EQ(h.control.size(), frequencies.size());
    EXPECT_FALSE(h.has_film);
    EXPECT_EQ(h.factorizations, 1);
    for (std::size_t k = 0; k < frequencies.size(); ++k) {
      const double omega = 2 * M_PI * frequencies[k];
      const double exact = -(eps_a * V / (g * g)) / (stiffness - kSpringMass * omega * omega);
      std::printf("V/V_PI = %.1f, w/w_bias = %.2f: x/v = %+.10e m/V, closed form %+.10e (%+.1e)\n",
                  fraction, omega / omega_bias, h.control[k].real(), exact,
                  h.control[k].real() / exact - 1);
      EXPECT_NEAR(h.control[k].real() / exact, 1.0, 1e-6) << fraction << " " << omega / omega_bias;
      EXPECT_LT(std::abs(h.control[k].imag()), 1e-9 * std::abs(exact));
    }
  }
  EXPECT_THROW(equilibrium_at_voltage(actuation, 0, curve, 1.001 * curve.pull_in_voltage, options),
               InputError);
}

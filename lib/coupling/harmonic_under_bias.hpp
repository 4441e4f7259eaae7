// The small-signal frequency response of a parallel-plate switch about its equilibrium under a DC
// bias: the voltage V = V_dc + Re(v exp(i w t)) with |v| << V_dc, the switch system (structure,
// parallel-plate force and, with a film, the Reynolds film: switch_system.hpp) linearised about
// the biased static state Y0 (displacements at rest in time, ambient film pressure):
//
//   (dF/dY + i w dF/dY') x = -dF/dV v,     dF/dV = 2 V_dc q(Y0),  q = dF/d(V^2)
//
// (solvers/harmonic_response.hpp; the electrostatic pressure is V^2 times a function of the gap,
// so the drive per volt of AC amplitude is exactly 2 V_dc q). The linearised stiffness carries
// the electrostatic softening -eps0 A V_dc^2 / g^3, so the response peaks at the biased
// natural frequencies (bias_modes.hpp); a 1-DOF actuator of stiffness k and mass m answers
//   x / v = -(eps0 A V_dc / g^2) / (k - eps0 A V_dc^2 / g^3 - m w^2)
// (test/unit/coupling/test_harmonic_bias.cpp).
//
// With a film, its force on the structure F = sum_c (p_c - p_a) A_c follows the motion; per unit
// of the mean gap change over the film, g_mean = sum_c A_c w_c / sum_c A_c,
//   k_film + i w c_film = -F / g_mean
// are the squeeze film's spring and damping coefficients against frequency as designers plot
// them: for a rigid plate they are Blech's (J. Lubrication Technology 105, 1983), a damper
// (k_film ~ w^2, c_film constant) at small squeeze numbers sigma = 12 mu w b^2 / (p_a g^2), a gas
// spring k_film -> p_a A / g0 (isothermal compression with no time to flow out) at large ones.
#pragma once
#include <complex>
#include <span>
#include <vector>

#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/switch_system.hpp"

namespace rfmems {

class ReynoldsFilm;

struct HarmonicUnderBias {
  Real bias = 0;                  // V_dc [V]
  Real static_control = 0;        // the control unknown's static deflection at the bias [m]
  std::vector<Real> frequencies;  // [Hz]
  // Per frequency, per volt of AC amplitude (the phase against the AC voltage's):
  std::vector<std::complex<Real>> control;  // the control unknown's deflection [m/V]
  bool has_film = false;
  std::vector<std::complex<Real>> film_force;  // the film's force on the structure [N/V]
  std::vector<std::complex<Real>> mean_gap;    // the mean gap change over the film [m/V]
  std::vector<Real> film_spring;               // k_film [N/m]
  std::vector<Real> film_damping;              // c_film [N s/m]
  long factorizations = 0, refactorizations = 0;
  double solve_cpu_s = 0;
};

// The structure's static equilibrium at `voltage` (below the curve's fold): KINSOL under voltage
// control from the stable-branch state at the curve's deflection interpolated to that voltage.
// InputError at or above the fold's voltage (no equilibrium to linearise about).
std::vector<Real> equilibrium_at_voltage(ParallelPlateActuation& actuation, Index control,
                                         const QuasiStaticPullIn& curve, Real voltage,
                                         const QuasiStaticOptions& options);

// The response at each frequency [Hz] about `structure_state` (the structure's unknowns at
// equilibrium under `bias`). film and film_unknowns (the structure unknown over each film cell):
// the scene's film, or null and empty without one.
HarmonicUnderBias harmonic_under_bias(SwitchSystem& system, Index control, Real bias,
                                      std::span<const Real> structure_state,
                                      const std::vector<Real>& frequencies,
                                      const ReynoldsFilm* film,
                                      std::span<const Index> film_unknowns);

}  // namespace rfmems

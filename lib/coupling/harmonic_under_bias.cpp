#include "coupling/harmonic_under_bias.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/process_cpu_clock.hpp"
#include "physics/gas/reynolds_film.hpp"
#include "solvers/harmonic_response.hpp"
#include "solvers/static_solve.hpp"

namespace rfmems {

std::vector<Real> equilibrium_at_voltage(ParallelPlateActuation& actuation, Index control,
                                         const QuasiStaticPullIn& curve, Real voltage,
                                         const QuasiStaticOptions& options) {
  if (voltage >= curve.pull_in_voltage)
    throw InputError(fmt::format(
        "pull_in.harmonic.bias: {} V is not below the quasi-static pull-in voltage {:.6g} V: "
        "no equilibrium to linearise about",
        voltage, curve.pull_in_voltage));
  const Index n = actuation.size();
  // The stable-branch samples that bracket the voltage (rest, then the curve up to its fold).
  Real d_low = 0, v_low = 0, d_high = curve.pull_in_displacement, v_high = curve.pull_in_voltage;
  for (const PullInPoint& p : curve.curve) {
    if (!p.stable) break;
    if (p.voltage <= voltage) {
      d_low = p.displacement, v_low = p.voltage;
    } else {
      d_high = p.displacement, v_high = p.voltage;
      break;
    }
  }
  // Displacement control to the deflection interpolated in V^2 (the curve is near-linear in it).
  std::vector<Real> state = displacement_control_start(actuation, curve);
  const Real fraction = (voltage * voltage - v_low * v_low) / (v_high * v_high - v_low * v_low);
  const Real guess = d_low + fraction * (d_high - d_low);
  if (guess != 0) state = follow_displacement(actuation, control, state, {guess}, options);
  state.resize(n);

  // Newton under voltage control from there: the residual to a tiny fraction of the largest
  // electrostatic force on an unknown (the load the structure balances).
  std::vector<Real> per_volt2(n);
  actuation.residual_per_volt2(state, per_volt2);
  Real load = 0;
  for (const Real q : per_volt2) load = std::max(load, std::abs(q) * voltage * voltage);
  actuation.set_voltage_squared([voltage](Real) { return voltage * voltage; });
  KinsolOptions kinsol;
  kinsol.relative_tolerance = 1e-12;
  kinsol.residual_scale = load;
  kinsol.max_iterations = 50;
  return solve_static(actuation, 0.0, kinsol, std::move(state)).y;
}

HarmonicUnderBias harmonic_under_bias(SwitchSystem& system, Index control, Real bias,
                                      std::span<const Real> structure_state,
                                      const std::vector<Real>& frequencies,
                                      const ReynoldsFilm* film,
                                      std::span<const Index> film_unknowns) {
  HarmonicUnderBias out;
  out.bias = bias;
  out.frequencies = frequencies;
  out.static_control = structure_state[control];
  out.has_film = film != nullptr;
  ParallelPlateActuation& actuation = system.actuation();

  // Y0: the switch system at rest in time with the biased displacements (the structure's
  // unknowns lead its state; velocities zero, the film at ambient pressure).
  std::vector<Real> y0, yp0;
  system.initial_state(0.0, y0, yp0);
  std::copy(structure_state.begin(), structure_state.end(), y0.begin());
  const std::vector<Real> zero(y0.size(), 0.0);

  // The drive per volt of AC amplitude: dF/dV = 2 V_dc (F(V_dc^2) - F(0)) / V_dc^2, exact as F
  // is affine in V^2.
  std::vector<Real> biased(y0.size()), unbiased(y0.size()), drive(y0.size());
  actuation.set_voltage_squared([](Real) { return 0.0; });
  system.residual(0.0, y0, zero, unbiased);
  actuation.set_voltage_squared([bias](Real) { return bias * bias; });
  system.residual(0.0, y0, zero, biased);
  for (std::size_t i = 0; i < drive.size(); ++i) drive[i] = 2 * (biased[i] - unbiased[i]) / bias;

  Real film_area = 0;
  if (film)
    for (Index c = 0; c < film->mesh().n_cells(); ++c) film_area += film->mesh().cell_volume(c);
  const Real force0 = system.gas_force(y0);

  HarmonicResponse response(system, 0.0, y0);
  std::vector<Real> part(y0.size());
  for (const Real f : frequencies) {
    const Real omega = 2 * M_PI * f;
    std::vector<std::complex<Real>> x;
    {
      ScopedCpuTimer timer{out.solve_cpu_s};
      x = response.solve(omega, drive, zero);
    }
    out.control.push_back(x[control]);
    if (!film) continue;
    // The film's force is affine in the pressures: its change for the real and imaginary parts.
    auto force_of = [&](auto component) {
      for (std::size_t i = 0; i < part.size(); ++i) part[i] = y0[i] + component(x[i]);
      return system.gas_force(part) - force0;
    };
    const std::complex<Real> force(force_of([](std::complex<Real> z) { return z.real(); }),
                                   force_of([](std::complex<Real> z) { return z.imag(); }));
    std::complex<Real> gap = 0;
    for (Index c = 0; c < film->mesh().n_cells(); ++c)
      gap += film->mesh().cell_volume(c) * x[film_unknowns[c]];
    gap /= film_area;
    const std::complex<Real> impedance = -force / gap;  // k + i w c
    out.film_force.push_back(force);
    out.mean_gap.push_back(gap);
    out.film_spring.push_back(impedance.real());
    out.film_damping.push_back(impedance.imag() / omega);
  }
  out.factorizations = response.fresh_factorizations();
  out.refactorizations = response.refactorizations();
  return out;
}

}  // namespace rfmems

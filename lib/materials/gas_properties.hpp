// Properties of the gas in a squeeze film (default: air at 300 K) and its rarefaction model.
//
//   mean free path   lambda(p) = lambda_ref p_ref / p       (kinetic theory at fixed T)
//   Knudsen number   Kn = lambda(p) / g                     (g: film thickness, the gap)
//   effective viscosity (Veijola, Kuisma, Lahdenpera, Ryhanen, Sensors and Actuators A 48
//   (1995) 239-248, a fit of the Fukui-Kaneko Poiseuille flow rate of the linearised
//   Boltzmann equation, within 5 % for 0 <= Kn <= 880):
//     mu_eff = mu / Q(Kn),   Q(Kn) = 1 + 9.638 Kn^1.159
//   Rarefaction::None keeps Q = 1 (continuum, no-slip Reynolds equation; Kn < ~0.01).
//   Rarefaction::Table takes Q(Kn) from a table (flow_factor_table.hpp: the kinetic solver's
//   Poiseuille flow rate over its continuum value, interpolated monotonically in ln Kn).
//
// Why Q is exposed rather than mu_eff alone: the film's flow coefficient g^3 p Q / (12 mu) is
// what the Reynolds operator differentiates, and dQ/dKn keeps that Jacobian exact.
#pragma once
#include <cmath>
#include <memory>

#include "core/types.hpp"
#include "materials/flow_factor_table.hpp"

namespace rfmems {

enum class Rarefaction { None, Veijola, Table };

struct GasProperties {
  Real viscosity = 1.85e-5;            // mu [Pa s], air at 300 K
  Real mean_free_path = 68e-9;         // lambda_ref [m] at reference_pressure
  Real reference_pressure = 101325.0;  // p_ref [Pa]
  Real ambient_pressure = 101325.0;    // p_a [Pa]: the gas around the film
  Rarefaction rarefaction = Rarefaction::Veijola;
  std::shared_ptr<const FlowFactorTable> flow_factor_table;  // Rarefaction::Table

  static constexpr Real kVeijolaCoefficient = 9.638;
  static constexpr Real kVeijolaExponent = 1.159;

  // Kn = lambda_ref p_ref / (p g).
  Real knudsen(Real pressure, Real gap) const {
    return mean_free_path * reference_pressure / (pressure * gap);
  }
  // Q(Kn) = mu / mu_eff.
  Real rarefaction_factor(Real kn) const {
    if (rarefaction == Rarefaction::None) return 1.0;
    if (rarefaction == Rarefaction::Table) return flow_factor_table->evaluate(kn).q;
    return 1.0 + kVeijolaCoefficient * std::pow(kn, kVeijolaExponent);
  }
  // dQ/dKn.
  Real rarefaction_factor_derivative(Real kn) const {
    if (rarefaction == Rarefaction::None) return 0.0;
    if (rarefaction == Rarefaction::Table) return flow_factor_table->evaluate(kn).dq_dkn;
    return kVeijolaCoefficient * kVeijolaExponent * std::pow(kn, kVeijolaExponent - 1.0);
  }
  Real effective_viscosity(Real pressure, Real gap) const {
    return viscosity / rarefaction_factor(knudsen(pressure, gap));
  }
};

}  // namespace rfmems

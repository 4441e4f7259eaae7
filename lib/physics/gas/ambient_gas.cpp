#include "physics/gas/ambient_gas.hpp"

#include <cmath>

#include "io/case_schema_yaml.hpp"

namespace rfmems {

AmbientGas read_ambient_gas(const CaseNode& gas, bool pressure_required) {
  AmbientGas a;
  GasProperties& g = a.film;
  g.ambient_pressure = pressure_required
                           ? gas.get_quantity("pressure", Dimension::Pressure, Range::positive())
                           : gas.get_quantity("pressure", Dimension::Pressure, g.ambient_pressure,
                                              Range::positive());
  g.reference_pressure = g.ambient_pressure;
  a.temperature =
      gas.get_quantity("temperature", Dimension::Temperature, a.temperature, Range::positive());
  g.viscosity = gas.get_quantity("viscosity", Dimension::Viscosity, g.viscosity, Range::positive());
  a.omega = gas.get_real("omega", a.omega, Range::closed(0.5, 1.0));
  // Mean free path of the thesis's eq. (5.30) family, lambda = mu / p sqrt(pi R T / 2), air.
  constexpr Real kAirGasConstant = 287.0;  // J / (kg K)
  const Real lambda =
      g.viscosity / g.ambient_pressure * std::sqrt(M_PI * kAirGasConstant * a.temperature / 2);
  g.mean_free_path =
      gas.get_quantity("mean_free_path", Dimension::Length, lambda, Range::positive());
  g.rarefaction = gas.get_choice("rarefaction", {"veijola", "none"}, "veijola") == "veijola"
                      ? Rarefaction::Veijola
                      : Rarefaction::None;
  return a;
}

CaseSchema ambient_gas_case_keys() {
  return embedded_case_schema("physics/gas/ambient_gas.keys.yaml");
}

}  // namespace rfmems

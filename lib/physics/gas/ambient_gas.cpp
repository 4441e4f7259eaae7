#include "physics/gas/ambient_gas.hpp"

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include "core/error.hpp"
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
  const std::string rarefaction =
      gas.get_choice("rarefaction", {"veijola", "none", "table"}, "veijola");
  g.rarefaction = rarefaction == "veijola" ? Rarefaction::Veijola
                  : rarefaction == "table" ? Rarefaction::Table
                                           : Rarefaction::None;
  const bool table = g.rarefaction == Rarefaction::Table;
  if (table || gas.has("flow_factor_table")) {
    const std::string file = gas.get_string("flow_factor_table");
    gas.require(table, "flow_factor_table", "read only with rarefaction: table");
    gas.require(!file.empty(), "flow_factor_table", "expected a file name");
    std::filesystem::path path(file);
    if (path.is_relative()) path = std::filesystem::path(gas.file()).parent_path() / path;
    try {
      g.flow_factor_table = std::make_shared<const FlowFactorTable>(
          FlowFactorTable::read(path.lexically_normal().string()));
    } catch (const InputError& e) {
      gas.fail("flow_factor_table", e.what());
    }
  }
  return a;
}

CaseSchema ambient_gas_case_keys() {
  return embedded_case_schema("physics/gas/ambient_gas.keys.yaml");
}

}  // namespace rfmems

#include "io/quantity_units.hpp"

#include <map>

namespace rfmems {

std::optional<std::string> units_of(const std::string& name) {
  static const std::map<std::string, std::string> units = {
      // cell fields: structure
      {"displacement", "m"},
      {"velocity", "m/s"},
      {"stress", "Pa"},
      {"deflection", "m"},
      {"rotation", "rad"},
      {"moment", "N"},  // moment resultants per unit length, N m / m
      {"shear_force", "N/m"},
      {"membrane_force", "N/m"},        // the von Karman plate's stretching resultants
      {"total_membrane_force", "N/m"},  // creep of the von Karman plate: h sigma0 + A:eps - C P
      {"plastic_moment", "N"},
      {"von_mises_top", "Pa"},
      {"von_mises_bottom", "Pa"},
      {"creep_strain", "1"},
      // cell fields: gas
      {"density", "kg/m^3"},
      {"temperature", "K"},
      {"pressure", "Pa"},
      {"heat_flux", "W/m^2"},
      // probe components
      {"ux", "m"},
      {"uy", "m"},
      {"uz", "m"},
      {"w", "m"},
      {"beta_x", "rad"},
      {"beta_y", "rad"},
      // time series and their abscissae
      {"time", "s"},
      {"iteration", "1"},
      {"mode", "1"},  // a mode's number (modal analyses)
      {"ratio", "1"},
      {"voltage", "V"},
      {"control", "m"},
      {"control_displacement", "m"},
      {"min_gap", "m"},
      {"stable", "1"},
      {"contact_fraction", "1"},
      {"max_surface_von_mises", "Pa"},
      {"max_creep_strain", "1"},
  };
  const auto it = units.find(name);
  if (it == units.end()) return std::nullopt;
  return it->second;
}

}  // namespace rfmems

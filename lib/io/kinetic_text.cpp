#include "io/kinetic_text.hpp"

#include <fmt/format.h>

namespace rfmems {

std::string kinetic_text(const Json& s) {
  const Json& solver = s["solver"];
  const Json& ref = s["reference"];
  const bool plane = s["mesh"]["dim"].get<int>() == 2;
  const std::string method = solver["method"].get<std::string>();
  std::string text = fmt::format(
      "{} ({}, Kn = {:.4g}, {} cells x {} velocities): ", s["case"].get<std::string>(),
      s["collision"].get<std::string>(), s["initial"]["knudsen"].get<double>(),
      s["mesh"]["cells"].get<long long>(), s["velocity_grid"]["ordinates"].get<long long>());
  if (solver.contains("handover")) text += solver["handover"].get<std::string>() + "; ";
  text += fmt::format("{} solver converged in {} {}s (residual ratio {:.2e}, {:.1f} s)\n", method,
                      solver["iterations"].get<int>(), solver["iteration"].get<std::string>(),
                      solver["residual_ratio"].get<double>(), solver["seconds"].get<double>());
  text += fmt::format(
      "  reference: p0 = {:.6g} Pa, T0 = {:.6g} K, rho0 = {:.6g} kg/m^3, mu0 = {:.6g} Pa s, "
      "v0 = sqrt(2 R T0) = {:.6g} m/s, H = {:.6g} m (initial.reference_length); "
      "delta = p0 H / (mu0 v0) = {:.6g}, {} = {:.6g}\n",
      ref["pressure"].get<double>(), ref["temperature"].get<double>(), ref["density"].get<double>(),
      ref["viscosity"].get<double>(), ref["thermal_speed"].get<double>(),
      ref["reference_length"].get<double>(), ref["rarefaction_parameter"].get<double>(),
      ref["knudsen_definition"].get<std::string>(), ref["knudsen"].get<double>());
  for (const auto& [name, wall] : s["walls"].items()) {
    const Json& F = wall["force"];
    text += fmt::format("  wall {}: force [{:.6e}, {:.6e}, {:.6e}] N{}, heat flow {:.6e} W{}\n",
                        name, F[0].get<double>(), F[1].get<double>(), F[2].get<double>(),
                        plane ? "/m" : "", wall["heat_flow"].get<double>(), plane ? "/m" : "");
    if (wall.contains("normalised_shear"))
      text += fmt::format(
          "    shear stress {:.6e} Pa, P = -p_xy v0 / (p0 U) = {:.6g} (U = {:.6g} m/s)\n",
          wall["shear_stress"].get<double>(), wall["normalised_shear"].get<double>(),
          ref["wall_speed"].get<double>());
    if (wall.contains("normalised_heat_flux"))
      text += fmt::format(
          "    heat flux {:.6e} W/m^2, q* = q / (p0 v0 dT / T0) = {:.6g} (dT = {:.6g} K)\n",
          wall["heat_flux"].get<double>(), wall["normalised_heat_flux"].get<double>(),
          ref["temperature_difference"].get<double>());
  }
  if (s.contains("flow_rate")) {
    const Json& q = s["flow_rate"];
    text += fmt::format(
        "  flow rate through {}: {:.6e} kg/s{}, G = -(2 / (xi H v0)) int u dy = {:.6g} "
        "(xi = (H / p0) dp/dx = {:.6g} for the body force {:.6g} m/s^2)\n",
        q["patch"].get<std::string>(), q["mass_flow"].get<double>(), plane ? "/m" : "",
        q["normalised_flow_rate"].get<double>(), ref["pressure_gradient"].get<double>(),
        ref["body_force"].get<double>());
  }
  return text;
}

}  // namespace rfmems

#include "io/kinetic_text.hpp"

#include <fmt/format.h>

namespace rfmems {

std::string kinetic_text(const Json& s) {
  const Json& solver = s["solver"];
  const bool plane = s["mesh"]["dim"].get<int>() == 2;
  std::string text = fmt::format(
      "{} ({}, Kn = {:.4g}, {} cells x {} velocities): {} solver converged in {} iterations "
      "(residual ratio {:.2e}, {:.1f} s)\n",
      s["case"].get<std::string>(), s["collision"].get<std::string>(),
      s["initial"]["knudsen"].get<double>(), s["mesh"]["cells"].get<long long>(),
      s["velocity_grid"]["ordinates"].get<long long>(), solver["type"].get<std::string>(),
      solver["iterations"].get<int>(), solver["residual_ratio"].get<double>(),
      solver["seconds"].get<double>());
  for (const auto& [name, wall] : s["walls"].items()) {
    const Json& F = wall["force"];
    text += fmt::format("  wall {}: force [{:.6e}, {:.6e}, {:.6e}] N{}, heat flow {:.6e} W{}\n",
                        name, F[0].get<double>(), F[1].get<double>(), F[2].get<double>(),
                        plane ? "/m" : "", wall["heat_flow"].get<double>(), plane ? "/m" : "");
  }
  return text;
}

}  // namespace rfmems

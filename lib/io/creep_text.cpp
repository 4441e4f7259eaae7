#include "io/creep_text.hpp"

#include <fmt/format.h>

namespace rfmems {

std::string creep_text(const Json& s) {
  std::string text =
      fmt::format("{} ({} creep, {}): {} steps to t = {:.4g} h", s["case"].get<std::string>(),
                  s["model"].get<std::string>(), s["integration"].get<std::string>(),
                  s["steps"].get<long>(), s["final_time_s"].get<double>() / 3600);
  for (const auto& [name, probe] : s["probes"].items())
    text += fmt::format(", {}: w {:.4e} -> {:.4e} m", name, probe["w_initial"].get<double>(),
                        probe["w_final"].get<double>());
  text += "\n";
  if (s["life_reached"].get<bool>())
    text += fmt::format("  creep life {:.4g} h ({})\n", s["lifetime_h"].get<double>(),
                        s["end"].get<std::string>());
  return text;
}

std::string hold_voltage_text(const Json& h) {
  return fmt::format("hold voltage {:.9g} V: gap {:.9g} m at probe {} ({} trials)\n",
                     h["voltage_V"].get<double>(), h["gap_m"].get<double>(),
                     h["probe"].get<std::string>(), h["trials"].size());
}

}  // namespace rfmems

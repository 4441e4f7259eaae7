#include "coupling/pull_in_results.hpp"

#include <fmt/format.h>

#include <cmath>
#include <vector>

namespace rfmems {

void write_pull_in_curve(ResultWriter& writer, const QuasiStaticPullIn& quasi_static) {
  std::vector<double> delta;
  std::vector<std::vector<double>> rows;
  for (const PullInPoint& p : quasi_static.curve) {
    delta.push_back(p.displacement);
    rows.push_back({p.voltage, p.min_gap, p.stable ? 1.0 : 0.0});
  }
  writer.write_time_series("pull_in", "curve", delta, rows, {"voltage", "min_gap", "stable"},
                           "control_displacement");
}

void write_bias_modes(ResultWriter& writer, const std::vector<BiasedModes>& modes) {
  std::vector<double> voltage;
  std::vector<std::vector<double>> rows;
  std::vector<std::string> names{"control_displacement"};
  std::vector<std::string> units{"m"};
  for (std::size_t k = 0; k < modes.front().modes.size(); ++k) {
    names.push_back(fmt::format("f{}", k + 1));
    units.push_back("Hz");
  }
  for (const BiasedModes& b : modes) {
    voltage.push_back(b.voltage);
    std::vector<double> row{b.displacement};
    for (const StructuralMode& m : b.modes) row.push_back(m.frequency);
    rows.push_back(row);
  }
  writer.write_time_series("pull_in", "modes", voltage, rows, names, "voltage", units);
}

void write_harmonic_under_bias(ResultWriter& writer, const HarmonicUnderBias& response) {
  std::vector<std::string> names{"control_real", "control_imag"}, units{"m/V", "m/V"};
  if (response.has_film) {
    names.insert(names.end(),
                 {"film_force_real", "film_force_imag", "film_spring", "film_damping"});
    units.insert(units.end(), {"N/V", "N/V", "N/m", "N s/m"});
  }
  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0; k < response.frequencies.size(); ++k) {
    std::vector<double> row{response.control[k].real(), response.control[k].imag()};
    if (response.has_film)
      row.insert(row.end(), {response.film_force[k].real(), response.film_force[k].imag(),
                             response.film_spring[k], response.film_damping[k]});
    rows.push_back(row);
  }
  writer.write_time_series("pull_in", "harmonic", response.frequencies, rows, names, "frequency",
                           units);
}

void write_dynamic_history(ResultWriter& writer, const std::string& name, const DynamicRun& run,
                           const std::string& force_units) {
  std::vector<double> t;
  std::vector<std::vector<double>> rows;
  for (const DynamicSample& s : run.history) {
    t.push_back(s.t);
    rows.push_back(
        {s.control, s.min_gap, s.electrostatic_force, s.gas_force, s.contact_force, s.voltage});
  }
  writer.write_time_series(
      "dynamic", name, t, rows,
      {"control", "min_gap", "electrostatic_force", "gas_force", "contact_force", "voltage"},
      "time", {"m", "m", force_units, force_units, force_units, "V"});
}

Json free_response_json(const FreeResponse& r) {
  return {{"fitted", r.fitted},
          {"damping_ratio", r.damping_ratio},
          {"frequency", r.frequency},
          {"natural_frequency", r.natural_frequency},
          {"method", r.from_log_decrement ? "log_decrement" : "fit"},
          {"fit",
           {{"damping_ratio", r.fit_damping_ratio},
            {"frequency", r.fit_frequency},
            {"residual", r.residual}}},
          {"fit_residual", r.residual},
          {"log_decrement",
           {{"damping_ratio", r.log_decrement.damping_ratio},
            {"frequency", r.log_decrement.frequency},
            {"swings", r.log_decrement.swings}}}};
}

Json pull_in_time_check_json(Real factor, Real pull_in_time, const DynamicRun& check) {
  Json j = {{"tolerance_factor", factor},
            {"pulled_in", check.pulled_in},
            {"steps", check.stats.steps},
            {"pull_in_time", Json()},
            {"relative_error_estimate", Json()}};
  if (check.pulled_in && check.pull_in_time > 0) {
    j["pull_in_time"] = check.pull_in_time;
    j["relative_error_estimate"] = std::abs(pull_in_time - check.pull_in_time) / check.pull_in_time;
  }
  return j;
}

}  // namespace rfmems

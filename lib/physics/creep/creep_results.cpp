#include "physics/creep/creep_results.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "io/quantity_units.hpp"
#include "io/units.hpp"
#include "physics/creep/creep_plate_model.hpp"
#include "physics/creep/hold_voltage_search.hpp"

namespace rfmems {

namespace {
Json nullable(Real x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }
}  // namespace

void write_creep_results(ResultWriter& writer, const CreepCase& creep, const CreepRunModel& model,
                         const CreepRunResult& result) {
  for (std::size_t k = 0; k < result.outputs.size(); ++k)
    write_plate_creep_output(creep, writer, static_cast<int>(k), result.outputs[k]);
  // The series' columns: the probes' deflections (named by the probes), then by their names.
  std::vector<std::string> units(creep.probes.size(), "m");
  for (std::size_t k = creep.probes.size(); k < model.series_columns.size(); ++k)
    units.push_back(units_of(model.series_columns[k]).value_or(""));
  writer.write_time_series("creep", "history", result.series_times, result.series,
                           model.series_columns, "time", units);
  writer.write_time_series("creep", "final_state", {result.final_time}, {result.state});
}

Json creep_summary(const CreepCase& creep, const CreepRunModel& model,
                   const CreepRunResult& result) {
  const CreepRunSettings& settings = creep.settings;
  const bool implicit = settings.integration == CreepRunSettings::Integration::Implicit;
  Json summary;
  summary["model"] = creep.structure->kind();
  summary["geometric_nonlinearity"] = creep.plate->von_karman != nullptr;  // the von Karman plate
  summary["mesh"] = {{"cells", creep.plate->mesh->n_cells()}};
  summary["integration"] = implicit ? "implicit" : "explicit";
  if (!implicit) summary["dt_s"] = settings.explicit_dt;
  summary["end_time_s"] = settings.end_time();
  summary["final_time_s"] = result.final_time;
  summary["end"] = to_string(result.end);
  summary["life_reached"] = result.life_reached();
  summary["lifetime_s"] = nullable(result.lifetime);
  summary["lifetime_h"] = nullable(result.lifetime / 3600);
  if (!result.message.empty()) summary["solver_message"] = result.message;
  summary["hold_voltage_V"] = creep.hold ? creep.hold->voltage : 0.0;
  if (creep.has_gap) summary["gap_m"] = creep.initial_gap;
  summary["plate_thickness_m"] = creep.plate->section.thickness;
  Json probes = Json::object();
  const std::vector<double>& first = result.series.front();
  const std::vector<double>& last = result.series.back();
  for (std::size_t p = 0; p < creep.probes.size(); ++p)
    probes[creep.probes[p].name] = {{"w_initial", first[p]}, {"w_final", last[p]}};
  summary["probes"] = probes;
  for (std::size_t k = creep.probes.size(); k < model.series_columns.size(); ++k)
    summary["final"][model.series_columns[k]] = last[k];
  if (creep.has_gap) summary["initial_min_gap"] = first[creep.probes.size()];
  summary["steps"] = result.steps;
  summary["segments"] = result.segments;
  summary["n_outputs"] = result.outputs.size();
  summary["restarted"] = result.restarted;
  if (result.restarted) summary["restart_time_s"] = result.restart_time;
  summary["checkpoints_written"] = result.checkpoints_written;
  summary["checkpoint"] = settings.checkpoint_path;
  return summary;
}

Json hold_voltage_for_gap(const CreepCase& creep, const std::string& option,
                          const std::string& gap) {
  auto bad = [&](const std::string& what) {
    return InputError(fmt::format("option '{}' = '{}': {}", option, gap, what));
  };
  Real target = 0;
  try {
    target = parse_quantity(gap, Dimension::Length);
  } catch (const std::invalid_argument& e) {
    throw bad(e.what());
  }
  if (!creep.has_gap) throw bad("the case has no actuation section (no gap)");
  if (creep.probes.empty()) throw bad("the case has no probe to measure the gap at");
  if (!(target > 0 && target < creep.initial_gap))
    throw bad(fmt::format("must be in (0, actuation.gap = {:.6g} m)", creep.initial_gap));
  HoldVoltageSearchResult r;
  try {
    HoldVoltageSearchOptions search;
    if (creep.hold) search.first_voltage = creep.hold->voltage;  // the case's value: a guess
    r = find_hold_voltage(case_probe_gap(creep, 0), target, search);
  } catch (const SolverError& e) {
    throw bad(e.what());
  }
  Json trials = Json::array();
  for (const HoldVoltageTrial& t : r.trials)
    trials.push_back({{"voltage_V", t.voltage}, {"gap_m", t.gap ? Json(*t.gap) : Json(nullptr)}});
  return {{"voltage_V", r.voltage},        {"gap_m", r.gap},
          {"target_gap_m", target},        {"initial_gap_m", creep.initial_gap},
          {"probe", creep.probes[0].name}, {"trials", trials}};
}

}  // namespace rfmems

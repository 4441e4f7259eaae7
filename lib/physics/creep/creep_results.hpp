// What a creep run (rfmems-creep) writes and reports:
//   - the result file: the plate's fields at every output (physics/creep/creep_plate_model.hpp),
//     the time series /creep/history (time, the probes' w, min_gap, max_surface_von_mises,
//     max_creep_strain) and /creep/final_state (the whole state at the final time, one row);
//   - the summary: model, mesh, integration, end time and how the run ended, the creep life
//     (lifetime_s / _h, null when no event ended it), hold voltage and gap, each probe's w at
//     t = 0 and at the end, the final series values, steps, segments, outputs, restart and
//     checkpoint figures;
//   - for --hold-voltage-for-gap, the hold voltage whose elastic gap at the case's first probe
//     is a given one, with its trials.
#pragma once
#include <string>

#include "io/json_summary.hpp"
#include "io/result_writer.hpp"
#include "physics/creep/creep_case.hpp"
#include "physics/creep/creep_run.hpp"

namespace rfmems {

void write_creep_results(ResultWriter& writer, const CreepCase& creep, const CreepRunModel& model,
                         const CreepRunResult& result);

Json creep_summary(const CreepCase& creep, const CreepRunModel& model,
                   const CreepRunResult& result);

// The hold voltage for the gap `gap` (a length as text, the value of `option`) as a summary:
// voltage_V, gap_m, target_gap_m, initial_gap_m, probe, trials. InputError naming the option
// when the case has no gap or probe, or the gap is not in (0, g0) or lies beyond the fold.
Json hold_voltage_for_gap(const CreepCase& creep, const std::string& option,
                          const std::string& gap);

}  // namespace rfmems

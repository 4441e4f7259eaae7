// The text rfmems-pullin prints after a run, from its JSON summary's pull_in object
// (coupling/pull_in_study.hpp's pull_in_summary), one printer for every scene:
//
//   <name> (<structure>, <field>, gas <gas>): static at 50.0 V: control deflection -0.04632 um
//   <name> (...): quasi-static pull-in at 188.26 V, control deflection -1.532 um (40.9 % of the
//   gap)
//     quasi-static pull-out at ... (contact)
//     dynamic pull-in (step voltage, monolithic) at 173.91 V (0.924 of quasi-static; 173.52 V
//     does not), pull-in time 11.898 us (1.1 % from a run at 0.1 x the tolerances: ...); 9 runs
//     release: ...
//   <name> (...): 180.00 V step (staggered), control deflection -3.6750 um at 12.345 us
//     (touch-down); 1234 steps, 5678 residual evaluations
//   wrote out/<name>.h5 (3.2 s)
#pragma once
#include <string>

#include "io/json_summary.hpp"

namespace rfmems {

// The lines for `pull_in` (the summary's pull_in object) of case `name`.
std::string pull_in_text(const std::string& name, const Json& pull_in);

}  // namespace rfmems

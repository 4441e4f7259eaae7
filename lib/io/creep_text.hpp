// The text rfmems-creep prints, from its JSON summaries (physics/creep/creep_results.hpp):
//
//   <name> (plate creep, implicit): 812 steps to t = 500 h, tip: w -1.2345e-07 -> -2.3456e-07 m
//     creep life 123.4 h (collapse)
//
// and for --hold-voltage-for-gap:
//
//   hold voltage 23.456789 V: gap 1.43e-06 m at probe centre (9 trials)
#pragma once
#include <string>

#include "io/json_summary.hpp"

namespace rfmems {

std::string creep_text(const Json& summary);
std::string hold_voltage_text(const Json& hold);

}  // namespace rfmems

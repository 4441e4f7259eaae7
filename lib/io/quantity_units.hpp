// The SI unit of every quantity rfmems writes to a result file, by the name it is written
// under (one name for one idea across the code): the cell fields, the probe and time-series
// components and their abscissae. "1" marks a dimensionless number. Forces and moments are
// those of the structure's own model: a plate's are whole (N, N m / m = N per unit length of a
// moment resultant), a plane beam's per unit depth.
#pragma once
#include <optional>
#include <string>

namespace rfmems {

// The unit of `name`, or nothing when the name is not a known quantity (a probe's own name).
std::optional<std::string> units_of(const std::string& name);

}  // namespace rfmems

#include "io/frequency_sweep.hpp"

#include <cmath>

namespace rfmems {

std::vector<Real> read_frequency_sweep(const CaseNode& node) {
  node.require(node.has("frequencies") != node.has("sweep"), "frequencies",
               "give the frequencies or a sweep (one of the two)");
  std::vector<Real> frequencies;
  if (node.has("frequencies")) {
    frequencies = node.get_quantities("frequencies", Dimension::Frequency);
    node.require(!frequencies.empty(), "frequencies", "give at least one");
    for (const Real f : frequencies)
      node.require(f > 0, "frequencies", "every frequency must be > 0");
    return frequencies;
  }
  const CaseNode sweep = node.child("sweep");
  const Real from = sweep.get_quantity("from", Dimension::Frequency, Range::positive());
  const Real to = sweep.get_quantity("to", Dimension::Frequency, Range::positive());
  const long points = sweep.get_int("points", 50, Range::closed(1, 100000));
  sweep.require(to >= from, "to", "must not be below sweep.from");
  for (long k = 0; k < points; ++k)
    frequencies.push_back(points == 1 ? from
                                      : from * std::pow(to / from, double(k) / (points - 1)));
  return frequencies;
}

}  // namespace rfmems

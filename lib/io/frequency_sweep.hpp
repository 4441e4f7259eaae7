// The frequencies of a harmonic (frequency-domain) analysis, as a case gives them in its
// analysis block, one of the two:
//
//   frequencies: [50 kHz, 64 kHz]                    # listed, each > 0, or
//   sweep: {from: 10 kHz, to: 200 kHz, points: 60}  # evenly spaced in log f (points default 50)
//
// Read by every harmonic analysis (rfmems-solid's analysis block, rfmems-pullin's
// pull_in.harmonic), so that both spell and check them the same way.
#pragma once
#include <vector>

#include "core/types.hpp"
#include "io/case_file.hpp"

namespace rfmems {

// The frequencies [Hz] of `node` in increasing order of the sweep (a list as given); InputError
// naming the key unless exactly one of the two is there and its values are valid.
std::vector<Real> read_frequency_sweep(const CaseNode& node);

}  // namespace rfmems

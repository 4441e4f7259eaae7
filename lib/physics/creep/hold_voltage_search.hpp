// The hold voltage that gives a held switch a prescribed gap at t = 0. The thesis (Table 4.3)
// starts its varactor from a 1.8 um gap that the hold voltage closes elastically to 1.43 um
// (the experiment's gap extrapolated back to t = 0) without giving the voltage; this finds it.
//
// The elastic equilibrium's gap g(V) falls monotonically from g(0) to the fold at the pull-in
// voltage, beyond which there is no equilibrium. g = target is solved in s = V^2, where g is
// linear for small deflections (the load is V^2 p1(g)) and concave (electrostatic softening):
//   - bracket: from the first guess, extrapolate the chord through (0, g(0)) and the last
//     point (concavity puts the chord's root beyond the true one, so one step brackets it;
//     growth capped at x16); a voltage without equilibrium is an upper bound without a value
//     and is bisected towards the last good point (down to 1e-8 of V^2: then the target lies
//     beyond the fold);
//   - then false position with the Illinois modification (the retained end's residual halved
//     when it is kept twice): superlinear, never leaving the bracket.
// Stops when |g - target| <= gap_tolerance.
#pragma once
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "core/types.hpp"
#include "physics/creep/creep_case.hpp"

namespace rfmems {

struct HoldVoltageSearchOptions {
  Real first_voltage = 10;     // [V] the first trial above 0 (e.g. a previous answer)
  Real gap_tolerance = 1e-12;  // [m] on |g(V) - target|
  int max_evaluations = 100;
};

struct HoldVoltageTrial {
  Real voltage = 0;
  std::optional<Real> gap;  // empty: no equilibrium
};

struct HoldVoltageSearchResult {
  Real voltage = 0;                      // [V]
  Real gap = 0;                          // [m] g(voltage), within the tolerance of the target
  std::vector<HoldVoltageTrial> trials;  // in order, V = 0 first
};

// gap_at(V): the gap of the elastic equilibrium at V, or empty if there is none. Throws
// SolverError if the target is not below g(0), lies beyond the fold, or the evaluations run
// out.
HoldVoltageSearchResult find_hold_voltage(const std::function<std::optional<Real>(Real)>& gap_at,
                                          Real target,
                                          const HoldVoltageSearchOptions& options = {});

// The gap g0 + w at probe `probe` of the case's elastic state at t = 0 under voltage V on the
// case's electrodes (the creep law plays no part at t = 0). InputError without a gap or probe.
std::function<std::optional<Real>(Real)> case_probe_gap(const CreepCase& creep_case,
                                                        std::size_t probe);

}  // namespace rfmems

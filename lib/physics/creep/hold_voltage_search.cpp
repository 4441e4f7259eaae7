// Hold voltage for a prescribed gap at t = 0 (see the header).
#include "physics/creep/hold_voltage_search.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/error.hpp"
#include "physics/creep/plate_creep_system.hpp"

namespace rfmems {

namespace {

struct Point {
  Real s = 0;  // V^2
  Real f = 0;  // g - target
};

}  // namespace

HoldVoltageSearchResult find_hold_voltage(const std::function<std::optional<Real>(Real)>& gap_at,
                                          Real target, const HoldVoltageSearchOptions& options) {
  HoldVoltageSearchResult result;
  auto evaluate = [&](Real s) {
    const Real v = std::sqrt(s);
    const std::optional<Real> g = gap_at(v);
    result.trials.push_back({v, g});
    return g;
  };
  const std::optional<Real> g0 = evaluate(0);
  if (!g0 || !(*g0 > target))
    throw SolverError(fmt::format(
        "hold voltage search: the target gap {:.6g} m is not below the unloaded gap {:.6g} m",
        target, g0 ? *g0 : std::nan("")));
  const Point origin{0, *g0 - target};
  Point lo = origin;
  std::optional<Point> hi;             // bracketing point with f < 0
  std::optional<Real> no_equilibrium;  // smallest s seen without equilibrium
  int kept = 0;                        // +-1: lo / hi replaced last; +-2: twice in a row
  Real s = options.first_voltage * options.first_voltage;
  for (int k = 1; k < options.max_evaluations; ++k) {
    const std::optional<Real> g = evaluate(s);
    if (!g) {
      if (hi)
        throw SolverError(fmt::format(
            "hold voltage search: no equilibrium at {:.8g} V, inside the bracket [{:.8g}, {:.8g}] "
            "V (gap not monotone?)",
            std::sqrt(s), std::sqrt(lo.s), std::sqrt(hi->s)));
      no_equilibrium = no_equilibrium ? std::min(*no_equilibrium, s) : s;
    } else {
      const Point p{s, *g - target};
      if (std::abs(p.f) <= options.gap_tolerance) {
        result.voltage = std::sqrt(s);
        result.gap = *g;
        return result;
      }
      if (p.f > 0) {
        lo = p;
        kept = kept >= 1 ? 2 : 1;
      } else {
        hi = p;
        kept = kept <= -1 ? -2 : -1;
      }
    }
    if (hi) {
      // Illinois: the end that stayed while the other was replaced twice has its residual
      // halved, so the false-position step moves past the root.
      if (kept == 2) hi->f *= 0.5;
      if (kept == -2) lo.f *= 0.5;
      s = lo.s - lo.f * (hi->s - lo.s) / (hi->f - lo.f);
    } else {
      // The chord through the origin and lo, capped; below a voltage without equilibrium,
      // bisect towards it.
      Real next = lo.s > 0 ? lo.s - lo.f * lo.s / (lo.f - origin.f) : s;
      next = std::min(next, 16 * std::max(lo.s, s));
      if (no_equilibrium && next >= *no_equilibrium) next = 0.5 * (lo.s + *no_equilibrium);
      if (no_equilibrium && *no_equilibrium - lo.s <= 1e-8 * *no_equilibrium)
        throw SolverError(fmt::format(
            "hold voltage search: no equilibrium above {:.8g} V, where the gap {:.6g} m is still "
            "above the target {:.6g} m (the target lies beyond the pull-in fold)",
            std::sqrt(lo.s), lo.f + target, target));
      s = next;
    }
  }
  throw SolverError(
      fmt::format("hold voltage search: no gap within {:.3g} m of {:.6g} m after {} evaluations",
                  options.gap_tolerance, target, options.max_evaluations));
}

std::function<std::optional<Real>(Real)> case_probe_gap(const CreepCase& c, std::size_t probe) {
  if (!c.has_gap) throw InputError("hold voltage search: the case has no actuation (no gap)");
  if (probe >= c.probes.size())
    throw InputError(fmt::format("hold voltage search: no probe {} (the case has {})", probe + 1,
                                 c.probes.size()));
  // One system for every trial; only the hold load changes. Each trial's Newton (a tangent
  // factorisation per iteration, the cost here: ~1 s on 3000 cells) starts from the last
  // equilibrium found, which is close (3 iterations where 5-6 from the unloaded plate).
  // With geometric nonlinearity the von Karman plate (its equilibrium a Newton iteration too).
  auto system =
      c.plate->von_karman
          ? std::make_shared<PlateCreepSystem>(*c.plate->von_karman, c.law, c.thickness_intervals)
          : std::make_shared<PlateCreepSystem>(*c.plate->op, c.law, c.thickness_intervals);
  auto last = std::make_shared<std::vector<Real>>(system->size(), 0.0);
  return [&c, probe, system, last](Real voltage) -> std::optional<Real> {
    // V = 0 before any hold is set: the plate is linear, one solve with its own factors.
    if (voltage > 0 || system->hold_voltage())
      system->set_hold_voltage(CreepHoldVoltage{c.gap_elements, c.initial_gap, c.gap_law, voltage});
    std::vector<Real> state = *last;
    try {
      system->equilibrate(0, state);
    } catch (const SolverError&) {
      return std::nullopt;
    } catch (const RecoverableError&) {  // a gap closed during Newton
      return std::nullopt;
    }
    *last = state;
    const std::span<const Real> y(state.data(), system->structural_size());
    return c.initial_gap + c.plate->probe_values({c.probes[probe]}, 0, y)[0][0];
  };
}

}  // namespace rfmems

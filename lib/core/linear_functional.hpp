// A linear functional l(u) = sum_k w_k u[i_k] of a state vector: what a run reports and
// controls as "the deflection". A single unknown (a cell's u_y) is the one-term case; a point
// value of a cell's reconstruction (the tip of a beam, half a cell beyond the last centroid) is
// a combination of the cell's stencil. Being linear, the same weights give the point's velocity
// from the velocity unknowns and its share of a displacement-control solve.
#pragma once
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

struct LinearFunctional {
  std::vector<std::pair<Index, Real>> terms;  // (unknown, weight)

  static LinearFunctional unknown(Index i) { return {{{i, 1.0}}}; }

  Real operator()(std::span<const Real> u) const {
    Real sum = 0;
    for (const auto& [i, w] : terms) sum += w * u[i];
    return sum;
  }
  // this += scale * other (an unknown may then appear twice; the sum is the same).
  LinearFunctional& add(const LinearFunctional& other, Real scale) {
    for (const auto& [i, w] : other.terms) terms.emplace_back(i, scale * w);
    return *this;
  }
  // The same weights on other unknowns, e.g. the velocities of a first-order state.
  LinearFunctional mapped(const std::function<Index(Index)>& index) const {
    LinearFunctional out;
    out.terms.reserve(terms.size());
    for (const auto& [i, w] : terms) out.terms.emplace_back(index(i), w);
    return out;
  }
  // Every unknown in [0, n).
  bool within(Index n) const {
    for (const auto& term : terms)
      if (term.first < 0 || term.first >= n) return false;
    return !terms.empty();
  }
};

}  // namespace rfmems

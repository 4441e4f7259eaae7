// The structure's surface facing an electrode across a gap, as the gap loads (parallel-plate
// pressure, contact, the creep hold voltage) and the gap criteria (touching point, lifetime)
// sample it. Built by StructuralModel::gap_elements (structural_model.hpp).
#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include "core/types.hpp"
#include "fv/dof_weight.hpp"

namespace rfmems {

// A quadrature point of a gap element: its share of the element's area and the displacement
// along the gap axis there as an affine map of the unknowns, u = offset + sum_k weight_k y[dof_k]
// (a reconstruction of the surface within the element).
struct GapPoint {
  Real area_fraction;
  Real offset = 0;
  std::vector<DofWeight> terms;
};

// A piece of the structure's surface that faces an electrode across a gap (the electrode
// below it, normal to the last axis: y in 2D, z for plates and 3D): the unknown that moves it
// along that axis (positive: the gap opens), its area, and its bounding box (to intersect it
// with the electrode's extent).
struct GapElement {
  Index dof;
  Real area;
  Vec3 lo, hi;
  std::vector<GapPoint> points;  // empty: one point, u = y[dof] (the element's own unknown)
};

// u_q(y) = offset + sum_k weight_k y[dof_k] at point q.
inline Real gap_displacement(const GapPoint& q, std::span<const Real> y) {
  return weighted_sum(q.terms, y, q.offset);
}

// The point where the surface is lowest (smallest u_q; the first of equals) and its element,
// over elements that all carry their points (as ParallelPlateActuation::elements() do). The
// smallest gap g0 + u_q of the gap loads and criteria, and its rate sum_k weight_k y'[dof_k].
struct LowestGapPoint {
  std::size_t element = 0;
  const GapPoint* point = nullptr;  // null without points
};
LowestGapPoint lowest_gap_point(std::span<const GapElement> elements, std::span<const Real> y);

}  // namespace rfmems

// The parallel-plate law (parallel_plate_actuation.hpp) seen as a gap field (gap_field.hpp): its
// load is inside the actuated structure's operator with the exact Jacobian (traits().exact), so
// a partitioned coupling applies none of it and splits the gas alone; the field reports its
// total force, the smallest gap (the contact root's) and the gap at rest.
#pragma once
#include "physics/electrostatics/gap_field.hpp"
#include "physics/electrostatics/parallel_plate_actuation.hpp"

namespace rfmems {

class ParallelPlateGapField : public GapField {
 public:
  explicit ParallelPlateGapField(const ParallelPlateActuation& actuation) : actuation_(actuation) {}
  std::string name() const override { return "parallel_plate"; }
  StructureLoad load(std::span<const Real> u, Real voltage) override {
    return {{}, actuation_.total_force(voltage * voltage, u)};
  }
  Real min_gap(std::span<const Real> u) const override { return actuation_.min_gap(u); }
  Real rest_gap() const override { return actuation_.initial_gap(); }
  GapFieldTraits traits() const override {
    GapFieldTraits t;
    t.exact = true;
    return t;
  }
  double seconds() const override { return 0; }
  Json counters() const override { return Json::object(); }

 private:
  const ParallelPlateActuation& actuation_;
};

}  // namespace rfmems

// A field that loads a structure across its gap: what the field-coupled structure
// (coupling/field_coupled_structure.hpp) asks of it, whatever solves it. The Laplace field in a
// gap mesh that follows a plane beam (laplace_gap_field.hpp) and the immersed-boundary field on
// a fixed background (ibm/immersed_boundary_field.hpp) give no exact Jacobian blocks: the
// coupling applies their load lagged or solves them in every residual. The parallel-plate law
// (parallel_plate_actuation.hpp) is inside the structure's operator with its exact Jacobian: as
// a gap field (traits().exact) it only reports its force and gap, and the coupling partitions the
// gas alone.
//
// A field answers with its force per structure unknown at a displacement u and voltage V, the
// smallest gap at u (the contact root's), the gap at rest, and what its resolution asks of the
// coupling (GapFieldTraits).
#pragma once
#include <span>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "io/json_summary.hpp"
#include "physics/structure/structure_load.hpp"

namespace rfmems {

// What a field's resolution asks of its coupling.
struct GapFieldTraits {
  Real static_tolerance = 1e-10;  // the fixed point at a voltage: relative change of the control
  Real quasi_static_tolerance = 1e-9;  // the fixed point at a deflection: update / |delta|
  int max_iterations = 200;            // of either fixed point
  // The lagged load: a trial gap below this fraction of the rest gap is a failed trial state
  // (gap_scaled_lagged_load.hpp; 0: its own default).
  Real closed_fraction = 0;
  // > 0: the velocities' absolute tolerance is the displacements' times this rate [1/s] unless
  // the run sets per-kind tolerances (state_tolerances.hpp).
  Real velocity_rate = 0;
  Real turning_after = 0;  // the turning-back rule counts extremes from this time on [s]
  // The structure's operator carries the field's load and its exact Jacobian (load() reports
  // it, the coupling does not apply it).
  bool exact = false;
};

class GapField {
 public:
  virtual ~GapField() = default;
  virtual std::string name() const = 0;
  // The field's force per structure unknown at displacement u and voltage V (a mesh it cannot
  // follow to u: MeshError).
  virtual StructureLoad load(std::span<const Real> u, Real voltage) = 0;
  // The smallest gap at u (cheap: the contact root's) and at rest [m].
  virtual Real min_gap(std::span<const Real> u) const = 0;
  virtual Real rest_gap() const = 0;
  virtual GapFieldTraits traits() const = 0;
  // CPU seconds spent in load() so far, and what the field did (for the summary).
  virtual double seconds() const = 0;
  virtual Json counters() const = 0;
};

}  // namespace rfmems

// A field that loads a plane beam across its gap and gives no exact Jacobian blocks: what the
// field-coupled beam (coupling/field_coupled_beam.hpp) asks of it, whatever solves it. The
// Laplace field in a gap mesh that follows the beam (laplace_gap_field.hpp) and the
// immersed-boundary field on a fixed background (ibm/immersed_boundary_field.hpp) are the two.
//
// A field answers with its force per beam unknown at a displacement u and voltage V (the load
// the coupled beam applies, lagged or exact), the smallest gap at u (the contact root's), the
// gap at rest, and what its resolution asks of the coupling (GapFieldTraits). A field whose
// beam is a surface in the gas's mesh also carries the gas (ibm/immersed_gas.hpp) on that surface.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "io/json_summary.hpp"

namespace rfmems {

class ImmersedGasModel;

// A load on the beam's unknowns and its total along the gap axis (y) [N/m; negative: closing].
struct BeamLoad {
  std::vector<Real> force;
  Real force_y = 0;
};

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
};

class GapField {
 public:
  virtual ~GapField() = default;
  virtual std::string name() const = 0;
  // The field's force per beam unknown at displacement u and voltage V (a mesh it cannot
  // follow to u: MeshError).
  virtual BeamLoad load(std::span<const Real> u, Real voltage) = 0;
  // The smallest gap at u (cheap: the contact root's) and at rest [m].
  virtual Real min_gap(std::span<const Real> u) const = 0;
  virtual Real rest_gap() const = 0;
  virtual GapFieldTraits traits() const = 0;
  // CPU seconds spent in load() so far, and what the field did (for the summary).
  virtual double seconds() const = 0;
  virtual Json counters() const = 0;

  // The gas around the beam's surface at rest at time t0, and advanced over [t, t + dt] with
  // the beam at u moving at v (the unknowns' rates): its force on the beam at t + dt. A field
  // whose beam is not a surface in the gas's mesh carries no gas (InputError).
  virtual void reset_gas(ImmersedGasModel& gas, Real t0);
  virtual BeamLoad gas_load(ImmersedGasModel& gas, std::span<const Real> u, std::span<const Real> v,
                            Real t, Real dt);
};

}  // namespace rfmems

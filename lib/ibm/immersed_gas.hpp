// The gas slot of the immersed-boundary switch: what a gas model on the beam's surface must
// offer, so that the ESBGK gas on the background mesh plugs in beside the cheap models without
// touching the coupling. ImmersedBoundaryField::surface_gas makes one the coupling's
// StructureGas (physics/gas/structure_gas.hpp), moving the surface with the structure.
//
// Per coupled step the manager hands the gas the body's surface at the end of the step and
// its segment velocities there, and asks for the gas force on each surface segment after
// advancing the gas over [t, t + dt]. The force is applied to the structure, lagged, during
// the next structural step (explicit, first order in the coupling; docs/immersed_switch.md),
// or, with coupling.strong_gas, the step is redone from a checkpoint of the gas (and of IDA)
// until the combined interface load converges (strong coupling with the gas).
//
// Models here: none (no call at all), reynolds (immersed_reynolds_film.hpp, a 1D squeeze film
// along the beam's facing side). An ESBGK model implements the same three calls on the
// background mesh (mark, interpolate the distributions to the IB faces, COMET/IDA step,
// integrate the traction on the IB faces, ForceTransfer::to_surface).
#pragma once
#include <span>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "ibm/immersed_surface.hpp"
#include "physics/gas/stepped_gas.hpp"

namespace rfmems {

class ImmersedGasModel : public SteppedGas {
 public:
  // The gas at rest (ambient) around the body at `surface` at time t0.
  virtual void reset(const ImmersedSurface& surface, Real t0) = 0;
  // Advances the gas over [t, t + dt] with the body at `surface` (its state at t + dt) moving
  // at segment_velocity [m/s] per segment; returns the gas force per segment [N/m] at t + dt.
  virtual std::vector<Vec3> advance(const ImmersedSurface& surface,
                                    std::span<const Vec3> segment_velocity, Real t, Real dt) = 0;
};

}  // namespace rfmems

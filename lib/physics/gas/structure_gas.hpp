// The gas on a structure's gap-facing surface as a partitioned coupling steps it
// (coupling/field_coupled_structure.hpp): the Reynolds film under a plate's cells
// (film_under_structure.hpp) or a gas on an immersed beam's surface (the film on a strip, the
// ESBGK gas on the background: ibm/immersed_boundary_field.hpp), one protocol for all.
//
// The gas starts at rest at t0 (reset), and each advance moves it over [t, t + dt] with the
// structure at u (its state at t + dt) moving at v (the unknowns' rates), returning its load on
// the structure's unknowns at t + dt: held over the next structural steps (lagged), or redone
// from a checkpoint per iterate of a strongly coupled step (stepped_gas.hpp).
#pragma once
#include <span>

#include "physics/gas/stepped_gas.hpp"
#include "physics/structure/structure_load.hpp"

namespace rfmems {

class StructureGas : public SteppedGas {
 public:
  virtual void reset(Real t0) = 0;
  virtual StructureLoad advance(std::span<const Real> u, std::span<const Real> v, Real t,
                                Real dt) = 0;
};

}  // namespace rfmems

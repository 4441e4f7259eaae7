// The gas on a structure's gap-facing surface as a partitioned coupling steps it
// (coupling/field_coupled_structure.hpp): the Reynolds film under a plate's cells
// (film_under_structure.hpp) or a gas on an immersed beam's surface (the film on a strip, the
// ESBGK gas on the background: ibm/immersed_boundary_field.hpp), one protocol for all.
//
// The gas starts at rest at t0 (reset), and each advance moves it over [t, t + dt] with the
// structure at u (its state at t + dt) moving at v (the unknowns' rates), returning its load on
// the structure's unknowns at t + dt: held over the next structural steps (lagged), or redone
// from a checkpoint per iterate of a strongly coupled step.
#pragma once
#include <span>
#include <string>

#include "core/error.hpp"
#include "physics/structure/structure_load.hpp"

namespace rfmems {

class StructureGas {
 public:
  virtual ~StructureGas() = default;
  virtual std::string name() const = 0;
  virtual void reset(Real t0) = 0;
  virtual StructureLoad advance(std::span<const Real> u, std::span<const Real> v, Real t,
                                Real dt) = 0;
  // One checkpoint of the gas after the last advance (or reset): save, then restore any number
  // of times to redo the next advance with a corrected motion. Gases without one throw.
  virtual void save_checkpoint() { no_checkpoint(); }
  virtual void restore_checkpoint() { no_checkpoint(); }
  // While held, a gas on a marked background keeps the cell marking of its last advance (the
  // strong iteration's iterates within a step differ by far less than a cell; a class change
  // between them makes the force jump). Others ignore it.
  virtual void hold_marking(bool /*hold*/) {}
  // The largest Knudsen number seen so far (validity report).
  virtual Real max_knudsen() const { return 0; }

 private:
  [[noreturn]] void no_checkpoint() const {
    throw InputError("gas model '" + name() + "' keeps no checkpoint (coupling.strong_gas)");
  }
};

}  // namespace rfmems

// What every gas a partitioned coupling steps offers besides its step (structure_gas.hpp on a
// structure's unknowns, ibm/immersed_gas.hpp on an immersed surface): its name, one checkpoint
// for the strong iteration, the marking hold and the Knudsen range it saw.
#pragma once
#include <string>

#include "core/error.hpp"
#include "core/types.hpp"

namespace rfmems {

class SteppedGas {
 public:
  virtual ~SteppedGas() = default;
  virtual std::string name() const = 0;
  // One checkpoint of the gas after the last advance (or reset): save, then restore any number
  // of times to redo the next advance with a corrected motion, as if the advances since the
  // save had not been made (the strong coupling's iterate per step). Gases without one throw.
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

#include "physics/electrostatics/gap_field.hpp"

#include "core/error.hpp"

namespace rfmems {

void GapField::reset_gas(ImmersedGasModel&, Real) {
  throw InputError("the " + name() + " field carries no gas on its beam");
}

BeamLoad GapField::gas_load(ImmersedGasModel&, std::span<const Real>, std::span<const Real>, Real,
                            Real) {
  throw InputError("the " + name() + " field carries no gas on its beam");
}

}  // namespace rfmems

// The validity report of a kinetic gas run (physics/validity/scene_validity.hpp): the computed
// field's density and temperature range (over every rank's owned cells; call on every rank), the
// reference length, the cell size and the velocity grid against the diffuse walls (update the
// operator's macros from the final state first).
#pragma once
#include "physics/validity/scene_validity.hpp"

namespace rfmems {

struct KineticScene;
class Communicator;

ValidityReport kinetic_scene_validity(const KineticScene& scene, const Communicator& comm);

}  // namespace rfmems

// The validity report of a creep run (physics/validity/scene_validity.hpp): its plate (the creep
// slenderness criterion) and, with an actuation, its parallel-plate gap (the rest gap: creep
// runs record no film).
#pragma once
#include "physics/validity/scene_validity.hpp"

namespace rfmems {

struct CreepCase;

ValidityReport creep_case_validity(const CreepCase& creep);

}  // namespace rfmems

// The validity report of a switch run (physics/validity/scene_validity.hpp): the scene's
// structure, field and gas described with what the run computed (its smallest gap, the fold),
// plus the immersed field's own limits and the dynamic bisection's tolerance.
#pragma once
#include "physics/validity/scene_validity.hpp"

namespace rfmems {

struct SwitchScene;
struct PullInReport;

// The switch scene's description; `thickness` from the case (model.thickness); report: what the
// pull-in run computed, or null before a run.
SceneDescription describe_switch_scene(const SwitchScene& scene, Real thickness,
                                       SceneDescription::Analysis analysis,
                                       const PullInReport* report);

// The pull-in driver's one call: describe_switch_scene with the plate's thickness and the
// analysis the run did, then check_scene_validity.
ValidityReport switch_scene_validity(const SwitchScene& scene, const PullInReport& report);

}  // namespace rfmems

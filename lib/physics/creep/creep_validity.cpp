#include "physics/creep/creep_validity.hpp"

#include "physics/creep/creep_case.hpp"

namespace rfmems {

ValidityReport creep_case_validity(const CreepCase &creep) {
  SceneDescription s;
  s.analysis = SceneDescription::Analysis::Creep;
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Vec3 &x : creep.plate->mesh->nodes()) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  s.length = hi.x() - lo.x();
  s.width = hi.y() - lo.y();
  s.thickness = creep.plate->section.thickness;
  s.plate_shear_creep = creep.shear_creep;
  s.plate_stretching = creep.plate->von_karman != nullptr;
  if (creep.has_gap) {
    s.gap = creep.initial_gap;
    s.fringing_factor = creep.gap_law.fringing_factor;
  }
  return check_scene_validity(s);
}

}  // namespace rfmems

#include "coupling/switch_validity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "coupling/pull_in_study.hpp"
#include "physics/plate/plate_scene.hpp"

namespace rfmems {

namespace {

// The immersed field's own limits: the touch-down against the background's resolution, the
// 1D Reynolds film's range (its Knudsen number and its large-displacement limit), the kinetic
// gas's cell size against the mean free path.
void check_immersed_field(const SwitchScene &scene, const PullInReport &report, ValidityReport &r) {
  const ImmersedField &f = *scene.immersed;
  const Real cell = f.sw->background_cell_height();
  const bool timed = report.has_dynamic || report.has_transient;
  if (timed && report.contact_gap < cell)
    r.warnings.push_back(
        fmt::format("contact gap {:.3g} m is below one background cell ({:.3g} "
                    "m): the IB layer fills the gap before touch-down",
                    report.contact_gap, cell));
  const Real kn = report.counters.value("gas_max_knudsen", 0.0);
  if (scene.gas() == GasModel::Reynolds && kn > 1.0)
    r.warnings.push_back(
        fmt::format("Reynolds film at Kn up to {:.3g} (> 1): Veijola's viscosity "
                    "fit holds, the film's lubrication assumptions weaken",
                    kn));
  if (scene.gas() == GasModel::Reynolds && timed && report.contact_gap < 0.5 * scene.gap)
    r.warnings.push_back(
        "Reynolds film followed to a gap below half the rest gap (large displacement: the 1D "
        "film takes h from the deformed beam, no edge correction at the tip)");
  if (scene.gas() == GasModel::Esbgk) {
    const ImmersedBoundaryGeometry &g = f.geometry;
    const Real hx = (g.background_upper.x() - g.background_lower.x()) / g.background_cells[0];
    check_cell_size_against_mean_free_path(std::min(hx, cell), f.gas.film.mean_free_path,
                                           f.gas.film.mean_free_path,
                                           "actuation.immersed.background.cells", r);
  }
}

}  // namespace

SceneDescription describe_switch_scene(const SwitchScene &scene, Real thickness,
                                       SceneDescription::Analysis analysis,
                                       const PullInReport *report) {
  SceneDescription s;
  s.analysis = analysis;
  s.plate = scene.structure->kind() == "plate";
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Vec3 &x : scene.structure->structure_mesh().nodes()) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  s.length = hi.x() - lo.x();
  // A plate spans x and y with the thickness given; a plane beam's thickness is its y extent
  // (its width is not modelled).
  s.width = s.plate ? hi.y() - lo.y() : 0;
  s.thickness = s.plate ? thickness : hi.y() - lo.y();
  s.gap = scene.gap;
  s.parallel_plate = scene.field() == FieldModel::ParallelPlate;
  s.fringing_factor = scene.actuation ? scene.actuation->law().fringing_factor : 0;
  if (scene.film) {
    s.reynolds = true;
    s.gas = scene.film->gas();
  }
  if (report) {
    Real g_min = scene.gap;
    for (const PullInPoint &p : report->quasi_static.curve) g_min = std::min(g_min, p.min_gap);
    for (const auto &[voltage, run] : report->histories)
      for (const DynamicSample &sample : run.history) g_min = std::min(g_min, sample.min_gap);
    s.min_gap = g_min;
    s.equilibrium_displacement = std::abs(report->quasi_static.pull_in_displacement);
  }
  return s;
}

ValidityReport switch_scene_validity(const SwitchScene &scene, const PullInReport &report) {
  // A plate's thickness; a plane beam's is its mesh's, not a key (0: not checked).
  const auto *plate = dynamic_cast<const PlateScene *>(scene.structure.get());
  const Real thickness = plate ? plate->section.thickness : 0.0;
  const auto analysis = report.has_dynamic || report.has_transient
                            ? SceneDescription::Analysis::Dynamic
                            : SceneDescription::Analysis::Static;
  ValidityReport r =
      check_scene_validity(describe_switch_scene(scene, thickness, analysis, &report));
  if (scene.immersed) check_immersed_field(scene, report, r);
  // The bisection's tolerance against what it measures (a fixed voltage is coarse on a slender
  // structure of a few volts).
  const Real v_qs = report.quasi_static.pull_in_voltage;
  if (report.has_dynamic && report.tolerance > ValidityCriteria::kMaxBisectionTolerance * v_qs)
    r.warnings.push_back(fmt::format(
        "pull_in.dynamic.tolerance {:.3g} V is {:.2g} % of the quasi-static pull-in voltage "
        "({:.4g} V): the dynamic pull-in voltage is known to that only",
        report.tolerance, 100 * report.tolerance / v_qs, v_qs));
  return r;
}

}  // namespace rfmems

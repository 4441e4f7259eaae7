#include "coupling/scene_validity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "coupling/pull_in_study.hpp"
#include "coupling/switch_scene.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distributed_mesh.hpp"
#include "physics/creep/creep_case.hpp"
#include "physics/gas/kinetic/kinetic_case.hpp"

namespace rfmems {

namespace {

using C = ValidityCriteria;

void check_film(const SceneDescription &s, ValidityReport &r) {
  const Real p = s.gas.ambient_pressure;
  const Real g_min = s.min_gap > 0 ? std::min(s.min_gap, s.gap) : s.gap;
  const Real kn_min = s.gas.knudsen(p, s.gap), kn_max = s.gas.knudsen(p, g_min);
  r.ranges.push_back({"film_knudsen", kn_min, kn_max});
  const bool veijola = s.gas.rarefaction == Rarefaction::Veijola;
  const Real kn_limit = veijola ? C::kVeijolaMaxKnudsen : C::kContinuumMaxKnudsen;
  if (kn_max > kn_limit)
    r.warnings.push_back(veijola
                             ? fmt::format("Reynolds film: Kn of the local gap reaches {:.3g} "
                                           "(gap {:.3g} um at "
                                           "{:.3g} Pa), beyond Veijola's fit range Kn <= {:g}",
                                           kn_max, g_min * 1e6, p, kn_limit)
                             : fmt::format("Reynolds film without rarefaction: Kn of the local "
                                           "gap reaches "
                                           "{:.3g}, beyond the continuum film's Kn <= {:g} (use "
                                           "rarefaction: "
                                           "veijola)",
                                           kn_max, kn_limit));
  const Real fraction = s.equilibrium_displacement / s.gap;
  r.ranges.push_back({"film_displacement_over_gap", 0, fraction});
  if (fraction > C::kFilmMaxDisplacementFraction)
    r.warnings.push_back(
        fmt::format("Reynolds film: equilibrium displacement / gap = {:.3g} "
                    "beyond {:g} (large-displacement film)",
                    fraction, C::kFilmMaxDisplacementFraction));
  if (s.width > 0) {
    const Real g_over_b = s.gap / s.width;
    if (!r.find("gap_over_width")) r.ranges.push_back({"gap_over_width", g_over_b, g_over_b});
    if (g_over_b > C::kFilmMaxGapOverWidth)
      r.warnings.push_back(
          fmt::format("Reynolds film: gap / width = {:.3g} beyond {:g} (the "
                      "open-edge correction is left out)",
                      g_over_b, C::kFilmMaxGapOverWidth));
  }
}

void check_plate(const SceneDescription &s, ValidityReport &r) {
  if (s.thickness <= 0 || s.length <= 0) return;
  const Real slenderness = s.length / s.thickness;
  r.ranges.push_back({"length_over_thickness", slenderness, slenderness});
  if (s.width > 0)
    r.ranges.push_back({"width_over_thickness", s.width / s.thickness, s.width / s.thickness});
  if (!s.plate) return;
  const bool creep = s.analysis == SceneDescription::Analysis::Creep && !s.plate_shear_creep;
  const Real limit = creep ? C::kCreepPlateMinSlenderness : C::kPlateMinSlenderness;
  if (slenderness < limit)
    r.warnings.push_back(creep ? fmt::format("plate creep: L/h = {:.3g} below {:g} (the plate "
                                             "neglects shear "
                                             "creep: 15 % at L/h = 10, 2.5 % at 30, "
                                             "docs/creep.md; "
                                             "creep.shear_creep: true includes it)",
                                             slenderness, limit)
                               : fmt::format("plate: L/h = {:.3g} below {:g} (thick plate: "
                                             "through-thickness "
                                             "stresses the Mindlin plate neglects)",
                                             slenderness, limit));
}

void check_parallel_plate(const SceneDescription &s, ValidityReport &r) {
  const Real g_over_l = s.gap / s.length;
  r.ranges.push_back({"gap_over_length", g_over_l, g_over_l});
  const Real g_over_b = s.width > 0 ? s.gap / s.width : 0;
  if (s.width > 0) r.ranges.push_back({"gap_over_width", g_over_b, g_over_b});
  if (s.fringing_factor > 0) {
    if (g_over_b > C::kFringingCorrectionMaxGapOverWidth)
      r.warnings.push_back(
          fmt::format("parallel-plate electrostatics: gap / width = {:.3g} "
                      "beyond {:g}, the first-order fringing correction's range",
                      g_over_b, C::kFringingCorrectionMaxGapOverWidth));
    return;
  }
  const Real limit = C::kFringingMaxForceError / C::kFringingFactor;
  for (const auto &[ratio, what] : {std::pair{g_over_b, "width"}, std::pair{g_over_l, "length"}})
    if (ratio > limit)
      r.warnings.push_back(
          fmt::format("parallel-plate electrostatics without fringing: gap / {} "
                      "= {:.3g} beyond {:.3g} (fringing adds {:.0f} % to the "
                      "force; set actuation.fringing: {:g})",
                      what, ratio, limit, 100 * C::kFringingFactor * ratio, C::kFringingFactor));
}

void check_kinetic(const SceneDescription::Kinetic &k, ValidityReport &r) {
  // lambda = mu / p sqrt(pi R T / 2), p = rho R T (Bird's hard-sphere mean free path).
  auto knudsen = [&](Real rho, Real T, Real mu) {
    return mean_free_path(rho, T, mu, k.gas_constant) / k.length;
  };
  if (k.cell_size > 0)
    check_cell_size_against_mean_free_path(
        k.cell_size, knudsen(k.density_max, k.temperature_min, k.viscosity_min) * k.length,
        knudsen(k.density_min, k.temperature_max, k.viscosity_max) * k.length, k.cell_size_key, r);
  r.ranges.push_back({"kinetic_knudsen", knudsen(k.density_max, k.temperature_min, k.viscosity_min),
                      knudsen(k.density_min, k.temperature_max, k.viscosity_max)});
  const Real needed = k.wall_speed + C::kVelocityGridThermalSpeeds *
                                         std::sqrt(2 * k.gas_constant * k.wall_temperature);
  r.ranges.push_back(
      {"velocity_extent_over_needed", k.velocity_extent / needed, k.velocity_extent / needed});
  if (k.velocity_extent < needed)
    r.warnings.push_back(
        fmt::format("kinetic gas: velocity grid half-extent {:.4g} m/s below the "
                    "wall speed + {:g} thermal speeds at the hottest wall "
                    "({:.4g} m/s)",
                    k.velocity_extent, C::kVelocityGridThermalSpeeds, needed));
}

}  // namespace

Real mean_free_path(Real density, Real temperature, Real viscosity, Real gas_constant) {
  return viscosity / (density * gas_constant * temperature) *
         std::sqrt(M_PI * gas_constant * temperature / 2);
}

void check_cell_size_against_mean_free_path(Real cell_size, Real lambda_min, Real lambda_max,
                                            const std::string &key, ValidityReport &r) {
  const Real worst = cell_size / (2 * lambda_min), best = cell_size / (2 * lambda_max);
  r.ranges.push_back({"kinetic_upwind_viscosity_ratio", best, worst});
  if (worst > C::kMaxUpwindViscosityRatio)
    r.warnings.push_back(fmt::format(
        "kinetic gas: cell size h = {:.3g} m is {:.3g} times 2 lambda (lambda = {:.3g} m): "
        "first-order upwinding adds a numerical viscosity mu_num / mu = h / (2 lambda) = {:.3g} "
        "(above {:g}); refine {}",
        cell_size, worst, lambda_min, worst, C::kMaxUpwindViscosityRatio,
        key.empty() ? "the mesh" : key));
}

const ValidityRange *ValidityReport::find(const std::string &name) const {
  for (const ValidityRange &range : ranges)
    if (range.name == name) return &range;
  return nullptr;
}

Json ValidityReport::to_json() const {
  Json j;
  j["ranges"] = Json::object();
  for (const ValidityRange &range : ranges) j["ranges"][range.name] = {range.min, range.max};
  j["warnings"] = warnings;
  return j;
}

ValidityReport check_scene_validity(const SceneDescription &s) {
  ValidityReport r;
  check_plate(s, r);
  if (s.gap > 0 && s.length > 0 && s.parallel_plate) check_parallel_plate(s, r);
  if (s.reynolds && s.gap > 0) check_film(s, r);
  if (s.kinetic.present) check_kinetic(s.kinetic, r);
  return r;
}

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
  if (report.has_dynamic && report.tolerance > C::kMaxBisectionTolerance * v_qs)
    r.warnings.push_back(fmt::format(
        "pull_in.dynamic.tolerance {:.3g} V is {:.2g} % of the quasi-static pull-in voltage "
        "({:.4g} V): the dynamic pull-in voltage is known to that only",
        report.tolerance, 100 * report.tolerance / v_qs, v_qs));
  return r;
}

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
  if (creep.has_gap) {
    s.gap = creep.initial_gap;
    s.fringing_factor = creep.gap_law.fringing_factor;
  }
  return check_scene_validity(s);
}

ValidityReport kinetic_scene_validity(const KineticScene &scene, const Communicator &comm) {
  const KineticOperator &op = *scene.op;
  SceneDescription s;
  auto &k = s.kinetic;
  k.present = true;
  Real rho_lo = 1e300, rho_hi = 0, t_lo = 1e300, t_hi = 0;
  for (Index c = 0; c < op.n_owned_cells(); ++c) {
    const MacroState &m = op.macro(c);
    rho_lo = std::min(rho_lo, m.rho);
    rho_hi = std::max(rho_hi, m.rho);
    t_lo = std::min(t_lo, m.T);
    t_hi = std::max(t_hi, m.T);
  }
  k.density_min = comm.min(rho_lo);
  k.density_max = comm.max(rho_hi);
  k.temperature_min = comm.min(t_lo);
  k.temperature_max = comm.max(t_hi);
  k.viscosity_min = op.gas().viscosity(k.temperature_min);
  k.viscosity_max = op.gas().viscosity(k.temperature_max);
  k.gas_constant = op.gas().R;
  k.length = scene.reference_length;
  k.velocity_extent = op.grid().extent.minCoeff();
  // h: the largest over the owned cells of the cell's smallest extent, volume / largest face
  // (a rectangle's shorter side): the resolution across a film or a Couette flow's shear, so
  // a quasi-1D mesh (one wide column) is judged by its rows.
  Real h = 0;
  const Mesh &mesh = scene.distributed ? scene.distributed->local.mesh : *scene.mesh;
  for (Index c = 0; c < mesh.n_owned_cells(); ++c) {
    Real largest_face = 0;
    for (Index f : mesh.cell_faces(c))
      largest_face = std::max(largest_face, mesh.face_area(f).norm());
    if (largest_face > 0) h = std::max(h, mesh.cell_volume(c) / largest_face);
  }
  k.cell_size = comm.max(h);
  k.cell_size_key = "mesh.cells";
  k.wall_temperature = scene.initial.T;  // the grid's thermal speed is the initial state's
  for (const KineticBoundary &b : op.boundaries())
    if (b.kind == KineticBoundaryKind::DiffuseWall || b.kind == KineticBoundaryKind::Pressure) {
      // Both send in a Maxwellian at their temperature (a pressure boundary at rest).
      if (b.kind == KineticBoundaryKind::DiffuseWall)
        k.wall_speed = std::max(k.wall_speed, b.velocity.cwiseAbs().maxCoeff());
      k.wall_temperature = std::max(k.wall_temperature, b.temperature);
    }
  return check_scene_validity(s);
}

void print_validity_warnings(const std::string &program, const ValidityReport &report) {
  for (const std::string &w : report.warnings)
    std::fprintf(stderr, "%s: warning: %s\n", program.c_str(), w.c_str());
}

}  // namespace rfmems

#include "physics/validity/scene_validity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rfmems {

namespace {

using C = ValidityCriteria;

void check_film(const SceneDescription &s, ValidityReport &r) {
  const Real p = s.gas.ambient_pressure;
  const Real g_min = s.min_gap > 0 ? std::min(s.min_gap, s.gap) : s.gap;
  const Real kn_min = s.gas.knudsen(p, s.gap), kn_max = s.gas.knudsen(p, g_min);
  r.ranges.push_back({"film_knudsen", kn_min, kn_max});
  const bool veijola = s.gas.rarefaction == Rarefaction::Veijola;
  if (s.gas.rarefaction == Rarefaction::Table) {
    const Real table_max = s.gas.flow_factor_table->max_knudsen();
    if (kn_max > table_max)
      r.warnings.push_back(fmt::format(
          "Reynolds film: Kn of the local gap reaches {:.3g} (gap {:.3g} um at {:.3g} Pa), beyond "
          "the flow-factor table's largest Kn {:g} ({}): extrapolated by the free-molecular law",
          kn_max, g_min * 1e6, p, table_max, s.gas.flow_factor_table->source()));
  }
  const Real kn_limit = veijola ? C::kVeijolaMaxKnudsen : C::kContinuumMaxKnudsen;
  if (s.gas.rarefaction != Rarefaction::Table && kn_max > kn_limit)
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
                                             "neglects shear creep: 15 % at L/h = 10, 2.5 % at "
                                             "30, docs/creep.md; {})",
                                             slenderness, limit,
                                             s.plate_stretching
                                                 ? "the von Karman plate has no shear creep"
                                                 : "creep.shear_creep: true includes it")
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
  if (k.cell_size > 0) {
    const Real lambda_min = knudsen(k.density_max, k.temperature_min, k.viscosity_min) * k.length;
    check_cell_size_against_mean_free_path(
        k.cell_size, lambda_min,
        knudsen(k.density_min, k.temperature_max, k.viscosity_max) * k.length, k.cell_size_key, r);
    const Real wall_error = k.cell_size / (2 * lambda_min);
    if (k.first_order && wall_error > C::kMaxWallFluxError &&
        wall_error <= C::kMaxUpwindViscosityRatio)
      r.warnings.push_back(fmt::format(
          "kinetic gas: first-order transport: the wall shear and heat flux may be off by up to "
          "h / (2 lambda) = {:.2g} % (upwinding's numerical viscosity against the physical; "
          "above {:g} %); set solver.transport: second_order or refine {}",
          100 * wall_error, 100 * C::kMaxWallFluxError,
          k.cell_size_key.empty() ? "the mesh" : k.cell_size_key));
  }
  r.ranges.push_back({"kinetic_knudsen", knudsen(k.density_max, k.temperature_min, k.viscosity_min),
                      knudsen(k.density_min, k.temperature_max, k.viscosity_max)});
  if (!(k.velocity_extent > 0)) return;  // Gauss-Hermite in every direction: no truncation
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

void print_validity_warnings(const std::string &program, const ValidityReport &report) {
  for (const std::string &w : report.warnings)
    std::fprintf(stderr, "%s: warning: %s\n", program.c_str(), w.c_str());
}

}  // namespace rfmems

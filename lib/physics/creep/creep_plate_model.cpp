// The plate creep case's run model and result fields (see the header).
#include "physics/creep/creep_plate_model.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

#include "physics/creep/plate_creep_system.hpp"

namespace rfmems {

namespace {

// Von Mises stress of an in-plane stress (sigma_xx, sigma_yy, sigma_xy), sigma_zz = 0.
Real von_mises(const Vec3& s) {
  return std::sqrt(s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3 * s[2] * s[2]);
}

PlateCreepSystem& as_plate(CreepSystem& system) { return dynamic_cast<PlateCreepSystem&>(system); }

// A membrane force to report: an in-plane residual stress, whose creep relaxation the system
// models, or the stretching von Karman plate (PlateCreepSystem::has_membrane_force()).
bool has_membrane_force(const CreepCase& c) {
  return c.plate->von_karman ||
         c.plate->section.residual_stress.topLeftCorner<2, 2>().cwiseAbs().maxCoeff() > 0;
}

// The gap point where the plate is lowest: the smallest gap, sampled where the hold load and
// the pull-in sample it (ParallelPlateActuation::elements(): Simpson points on quadrilaterals).
const GapPoint& lowest_point(const CreepCase& c, std::span<const Real> state) {
  return *lowest_gap_point(c.gap_elements, state).point;
}

}  // namespace

CreepRunModel make_plate_creep_model(const CreepCase& c) {
  CreepRunModel m;
  m.make_system = [&c]() -> std::unique_ptr<CreepSystem> {
    if (c.plate->von_karman)
      return std::make_unique<PlateCreepSystem>(*c.plate->von_karman, c.law, c.thickness_intervals,
                                                c.hold);
    return std::make_unique<PlateCreepSystem>(*c.plate->op, c.law, c.thickness_intervals,
                                              c.shear_creep, c.hold);
  };
  if (c.has_gap) {
    m.min_gap = [&c](std::span<const Real> state) {
      return c.initial_gap + gap_displacement(lowest_point(c, state), state);
    };
    m.min_gap_rate = [&c](std::span<const Real> state, std::span<const Real> state_dot) {
      return weighted_sum(lowest_point(c, state).terms, state_dot);  // u_q is affine in y
    };
  }
  for (const Probe& p : c.probes) m.series_columns.push_back(p.name);
  if (c.has_gap) m.series_columns.push_back("min_gap");
  m.series_columns.push_back("max_surface_von_mises");
  m.series_columns.push_back("max_creep_strain");
  // The membrane stress N_xx / h (relaxing, or stretching too), the mean over the cells.
  if (has_membrane_force(c)) m.series_columns.push_back("mean_membrane_stress_xx");

  m.sample = [&c, min_gap = m.min_gap](CreepSystem& system, Real t, std::span<const Real> state) {
    PlateCreepSystem& plate = as_plate(system);
    std::vector<double> row;
    const std::span<const Real> y = state.first(plate.structural_size());
    for (const Vec3& v : c.plate->probe_values(c.probes, t, y)) row.push_back(v[0]);
    if (min_gap) row.push_back(min_gap(state));
    Real vm = 0;
    for (Index i : {Index{0}, plate.n_points() - 1})
      for (const Vec3& s : plate.fibre_stress(t, state, i)) vm = std::max(vm, von_mises(s));
    row.push_back(vm);
    Real eps = 0;
    for (Index cell = 0; cell < plate.n_cells(); ++cell)
      for (Index i = 0; i < plate.n_points(); ++i)
        eps = std::max(eps, state[plate.creep_index(cell, i, PlateCreepSystem::kEff)]);
    row.push_back(eps);
    if (plate.has_membrane_force()) {
      Real n = 0;
      for (const Vec3& v : plate.membrane_forces(state, t)) n += v[0];
      row.push_back(n / (plate.n_cells() * plate.plate().section().thickness));
    }
    return row;
  };

  m.output_fields = [](CreepSystem& system, Real t, std::span<const Real> state) {
    PlateCreepSystem& plate = as_plate(system);
    const Index nc = plate.n_cells();
    std::map<std::string, std::vector<double>> f;
    f["structure"].assign(state.begin(), state.begin() + plate.structural_size());
    auto& mp = f["plastic_moment"];
    for (const Vec3& m : plate.plastic_moments(state)) mp.insert(mp.end(), {m[0], m[1], m[2]});
    const std::pair<const char*, Index> surfaces[] = {{"von_mises_bottom", 0},
                                                      {"von_mises_top", plate.n_points() - 1}};
    for (const auto& [name, i] : surfaces) {
      auto& vm = f[name];
      for (const Vec3& s : plate.fibre_stress(t, state, i)) vm.push_back(von_mises(s));
    }
    if (plate.has_membrane_force()) {
      // The von Karman plate's fields already hold its stretching part A : eps_m as
      // membrane_force: the whole force under its own name.
      auto& n = f[plate.geometric_nonlinearity() ? "total_membrane_force" : "membrane_force"];
      for (const Vec3& v : plate.membrane_forces(state, t)) n.insert(n.end(), {v[0], v[1], v[2]});
    }
    auto& eps = f["creep_strain"];
    eps.assign(nc, 0.0);
    for (Index cell = 0; cell < nc; ++cell)
      for (Index i = 0; i < plate.n_points(); ++i)
        eps[cell] = std::max(eps[cell], state[plate.creep_index(cell, i, PlateCreepSystem::kEff)]);
    return f;
  };
  return m;
}

void write_plate_creep_output(const CreepCase& c, ResultWriter& writer, int index,
                              const CreepOutput& out) {
  c.plate->write_fields(writer, index, out.time, out.fields.at("structure"), {});
  writer.write_cell_field_at(index, out.time, "plastic_moment", out.fields.at("plastic_moment"), 3,
                             {"Mp_xx", "Mp_yy", "Mp_xy"});
  for (const char* name : {"membrane_force", "total_membrane_force"})
    if (out.fields.count(name))
      writer.write_cell_field_at(index, out.time, name, out.fields.at(name), 3,
                                 {"N_xx", "N_yy", "N_xy"});
  for (const char* name : {"von_mises_top", "von_mises_bottom", "creep_strain"})
    writer.write_cell_field_at(index, out.time, name, out.fields.at(name), 1);
}

void check_hold_equilibrium(const CaseNode& root, const CreepCase& creep_case,
                            const CreepRunModel& model) {
  if (!creep_case.hold) return;
  try {
    std::vector<Real> y, yp;
    model.make_system()->initial_state(0, y, yp);
  } catch (const std::exception&) {
    root.child("actuation")
        .fail("voltage",
              "no elastic equilibrium at this hold voltage (above the pull-in voltage?)");
  }
}

}  // namespace rfmems

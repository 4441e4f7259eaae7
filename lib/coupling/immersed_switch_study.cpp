#include "coupling/immersed_switch_study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.hpp"
#include "coupling/immersed_esbgk_gas.hpp"
#include "coupling/immersed_reynolds_film.hpp"
#include "coupling/pull_in_results.hpp"
#include "coupling/scene_validity.hpp"
#include "io/probes.hpp"
#include "physics/gas/kinetic/kinetic_case.hpp"

namespace rfmems {

namespace {

std::pair<Real, Real> read_pair(const CaseNode& node, const std::string& key, Dimension d) {
  const std::vector<Real> v = node.get_quantities(key, d);
  node.require(v.size() == 2 && v[0] < v[1], key, "expected [a, b] with a < b");
  return {v[0], v[1]};
}

}  // namespace

std::unique_ptr<ImmersedGasModel> make_case_gas(const CaseNode& root, const ImmersedSwitch& scene,
                                                const ImmersedSwitchGeometry& geometry,
                                                Real* mean_free_path) {
  const CaseNode gas = root.child_or_empty("gas");
  const std::string model = gas.get_choice("model", {"none", "reynolds", "esbgk"}, "none");
  // Keys are read (and checked) even for none, so a case toggled by --set stays valid.
  GasProperties g;
  g.ambient_pressure = gas.get_quantity("pressure", Dimension::Pressure, 1.36e4, Range::positive());
  const Real temperature =
      gas.get_quantity("temperature", Dimension::Temperature, 300.0, Range::positive());
  const Real mu0 = gas.get_quantity("viscosity", Dimension::Viscosity, 1.712e-5, Range::positive());
  const Real omega = gas.get_real("omega", 0.74, Range::closed(0.5, 1.0));
  g.viscosity = mu0 * std::pow(temperature / 273.15, omega);
  // Mean free path of the thesis's eq. (5.30) family: lambda = mu / p sqrt(pi R T / 2), air.
  const Real lambda = g.viscosity / g.ambient_pressure * std::sqrt(M_PI * 287.0 * temperature / 2);
  g.mean_free_path =
      gas.get_quantity("mean_free_path", Dimension::Length, lambda, Range::positive());
  g.reference_pressure = g.ambient_pressure;
  g.rarefaction = gas.get_choice("rarefaction", {"veijola", "none"}, "veijola") == "veijola"
                      ? Rarefaction::Veijola
                      : Rarefaction::None;
  if (mean_free_path) *mean_free_path = g.mean_free_path;
  // esbgk: the kinetic gas on the background (immersed_esbgk_gas.hpp).
  ImmersedEsbgkSettings e;
  e.gas.R = 287.05;
  e.gas.mu_ref = mu0;
  e.gas.T_ref = 273.15;
  e.gas.omega = omega;
  e.gas.model = gas.get_choice("collision", {"esbgk", "bgk"}, "esbgk") == "esbgk"
                    ? CollisionModel::Esbgk
                    : CollisionModel::Bgk;
  e.pressure = g.ambient_pressure;
  e.temperature = temperature;
  e.velocities = static_cast<int>(gas.get_int("velocities", 10, Range::closed(4, 40)));
  e.velocity_extent = gas.get_real("velocity_extent", 3.5, Range::closed(2.0, 8.0));
  // Defaults from BENCHMARKS.md section 22: a 1e-5 step residual keeps the gas force within
  // 0.4 % of a 1e-9 solve; the point-coupled sweep and the predictor cut the sweeps 4x.
  e.options.step_tolerance = gas.get_real("step_tolerance", 1e-5, Range::closed(1e-14, 1e-1));
  const std::string smoother = gas.get_choice("smoother", {"point", "downwind", "both"}, "point");
  e.options.smoother = smoother == "point"      ? GasSmoother::PointCoupled
                       : smoother == "downwind" ? GasSmoother::Downwind
                                                : GasSmoother::Both;
  e.options.predictor = gas.get_bool("predictor", true);
  e.options.max_step_sweeps =
      static_cast<int>(gas.get_int("max_step_sweeps", 2000, Range::closed(1, 100000)));
  e.options.transport = read_transport_scheme(gas);
  if (model == "none") return nullptr;
  if (model == "esbgk")
    return std::make_unique<ImmersedEsbgkGas>(scene.background(), e, geometry.background_lower.y());
  Real tip = -1e300;
  for (const Vec3& x : scene.rest_surface().vertices()) tip = std::max(tip, x.x());
  return std::make_unique<ImmersedReynoldsFilm>(g, scene.facing_segments(),
                                                geometry.background_lower.y(),
                                                geometry.background_lower.x(), tip);
}

ImmersedSwitchCase read_immersed_switch_case(const CaseNode& root, const std::string& case_dir) {
  ImmersedSwitchCase c;
  c.beam = std::make_unique<ElasticityScene>(
      build_elasticity_scene(root, case_dir, AnalysisType::Transient));
  const Mesh& mesh = *c.beam->mesh;
  root.child("model").require(mesh.dim() == 2, "structure",
                              "the immersed switch needs a plane beam");
  const CaseNode im = root.child("immersed");
  const CaseNode bg = im.child("background");
  ImmersedSwitchGeometry& g = c.geometry;
  g.background_lower = bg.get_vec3_quantity("lower", Dimension::Length);
  g.background_upper = bg.get_vec3_quantity("upper", Dimension::Length);
  bg.require(g.background_upper.x() > g.background_lower.x() &&
                 g.background_upper.y() > g.background_lower.y(),
             "upper", "must lie above and right of lower");
  const std::vector<Real> cells = bg.get_reals("cells");
  bg.require(cells.size() == 2 && cells[0] >= 4 && cells[1] >= 4 && cells[0] <= 4000 &&
                 cells[1] <= 4000 && cells[0] == std::floor(cells[0]) &&
                 cells[1] == std::floor(cells[1]),
             "cells", "expected [nx, ny], integers in [4, 4000]");
  g.background_cells[0] = static_cast<int>(cells[0]);
  g.background_cells[1] = static_cast<int>(cells[1]);
  std::tie(g.electrode_begin, g.electrode_end) =
      read_pair(im.child("electrode"), "x", Dimension::Length);
  g.anchor_patch = im.get_string("anchor_patch", "left");
  im.require(mesh.find_patch(g.anchor_patch) >= 0, "anchor_patch",
             "the beam mesh has no such patch");
  g.facing_patch = im.get_string("facing_patch", "bottom");
  im.require(mesh.find_patch(g.facing_patch) >= 0, "facing_patch",
             "the beam mesh has no such patch");
  g.anchor_extension =
      im.get_quantity("anchor_extension", Dimension::Length, 0.0, Range::non_negative());
  for (const Vec3& x : mesh.nodes())
    if (!(x.x() >= g.background_lower.x() - 1e-9 && x.x() <= g.background_upper.x() &&
          x.y() > g.background_lower.y() && x.y() < g.background_upper.y()))
      bg.fail("lower", fmt::format("the beam (node at [{:g}, {:g}] m) is not inside the background",
                                   x.x(), x.y()));
  const CasePointFinder finder(mesh);
  // The reported deflection is u_y at the control point itself (the tip), from its cell's
  // reconstruction, not at the cell's centroid half a cell short of it.
  const auto [control_point, control_cell] = finder.find(im, "control", "the control point");
  c.scene = std::make_unique<ImmersedSwitch>(
      *c.beam->op, g, c.beam->op->displacement_functional(control_cell, control_point, 1));
  if (im.get_bool("electrostatics_distributed", false))
    c.scene->distribute_electrostatics(Communicator::world());

  const CaseNode pi = root.child("pull_in");
  c.mode = pi.get_choice("mode", {"dynamic", "transient", "static", "quasi_static"});
  const Real gap = c.scene->rest_gap();
  c.run.contact_gap = pi.get_quantity("contact_gap", Dimension::Length,
                                      std::min(1.5 * c.scene->background_cell_height(), 0.5 * gap),
                                      Range::open(0.0, gap));
  const CaseNode solver = root.child_or_empty("solver");
  c.run.ida.rtol = solver.get_real("rtol", 1e-4, Range::open(0.0, 1.0));
  c.run.ida.atol = solver.get_quantity("atol", Dimension::Length, 1e-5 * gap, Range::positive());
  c.run.ida.max_order = static_cast<int>(solver.get_int("max_order", 2, Range::closed(1, 5)));
  // Fixed steps (the coupling schemes' splitting error at a given step): cut to 1e-4 of it
  // only after a failed Newton solve (the 1/g^2 touch-down), as bench_pullin_work_error does.
  c.run.ida.fixed_step = solver.get_quantity("fixed_step", Dimension::Time, 0.0, Range::non_negative());
  c.run.ida.fixed_step_min = 1e-4 * c.run.ida.fixed_step;
  const CaseNode coupling = root.child_or_empty("coupling");
  const std::string scheme =
      coupling.get_choice("scheme", {"staggered", "implicit", "strong"}, "staggered");
  c.run.coupling = scheme == "implicit" ? ImmersedCoupling::Implicit
                   : scheme == "strong" ? ImmersedCoupling::Strong
                                        : ImmersedCoupling::Staggered;
  c.run.strong_tolerance = coupling.get_real("tolerance", 1e-6, Range::open(0.0, 1.0));
  c.run.strong_max_iterations =
      static_cast<int>(coupling.get_int("max_iterations", 20, Range::closed(1, 1000)));
  c.run.gas_every = static_cast<int>(coupling.get_int("gas_every", 1, Range::closed(1, 1000)));
  c.run.strong_gas = coupling.get_bool("strong_gas", false);
  coupling.require(!c.run.strong_gas || c.run.coupling == ImmersedCoupling::Strong, "strong_gas",
                   "strong_gas: true needs scheme: strong (the gas inside its iterations)");
  coupling.require(!c.run.strong_gas || c.run.gas_every == 1, "strong_gas",
                   "strong_gas: true advances the gas over every step: gas_every must be 1");
  // Every block is checked whatever the mode (a case toggled by --set stays valid); the
  // active mode's block and required keys must be there.
  auto block = [&](const std::string& name) {
    return c.mode == name ? pi.child(name) : pi.child_or_empty(name);
  };
  const CaseNode d = block("dynamic");
  if (c.mode == "dynamic" || d.has("bracket")) {
    std::tie(c.bracket_low, c.bracket_high) = read_pair(d, "bracket", Dimension::Voltage);
    d.require(c.bracket_low > 0, "bracket", "voltages must be > 0");
  }
  c.tolerance = d.get_quantity("tolerance", Dimension::Voltage, 1.0, Range::positive());
  // The bisection's early ends, as rfmems-pullin's other scenes read them (pull_in_study.cpp):
  // settled at rest (0: off) and past the unstable equilibrium (the quasi-static curve traced
  // before the bisection gives the fold and the unstable branch).
  c.run.settle_tolerance =
      d.get_real("settle_tolerance", kSettleTolerance, Range{0.0, 1.0, false, true});
  c.run.past_fold_margin = d.get_real("past_fold_margin", kPastFoldMargin, Range::closed(0.0, 1.0));
  const Real dynamic_end = d.get_quantity("end_time", Dimension::Time,
                                          4 * c.scene->first_bending_period(), Range::positive());
  const CaseNode tr = block("transient");
  const bool transient = c.mode == "transient";
  const Real transient_voltage =
      transient ? tr.get_quantity("voltage", Dimension::Voltage, Range::positive())
                : tr.get_quantity("voltage", Dimension::Voltage, 1.0, Range::positive());
  const Real transient_end =
      transient ? tr.get_quantity("end_time", Dimension::Time, Range::positive())
                : tr.get_quantity("end_time", Dimension::Time, 1.0, Range::positive());
  const Real transient_output =
      tr.get_quantity("output_interval", Dimension::Time, transient_end / 400, Range::positive());
  const CaseNode st = block("static");
  const Real static_voltage =
      c.mode == "static" ? st.get_quantity("voltage", Dimension::Voltage, Range::positive())
                         : st.get_quantity("voltage", Dimension::Voltage, 1.0, Range::positive());
  const CaseNode q = block("quasi_static");
  c.quasi_static.n_points = static_cast<int>(q.get_int("points", 16, Range::closed(4, 1000)));
  c.quasi_static.max_fraction = q.get_real("max_fraction", 0.6, Range::open(0.0, 1.0));
  c.quasi_static.voltage_tolerance =
      q.get_quantity("voltage_tolerance", Dimension::Voltage, 0.05, Range::positive());
  if (c.mode == "dynamic") {
    c.run.end_time = dynamic_end;
  } else if (transient) {
    c.voltage = transient_voltage;
    c.run.end_time = transient_end;
    c.run.output_interval = transient_output;
    c.run.stop_at_turning = false;
  } else if (c.mode == "static") {
    c.voltage = static_voltage;
  }
  c.gas = make_case_gas(root, *c.scene, g, &c.mean_free_path);
  // The pull-in time's check costs one more coupled run at the tighter tolerance: with the
  // kinetic gas 10-40 min (BENCHMARKS 48 and 50), so off unless the case asks.
  const bool kinetic = c.gas && c.gas->name() == "esbgk";
  c.time_check = d.get_real("time_check", kinetic ? 0.0 : 0.1, Range{0.0, 1.0, false, true});
  return c;
}

namespace {

Json times_json(const ImmersedPhysicsTimes& t) {
  return {{"move_s", t.move},
          {"marking_s", t.marking},
          {"interpolation_s", t.interpolation},
          {"electrostatics_s", t.electrostatics},
          {"transfer_s", t.transfer},
          {"gas_s", t.gas},
          {"structure_s", t.structure},
          {"load_evaluations", t.load_evaluations},
          {"electrostatic_analyses", t.electrostatic_analyses},
          {"electrostatic_krylov_iterations", t.electrostatic_krylov_iterations},
          {"coupling_iterations", t.coupling_iterations},
          {"max_coupling_iterations", t.max_coupling_iterations},
          {"unconverged_coupling_steps", t.unconverged_steps},
          {"max_coupling_residual", t.max_coupling_residual},
          {"structure_steps", t.structure_steps},
          {"gas_steps", t.gas_steps}};
}

void write_displacement(ResultWriter& writer, const ElasticityScene& beam,
                        std::span<const Real> u) {
  std::vector<double> d;
  for (Index c = 0; c < beam.mesh->n_cells(); ++c) {
    d.push_back(u[2 * c]);
    d.push_back(u[2 * c + 1]);
    d.push_back(0.0);
  }
  writer.write_cell_field_at(0, 0.0, "displacement", d, 3);
}

}  // namespace

Json run_immersed_switch_study(ImmersedSwitchCase& c, const CaseNode& root, ResultWriter& writer) {
  ImmersedSwitch& s = *c.scene;
  const auto wall0 = std::chrono::steady_clock::now();
  auto wall = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  };
  Json j;
  j["mode"] = c.mode;
  j["gap"] = s.rest_gap();
  j["background_cells"] = {c.geometry.background_cells[0], c.geometry.background_cells[1]};
  j["beam_cells"] = c.beam->mesh->n_cells();
  j["surface_segments"] = s.rest_surface().n_segments();
  j["first_bending_period"] = s.first_bending_period();
  j["gas"] = c.gas ? c.gas->name() : "none";
  j["coupling"] = c.run.coupling == ImmersedCoupling::Implicit ? "implicit"
                  : c.run.coupling == ImmersedCoupling::Strong ? "strong"
                                                               : "staggered";
  j["gas_every"] = c.run.gas_every;
  j["strong_gas"] = c.run.strong_gas;
  j["contact_gap"] = c.run.contact_gap;
  const std::size_t n = c.beam->op->size();
  if (c.mode == "static") {
    const ImmersedStatic st = s.solve_static(c.voltage);
    j["static"] = {{"voltage", c.voltage},
                   {"control", st.control},
                   {"force_y", st.force_y},
                   {"iterations", st.iterations}};
    write_displacement(writer, *c.beam, st.u);
  } else if (c.mode == "quasi_static") {
    const QuasiStaticPullIn qs = s.trace_quasi_static(c.quasi_static);
    write_pull_in_curve(writer, qs);
    j["quasi_static"] = {{"pull_in_voltage", qs.pull_in_voltage},
                         {"pull_in_displacement", qs.pull_in_displacement},
                         {"solves", qs.solves}};
    write_displacement(writer, *c.beam, qs.fold_state);
  } else if (c.mode == "transient") {
    const DynamicRun run = s.run(c.voltage, c.run, c.gas.get());
    write_dynamic_history(writer, "transient", run);
    j["transient"] = {{"voltage", c.voltage},
                      {"pulled_in", run.pulled_in},
                      {"pull_in_time", run.pull_in_time},
                      {"max_deflection", -run.extreme_control},
                      {"steps", run.stats.steps},
                      {"final_time", run.final_time}};
    // A history that ends in contact has no small-signal response to fit: the damping figures
    // are written only for runs that stay up.
    if (!run.pulled_in) j["transient"].update(free_response_json(free_response(run.history)));
    write_displacement(writer, *c.beam, std::span<const Real>(run.final_state.y).subspan(0, n));
  } else {
    // The quasi-static curve arms the settle and past-fold rules (60 electrostatic solves on
    // the case: < 1 s, against 10-1000 s per coupled run).
    const QuasiStaticPullIn qs = s.trace_quasi_static(c.quasi_static);
    c.run.fold = FoldBranch::of(qs);
    DynamicRun last;
    Real last_voltage = 0, max_kn = 0;
    auto runner = [&](const ImmersedRunOptions& options) {
      return [&, options](Real v) {
        std::unique_ptr<ImmersedGasModel> gas = make_case_gas(root, s, c.geometry);
        DynamicRun r = s.run(v, options, gas.get());
        if (gas) max_kn = std::max(max_kn, gas->max_knudsen());
        // The history written: the lowest voltage that pulled in, to contact if it got there.
        if (r.pulled_in && (last_voltage == 0 || v < last_voltage ||
                            (v == last_voltage && r.pull_in_time > 0))) {
          last = r;
          last_voltage = v;
        }
        return r;
      };
    };
    ImmersedRunOptions to_contact = c.run;
    to_contact.stop_past_fold = false;  // the upper end's touch-down time
    const DynamicPullIn pi = find_dynamic_pull_in(runner(c.run), c.bracket_low, c.bracket_high,
                                                  c.tolerance, c.run.end_time,
                                                  runner(to_contact));
    write_dynamic_history(writer, "pull_in", last);
    // The pull-in time's integration error (pull_in_study.cpp's check): the upper end again,
    // to contact, at time_check x the tolerances, with a fresh gas.
    Json check;
    if (c.time_check > 0 && pi.pull_in_time > 0) {
      ImmersedRunOptions tight = to_contact;
      tight.ida = with_tolerances_scaled(to_contact.ida, c.time_check);
      tight.output_interval = 0;
      std::unique_ptr<ImmersedGasModel> gas = make_case_gas(root, s, c.geometry);
      check = pull_in_time_check_json(c.time_check, pi.pull_in_time,
                                      s.run(pi.voltage, tight, gas.get()));
    }
    j["dynamic"] = {{"pull_in_voltage", pi.voltage},
                    {"not_pulling_in", pi.lower},
                    {"pull_in_time", pi.pull_in_time},
                    {"runs", pi.runs},
                    {"steps", pi.steps},
                    {"settled_runs", pi.settled_runs},
                    {"past_fold_runs", pi.past_fold_runs},
                    {"quasi_static_pull_in_voltage", qs.pull_in_voltage},
                    {"tolerance", c.tolerance}};
    if (!check.is_null()) j["dynamic"]["pull_in_time_check"] = check;
    write_displacement(writer, *c.beam, std::span<const Real>(last.final_state.y).subspan(0, n));
    if (c.gas) j["gas_max_knudsen"] = max_kn;
  }
  if (c.gas && !j.contains("gas_max_knudsen")) j["gas_max_knudsen"] = c.gas->max_knudsen();
  // Validity (issue 8's scene report): where the chosen models leave their range.
  Json warnings = Json::array();
  const Real cell = s.background_cell_height();
  if (c.run.contact_gap < cell)
    warnings.push_back(
        fmt::format("contact gap {:.3g} m is below one background cell ({:.3g} m): "
                    "the IB layer fills the gap before touch-down",
                    c.run.contact_gap, cell));
  // The film's limits are the Reynolds film's only; the kinetic gas holds at every Kn.
  const std::string gas_model = c.gas ? c.gas->name() : "none";
  if (gas_model == "reynolds" && j["gas_max_knudsen"].get<double>() > 1.0)
    warnings.push_back(
        fmt::format("Reynolds film at Kn up to {:.3g} (> 1): Veijola's viscosity "
                    "fit holds, the film's lubrication assumptions weaken",
                    j["gas_max_knudsen"].get<double>()));
  if (gas_model == "reynolds" && (c.mode == "dynamic" || c.mode == "transient") &&
      c.run.contact_gap < 0.5 * s.rest_gap())
    warnings.push_back(
        "Reynolds film followed to a gap below half the rest gap (large "
        "displacement: the 1D film takes h from the deformed beam, no edge "
        "correction at the tip)");
  // ESBGK on the background: its cell size against the mean free path (scene_validity.hpp).
  if (gas_model == "esbgk") {
    const ImmersedSwitchGeometry& g = c.geometry;
    const Real hx = (g.background_upper.x() - g.background_lower.x()) / g.background_cells[0];
    ValidityReport v;
    check_cell_size_against_mean_free_path(std::min(hx, cell), c.mean_free_path, c.mean_free_path,
                                           "immersed.background.cells", v);
    for (const std::string& w : v.warnings) warnings.push_back(w);
    j["kinetic_upwind_viscosity_ratio"] = v.ranges.front().max;
  }
  j["validity_warnings"] = warnings;
  j["cpu"] = times_json(s.times());
  j["study_wall_s"] = wall();
  return j;
}

}  // namespace rfmems

#include "physics/gas/kinetic/kinetic_results.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "parallel/communication_counters.hpp"
#include "physics/gas/kinetic/kinetic_reference.hpp"

namespace rfmems {

void write_kinetic_results(ResultWriter* writer, const KineticScene& scene,
                           const KineticSolveResult& result) {
  const KineticOperator& op = *scene.op;
  const Index n = op.n_owned_cells();
  std::vector<double> rho(n), T(n), p(n), u(3 * n), q(3 * n), tau(6 * n);
  for (Index c = 0; c < n; ++c) {
    const MacroState& m = op.macro(c);
    rho[c] = m.rho;
    T[c] = m.T;
    p[c] = m.p;
    for (int d = 0; d < 3; ++d) {
      u[3 * c + d] = m.u[d];
      q[3 * c + d] = m.heat_flux[d];
    }
    const Mat3& s = m.stress;
    const double voigt[6] = {s(0, 0), s(1, 1), s(2, 2), s(1, 2), s(0, 2), s(0, 1)};
    for (int i = 0; i < 6; ++i) tau[6 * c + i] = voigt[i];
  }
  auto write = [&](const char* name, const std::vector<double>& values, int block,
                   std::vector<std::string> components = {}) {
    const std::vector<double> all = scene.gather(values, block);
    if (writer) writer->write_cell_field_at(0, 0.0, name, all, block, std::move(components));
  };
  write("density", rho, 1);
  write("velocity", u, 3, {"x", "y", "z"});
  write("temperature", T, 1);
  write("pressure", p, 1);
  write("heat_flux", q, 3, {"x", "y", "z"});
  write("stress", tau, 6, {"xx", "yy", "zz", "yz", "xz", "xy"});
  if (!writer) return;
  std::vector<double> iterations;
  std::vector<std::vector<double>> ratios;
  for (std::size_t i = 0; i < result.history.size(); ++i) {
    iterations.push_back(static_cast<double>(i + 1));
    ratios.push_back({result.history[i]});
  }
  writer->write_time_series("solver", "residual", iterations, ratios, {"ratio"}, "iteration");
}

Json kinetic_summary(const KineticScene& scene, const KineticSolveResult& result,
                     std::span<const Real> f) {
  const KineticOperator& op = *scene.op;
  const FaceGraph& g = *scene.graph;
  Json summary;
  summary["collision"] = collision_model_name(op.gas().model);
  summary["mesh"] = {{"dim", g.dim}, {"cells", scene.mesh->n_cells()}};
  if (scene.distributed) {
    summary["partition"] = {{"ranks", op.communicator().size()},
                            {"edge_cut", scene.distributed->partition.edge_cut},
                            {"imbalance", scene.distributed->partition.imbalance}};
    // What the root sent during the whole run (parallel/communication_counters.hpp).
    const CommunicationCounters sent = communication_counters();
    summary["communication_rank0"] = {{"messages", sent.messages},
                                      {"bytes", sent.bytes},
                                      {"ghost_exchanges", sent.exchanges},
                                      {"reductions", sent.reductions}};
  }
  const VelocityGrid& grid = op.grid();
  nlohmann::json types = nlohmann::json::array(), extents = nlohmann::json::array();
  for (int d = 0; d < 3; ++d) {
    types.push_back(velocity_rule_name(grid.rule[d]));
    // null: a Gauss-Hermite rule (the whole line).
    extents.push_back(std::isfinite(grid.extent[d]) ? nlohmann::json(grid.extent[d])
                                                    : nlohmann::json(nullptr));
  }
  summary["velocity_grid"] = {{"points", grid.n},
                              {"ordinates", grid.size()},
                              {"types", types},
                              {"extents_m_per_s", extents}};
  summary["initial"] = {{"density", scene.initial.rho},
                        {"temperature", scene.initial.T},
                        {"knudsen", scene.knudsen},
                        {"reference_length", scene.reference_length}};
  const KineticReference ref = kinetic_reference(scene);
  Json reference = {{"pressure", ref.pressure},
                    {"temperature", ref.temperature},
                    {"density", ref.density},
                    {"viscosity", ref.viscosity},
                    {"thermal_speed", ref.thermal_speed},
                    {"reference_length", ref.reference_length},
                    {"rarefaction_parameter", ref.rarefaction_parameter},
                    {"knudsen", ref.knudsen},
                    {"knudsen_definition", kKnudsenDefinition}};
  if (ref.wall_speed > 0) reference["wall_speed"] = ref.wall_speed;
  if (ref.temperature_difference > 0)
    reference["temperature_difference"] = ref.temperature_difference;
  if (ref.body_force > 0) {
    reference["body_force"] = ref.body_force;
    reference["pressure_gradient"] = ref.pressure_gradient;
  }
  summary["reference"] = reference;
  summary["solver"] = {{"type", scene.solver.type},
                       {"method", result.method},
                       {"iteration", result.method == "comet" ? "cycle" : "sweep"},
                       {"converged", result.converged},
                       {"iterations", result.iterations},
                       {"tolerance", scene.solver.tolerance},
                       {"residual_initial", result.initial_residual},
                       {"residual_final", result.final_residual},
                       {"residual_ratio", result.residual_ratio},
                       {"seconds", result.seconds}};
  if (!result.handover.empty()) summary["solver"]["handover"] = result.handover;
  Json walls = Json::object();
  for (const std::string& name : scene.force_patches) {
    const int p = g.find_patch(name);  // -1 on a rank without it: contributes nothing
    const Vec3 F = op.wall_force(p, f);
    const Real Q = op.wall_heat_flow(p, f);
    const KineticOperator::PatchArea A = op.patch_area(p);
    const WallAnswer answer = wall_answer(scene, ref, name, F, Q, A.area, A.vector);
    Json wall = {{"force", {F.x(), F.y(), F.z()}},
                 {"heat_flow", Q},
                 {"area", answer.area},
                 {"heat_flux", answer.heat_flux}};
    if (answer.shear_stress) wall["shear_stress"] = *answer.shear_stress;
    if (answer.normalised_shear) wall["normalised_shear"] = *answer.normalised_shear;
    if (answer.normalised_heat_flux) wall["normalised_heat_flux"] = *answer.normalised_heat_flux;
    walls[name] = wall;
  }
  summary["walls"] = walls;
  Json boundaries = Json::object();
  for (const Patch& patch : scene.mesh->patches())
    boundaries[patch.name] = {{"mass_flow", op.boundary_mass_flow(g.find_patch(patch.name), f)}};
  summary["boundaries"] = boundaries;
  // A body-force-driven channel: G through the periodic patch the force drives the gas out of.
  for (const auto& [name, bc] : scene.conditions) {
    if (bc.kind != KineticBoundaryKind::Periodic || !(ref.body_force > 0)) continue;
    const int p = g.find_patch(name);
    const KineticOperator::PatchArea A = op.patch_area(p);
    if (!(A.vector.dot(scene.body_force) > 0)) continue;
    const Real m = op.boundary_mass_flow(p, f);
    summary["flow_rate"] = {{"patch", name},
                            {"mass_flow", m},
                            {"normalised_flow_rate", normalised_flow_rate(ref, m, A.area)}};
  }
  summary["total_mass"] = op.total_mass(f);
  return summary;
}

}  // namespace rfmems

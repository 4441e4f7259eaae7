// rfmems-gas: steady rarefied gas flow by the discrete-velocity BGK / ESBGK model
// (lib/physics/gas/kinetic): reads a case file (mesh, gas, initial state, velocity grid,
// boundaries, solver; physics/gas/kinetic/kinetic_case.hpp), iterates to the steady state with
// the solver named in `solver.type` (sequential or comet), writes the cell fields
// and the residual history to HDF5 + XDMF, and reports iterations, residuals and the forces and
// heat flows on the walls.
//
// Sample runs:
//   rfmems-gas cases/gas_couette/case.yaml                  # -> out/gas_couette.h5, .xdmf
//   rfmems-gas cases/gas_heat_transfer/case.yaml --json --quiet
//   rfmems-gas cases/gas_cavity/case.yaml --set initial.knudsen=1 -o out/cavity_kn1.h5
//   mpirun -np 2 rfmems-gas cases/gas_heat_transfer/case.yaml --set solver.type=comet
//       # METIS parts, one ghost layer; COMET's coarse levels agglomerated per part
//
// Fields (step 0): density (kg/m^3), velocity (m/s), temperature (K), pressure (Pa),
// heat_flux (W/m^2), stress (viscous, Pa, Voigt xx yy zz yz xz xy). /solver/residual: the
// ratio ||r|| / ||r_0|| per iteration. Exit codes as rfmems-solid: 0 success; 2 bad input (one
// line on stderr, no result file); 1 other failures (including no convergence).
#include <fmt/format.h>

#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "coupling/scene_validity.hpp"
#include "io/atomic_file.hpp"
#include "io/case_file.hpp"
#include "io/driver_main.hpp"
#include "io/input_solve.hpp"
#include "io/interrupt_cleanup.hpp"
#include "io/json_summary.hpp"
#include "io/progress.hpp"
#include "io/result_writer.hpp"
#include "parallel/communication_counters.hpp"
#include "parallel/communicator.hpp"
#include "physics/gas/kinetic/kinetic_case.hpp"
#include "solvers/convergence_forecast.hpp"

namespace {

using namespace rfmems;

// The macroscopic fields of the owned cells, gathered in global order on the root; only the
// root writes (writer is null elsewhere).
void write_fields(ResultWriter* writer, const KineticScene& scene) {
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
}

int run(const DriverOptions& options) {
  const DriverCase run_case(options);
  const CaseFile& case_file = run_case.file;
  const CaseNode& root = run_case.root;
  const std::string& name = run_case.name;
  const std::string& output = run_case.output;
  auto elapsed = [&] { return run_case.elapsed(); };

  const Communicator world = Communicator::world();
  // The initial and the walls' states are discrete equilibria on the velocity grid: one that
  // does not converge is a temperature or a velocity the grid cannot represent.
  KineticScene scene = read_with_input_solves(
      root, "a gas state of the case has no discrete equilibrium on velocity_grid",
      [&] { return build_kinetic_scene(root, run_case.dir, world); });
  case_file.check_all_used();  // a typo stops the run here, before any solving
  KineticOperator& op = *scene.op;

  std::unique_ptr<ResultWriter> writer;  // the root writes
  if (world.is_root()) {
    writer = std::make_unique<ResultWriter>(output, *scene.mesh);
    remove_on_interrupt(temp_path_for(output));
  }

  std::vector<Real> f(op.size());
  op.initialize(f, [&](const Vec3&) { return scene.initial; });
  const bool quiet = options.quiet || !world.is_root();
  // Progress every 5 s with the contraction rate's forecast of the time still needed; once
  // that forecast passes kSlowForecastSeconds, one warning with the remedy.
  constexpr double kSlowForecastSeconds = 600;
  const bool sequential = scene.solver.type == "sequential";
  double last_print = -10;
  bool warned_slow = false;
  std::vector<Real> ratios;
  auto monitor = [&](int iteration, Real ratio) {
    ratios.push_back(ratio);
    if (quiet || elapsed() - last_print <= 5) return true;
    last_print = elapsed();
    const auto forecast = ConvergenceForecast::of(ratios, scene.solver.tolerance);
    if (!forecast) {
      std::fprintf(stderr, "iteration %d: residual ratio %.3e (%.0f s)\n", iteration, ratio,
                   elapsed());
      return true;
    }
    const double seconds_left = forecast->remaining * elapsed() / iteration;
    std::fprintf(stderr,
                 "iteration %d: residual ratio %.3e, %.5f per iteration, ~%.2g more to %.0e "
                 "(~%s) (%.0f s)\n",
                 iteration, ratio, forecast->rate, forecast->remaining, scene.solver.tolerance,
                 format_duration(seconds_left).c_str(), elapsed());
    if (!warned_slow && seconds_left > kSlowForecastSeconds) {
      warned_slow = true;
      std::fprintf(stderr, "rfmems-gas: warning: at this rate the solve needs ~%s more%s\n",
                   format_duration(seconds_left).c_str(),
                   sequential ? "; the sequential solver's rate tends to 1 near the continuum "
                                "(Kn -> 0), where solver.type: comet converges in far fewer "
                                "iterations"
                              : "");
    }
    return true;
  };
  const KineticSolveResult result =
      kinetic_solvers().at(scene.solver.type)(op, f, scene.solver, monitor);
  op.update_collision(f);  // macros of the final state
  const ValidityReport validity = kinetic_scene_validity(scene, world);
  if (!quiet) print_validity_warnings("rfmems-gas", validity);

  write_fields(writer.get(), scene);
  std::vector<double> its;
  std::vector<std::vector<double>> ratio_rows;
  for (std::size_t i = 0; i < result.history.size(); ++i) {
    its.push_back(static_cast<double>(i + 1));
    ratio_rows.push_back({result.history[i]});
  }
  if (writer)
    writer->write_time_series("solver", "residual", its, ratio_rows, {"ratio"}, "iteration");

  const FaceGraph& g = *scene.graph;
  Json summary;
  summary["case"] = name;
  summary["collision"] = collision_model_name(op.gas().model);
  summary["mesh"] = {{"dim", g.dim}, {"cells", scene.mesh->n_cells()}};
  if (scene.distributed) {
    summary["partition"] = {{"ranks", world.size()},
                            {"edge_cut", scene.distributed->partition.edge_cut},
                            {"imbalance", scene.distributed->partition.imbalance}};
    // What the root sent during the whole run (parallel/communication_counters.hpp).
    const CommunicationCounters sent = communication_counters();
    summary["communication_rank0"] = {{"messages", sent.messages},
                                      {"bytes", sent.bytes},
                                      {"ghost_exchanges", sent.exchanges},
                                      {"reductions", sent.reductions}};
  }
  summary["velocity_grid"] = {{"points", op.grid().n},
                              {"ordinates", op.grid().size()},
                              {"extent_m_per_s", op.grid().extent.maxCoeff()}};
  summary["initial"] = {{"density", scene.initial.rho},
                        {"temperature", scene.initial.T},
                        {"knudsen", scene.knudsen},
                        {"reference_length", scene.reference_length}};
  summary["solver"] = {{"type", scene.solver.type},
                       {"converged", result.converged},
                       {"iterations", result.iterations},
                       {"tolerance", scene.solver.tolerance},
                       {"residual_initial", result.initial_residual},
                       {"residual_final", result.final_residual},
                       {"residual_ratio", result.residual_ratio},
                       {"seconds", result.seconds}};
  Json walls = Json::object();
  std::vector<Vec3> forces;
  std::vector<Real> heat_flows;
  for (const std::string& name : scene.force_patches) {
    const int p = g.find_patch(name);  // -1 on a rank without it: contributes nothing
    forces.push_back(op.wall_force(p, f));
    heat_flows.push_back(op.wall_heat_flow(p, f));
    const Vec3& F = forces.back();
    walls[name] = {{"force", {F.x(), F.y(), F.z()}}, {"heat_flow", heat_flows.back()}};
  }
  summary["walls"] = walls;
  // Net outflow of mass through every patch: a steady state passes as much in as out.
  Json boundaries = Json::object();
  for (const Patch& patch : scene.mesh->patches())
    boundaries[patch.name] = {{"mass_flow", op.boundary_mass_flow(g.find_patch(patch.name), f)}};
  summary["boundaries"] = boundaries;
  summary["total_mass"] = op.total_mass(f);
  summary["output"] = {{"h5", output}, {"xdmf", output.substr(0, output.rfind('.')) + ".xdmf"}};
  summary["validity"] = validity.to_json();
  summary["wall_time_s"] = elapsed();
  if (!result.converged && !result.stop_reason.empty())
    throw SolverError(
        fmt::format("{}{}", result.stop_reason,
                    sequential ? " (near the continuum use solver.type: comet)" : ""));
  if (!result.converged)
    throw SolverError(
        fmt::format("no convergence after {} iterations (residual ratio {:.3e}, tolerance {:.1e})",
                    result.iterations, result.residual_ratio, scene.solver.tolerance));
  if (!world.is_root()) return 0;
  writer->write_metadata({{"case_file", case_file.path()},
                          {"case_name", name},
                          {"case_text", case_file.text()},
                          {"case_effective", case_file.effective_text()},
                          {"collision", collision_model_name(op.gas().model)},
                          {"solver", scene.solver.type},
                          {"summary", json_text(summary)}},
                         {{"wall_time_s", elapsed()},
                          {"iterations", result.iterations},
                          {"residual_ratio", result.residual_ratio},
                          {"knudsen", scene.knudsen}});
  writer->finish();

  if (options.json) {
    std::cout << json_text(summary) << std::flush;
  } else if (!quiet) {
    std::printf(
        "%s (%s, Kn = %.4g, %lld cells x %lld velocities): %s solver converged in %d "
        "iterations (residual ratio %.2e, %.1f s)\n",
        name.c_str(), collision_model_name(op.gas().model), scene.knudsen,
        static_cast<long long>(scene.mesh->n_cells()), static_cast<long long>(op.grid().size()),
        scene.solver.type.c_str(), result.iterations, result.residual_ratio, result.seconds);
    for (std::size_t i = 0; i < forces.size(); ++i) {
      const Vec3& F = forces[i];
      std::printf("  wall %s: force [%.6e, %.6e, %.6e] N%s, heat flow %.6e W%s\n",
                  scene.force_patches[i].c_str(), F.x(), F.y(), F.z(), g.dim == 2 ? "/m" : "",
                  heat_flows[i], g.dim == 2 ? "/m" : "");
    }
    std::printf("wrote %s and %s (%.1f s)\n", writer->path().c_str(), writer->xdmf_path().c_str(),
                elapsed());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return driver_main("rfmems-gas",
                     "rfmems-gas: steady rarefied gas flow, discrete-velocity BGK / ESBGK (FV)",
                     argc, argv, run, RankUse::AllRanks);
}

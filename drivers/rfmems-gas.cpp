// rfmems-gas: steady rarefied gas flow by the discrete-velocity BGK / ESBGK model
// (lib/physics/gas/kinetic): reads a case file (mesh, gas, initial state, velocity grid,
// boundaries, solver; physics/gas/kinetic/kinetic_case.hpp), iterates to the steady state with
// the solver named in `solver.type` (sequential or comet), writes the cell fields
// and the residual history to HDF5 + XDMF, and reports the solver that ran (and COMET's hand-over
// to the sequential one), iterations, residuals, the reference state (p0, T0, rho0, mu0, v0, H,
// delta, Kn), the forces and heat flows on the walls with their normalised shear P and heat flux
// q*, and a body-force-driven channel's flow rate G (physics/gas/kinetic/kinetic_reference.hpp).
//
// Sample runs:
//   rfmems-gas cases/gas_couette/case.yaml                  # -> out/gas_couette.h5, .xdmf
//   rfmems-gas cases/gas_heat_transfer/case.yaml --json --quiet
//   rfmems-gas cases/gas_cavity/case.yaml --set initial.knudsen=1 -o out/cavity_kn1.h5
//   rfmems-gas cases/gas_poiseuille/case.yaml             # periodic channel, body force: G
//   mpirun -np 2 rfmems-gas cases/gas_heat_transfer/case.yaml --set solver.type=comet
//       # METIS parts, one ghost layer; COMET's coarse levels agglomerated per part
//
// Fields (step 0): density (kg/m^3), velocity (m/s), temperature (K), pressure (Pa),
// heat_flux (W/m^2), stress (viscous, Pa, Voigt xx yy zz yz xz xy). /solver/residual: the
// ratio ||r|| / ||r_0|| per iteration. Exit codes as rfmems-solid: 0 success; 2 bad input (one
// line on stderr, no result file); 1 other failures (including no convergence).
#include <fmt/format.h>

#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/case_file.hpp"
#include "io/driver_main.hpp"
#include "io/input_solve.hpp"
#include "io/interrupt_cleanup.hpp"
#include "io/iteration_progress.hpp"
#include "io/json_summary.hpp"
#include "io/kinetic_text.hpp"
#include "io/result_writer.hpp"
#include "parallel/communicator.hpp"
#include "physics/gas/kinetic/kinetic_case.hpp"
#include "physics/gas/kinetic/kinetic_results.hpp"
#include "physics/gas/kinetic/kinetic_validity.hpp"

namespace {

using namespace rfmems;

constexpr const char* kProgram = "rfmems-gas";

int run(const DriverOptions& options) {
  const DriverCase run_case(options);
  const CaseFile& case_file = run_case.file;
  const Communicator world = Communicator::world();
  // The initial and the walls' states are discrete equilibria on the velocity grid: one that
  // does not converge is a temperature or a velocity the grid cannot represent.
  KineticScene scene = read_with_input_solves(
      run_case.root, "a gas state of the case has no discrete equilibrium on velocity_grid",
      [&] { return build_kinetic_scene(run_case.root, run_case.dir, world); });
  if (!run_case.finish_reading()) return 0;  // a typo stops the run here, before any solving
  KineticOperator& op = *scene.op;

  std::unique_ptr<ResultWriter> writer;  // the root writes
  if (world.is_root()) {
    writer = std::make_unique<ResultWriter>(run_case.output, *scene.mesh);
    remove_on_interrupt(temp_path_for(run_case.output));
  }

  std::vector<Real> f(op.size());
  op.initialize(f, [&](const Vec3&) { return scene.initial; });
  const bool quiet = options.quiet || !world.is_root();
  // Source iteration's rate tends to 1 near the continuum, where COMET does not slow down.
  const bool sequential = scene.solver.type == "sequential";
  const std::string remedy = sequential ? "near the continuum use solver.type: comet" : "";
  IterationProgress progress(quiet, scene.solver.tolerance, kProgram, remedy);
  const KineticSolveResult result =
      kinetic_solvers().at(scene.solver.type)(op, f, scene.solver, std::ref(progress));
  op.update_collision(f);  // macros of the final state
  const ValidityReport validity = kinetic_scene_validity(scene, world);
  if (!quiet) print_validity_warnings(kProgram, validity);

  write_kinetic_results(writer.get(), scene, result);
  Json summary = kinetic_summary(scene, result, f);
  summary["case"] = run_case.name;
  summary["output"] = {{"h5", run_case.output},
                       {"xdmf", ResultWriter::sidecar_path(run_case.output)}};
  summary["validity"] = validity.to_json();
  summary["wall_time_s"] = run_case.elapsed();
  if (!result.converged && !result.stop_reason.empty())
    throw SolverError(result.stop_reason + (sequential ? " (" + remedy + ")" : ""));
  if (!result.converged)
    throw SolverError(
        fmt::format("no convergence after {} iterations (residual ratio {:.3e}, tolerance {:.1e})",
                    result.iterations, result.residual_ratio, scene.solver.tolerance));
  if (!world.is_root()) return 0;
  writer->write_metadata({{"case_file", case_file.path()},
                          {"case_name", run_case.name},
                          {"case_text", case_file.text()},
                          {"case_effective", case_file.effective_text()},
                          {"collision", collision_model_name(op.gas().model)},
                          {"solver", scene.solver.type},
                          {"summary", json_text(summary)}},
                         {{"wall_time_s", run_case.elapsed()},
                          {"iterations", result.iterations},
                          {"residual_ratio", result.residual_ratio},
                          {"knudsen", scene.knudsen}});
  writer->finish();
  if (options.json) {
    std::cout << json_text(summary) << std::flush;
  } else if (!quiet) {
    std::printf("%swrote %s and %s (%.1f s)\n", kinetic_text(summary).c_str(),
                writer->path().c_str(), writer->xdmf_path().c_str(), run_case.elapsed());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return driver_main(kProgram,
                     "rfmems-gas: steady rarefied gas flow, discrete-velocity BGK / ESBGK (FV)",
                     kinetic_case_keys(), argc, argv, run, RankUse::AllRanks);
}

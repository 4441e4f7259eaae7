// rfmems-solid: linear elastodynamics and elastostatics of a structure: a plane or 3D
// continuum (FV elasticity operator) or a Mindlin-Reissner plate (FV plate operator), as the
// case's model.structure says. Reads a case file, builds the model, runs a static (KINSOL or
// segregated), transient (IDA) or modal (shift-invert Arnoldi: frequencies and mode shapes)
// analysis, writes an HDF5 + XDMF result.
//
// Sample runs:
//   rfmems-solid cases/cantilever_vibration/case.yaml          # -> out/cantilever_vibration.h5
//   rfmems-solid cases/cantilever_static/case.yaml --json --quiet
//   rfmems-solid cases/cantilever_static/case.yaml --set mesh.cells=[320,32] -o out/fine.h5
//   rfmems-solid cases/clamped_plate/case.yaml                 # plate: deflection, moments
//   rfmems-solid cases/plate_vibration/case.yaml --set analysis.type=modal   # 6 lowest modes
//
// Under mpirun the structure is solved on rank 0 while the other ranks wait, unless the case
// says solver.distributed: true: then the continuum (or a static plate) is distributed over the
// ranks (METIS parts, GMRES preconditioned by rank-local KLU;
// physics/structure/distributed_analysis.hpp) and rank 0 gathers each output into the same result
// file:
//   mpirun -np 2 rfmems-solid cases/cantilever_static/case.yaml --set 'solver={distributed: true}'
//
// Large 3D continua are solved by GMRES with algebraic multigrid (hypre's BoomerAMG) on the
// same distributed vectors, on one rank unless distributed (solver.linear; docs/scale.md):
//   rfmems-solid cases/cantilever_box_3d/case.yaml --set 'mesh.cells=[320,32,32]'  # 1M unknowns
//
// Exit codes: 0 success; 2 bad input (case file, option, mesh file): one line
// "rfmems-solid: <message>" on stderr and no result file; 1 any other failure.
#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/case_file.hpp"
#include "io/driver_main.hpp"
#include "io/interrupt_cleanup.hpp"
#include "io/json_summary.hpp"
#include "io/probes.hpp"
#include "io/progress.hpp"
#include "parallel/communicator.hpp"
#include "physics/structure/distributed_analysis.hpp"
#include "physics/structure/structural_analysis.hpp"
#include "physics/structure/structural_results.hpp"
#include "physics/structure/structure_from_case.hpp"

namespace {

using namespace rfmems;

struct NoOutput : AnalysisObserver {
  void output(int, Real, std::span<const Real>, std::span<const Real>) override {}
};

int run(const DriverOptions& options) {
  const DriverCase run_case(options);
  const CaseFile& case_file = run_case.file;
  const CaseNode& root = run_case.root;
  const std::string& name = run_case.name;
  const std::string& output = run_case.output;
  auto elapsed = [&] { return run_case.elapsed(); };
  const Communicator world = Communicator::world();
  // Serial structures: the root alone builds and solves; the other ranks wait at exit.
  const bool distributed = root.child_or_empty("solver").get_bool("distributed", false);
  if (!distributed && !world.is_root()) return 0;

  const AnalysisType type = read_analysis_type(root);
  std::unique_ptr<StructuralModel> model = build_structure(root, run_case.dir, type);
  AnalysisSettings settings = read_analysis_settings(root, *model);
  std::vector<Probe> probes = read_probes(root.child_or_empty("probes"), model->structure_mesh());
  settle_linear_solver(*model, settings, root);
  // Multigrid alone runs the distributed solvers on the root's one rank.
  const Communicator comm = distributed ? world : Communicator::serial();
  if (!run_case.finish_reading()) return 0;  // a typo stops the run here, before any solving

  // The result file exists on the root only; if creating it fails there, a distributed run's
  // other ranks must not enter the collective solve (they would wait for the root forever).
  std::unique_ptr<StructuralResults> results;
  std::exception_ptr failure;
  if (world.is_root()) try {
      results = std::make_unique<StructuralResults>(output, *model, std::move(probes));
      remove_on_interrupt(temp_path_for(output));  // exceptions clean up; signals need this
    } catch (...) {
      failure = std::current_exception();
    }
  if (distributed && world.max(static_cast<Index>(failure ? 1 : 0)) != 0 && !failure) return 0;
  if (failure) std::rethrow_exception(failure);
  if (!world.is_root()) {  // a distributed run's other ranks: solve, the root writes
    ProgressReporter silent(true, settings.end_time);
    NoOutput none;
    run_distributed_analysis(*model, settings, world, none, silent);
    return 0;
  }
  ProgressReporter progress(options.quiet || type != AnalysisType::Transient, settings.end_time);
  const AnalysisStats stats =
      on_distributed_vectors(settings)
          ? run_distributed_analysis(*model, settings, comm, *results, progress)
          : run_analysis(*model, settings, *results, progress);
  progress.finish();
  results->finish(case_file, name, stats, elapsed());

  const Json summary = structural_summary(name, *model, *results, stats, elapsed());
  if (options.json) {
    std::cout << json_text(summary) << std::flush;
  } else if (!options.quiet) {
    for (const StructuralMode& m : stats.modal.modes)
      std::printf("mode %lld: f = %.6e Hz%s\n", static_cast<long long>(m.number), m.frequency,
                  m.complex ? fmt::format(" (complex eigenvalue: lambda = {:.6e} {:+.6e} i, "
                                          "damping ratio {:.3e})",
                                          m.eigenvalue.real(), m.eigenvalue.imag(), m.damping_ratio)
                                  .c_str()
                            : "");
    const auto components = model->probe_components();
    const bool plate = model->kind() == "plate";
    const int shown = plate || model->structure_mesh().dim() == 3 ? 3 : 2;
    if (type == AnalysisType::Harmonic) {
      // Per probe, the main component's largest amplitude over the sweep.
      const int main = model->main_probe_component();
      const std::string name = model->probe_components()[main];
      const std::vector<Real>& f = stats.harmonic.frequencies;
      for (std::size_t p = 0; p < results->harmonic().size(); ++p) {
        std::size_t top = 0;
        for (std::size_t k = 0; k < f.size(); ++k)
          if (std::abs(results->harmonic()[p][k][main]) >
              std::abs(results->harmonic()[p][top][main]))
            top = k;
        std::printf(
            "probe %s: largest |%s| = %.6e at %.6e Hz (of %zu frequencies "
            "from %.6e to %.6e Hz)\n",
            results->probes()[p].name.c_str(), name.c_str(),
            std::abs(results->harmonic()[p][top][main]), f[top], f.size(), f.front(), f.back());
      }
    }
    // Modal and harmonic runs' probes sample shapes and responses, not a state: not printed.
    const bool state = type != AnalysisType::Modal && type != AnalysisType::Harmonic;
    const Json shown_probes = state ? summary["probes"] : Json::object();
    for (const auto& [probe, value] : shown_probes.items()) {
      std::printf("probe %s:", probe.c_str());
      for (int k = 0; k < shown; ++k)
        std::printf("%s %s = %.6e%s", k ? "," : "", components[k].c_str(),
                    value[components[k]].get<double>(), plate && k > 0 ? " rad" : " m");
      std::printf("\n");
    }
    std::printf("wrote %s and %s (%.1f s)\n", results->path().c_str(), results->xdmf_path().c_str(),
                elapsed());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return driver_main(
      "rfmems-solid",
      "rfmems-solid: static, transient, modal and harmonic linear elasticity of a continuum "
      "or a plate (FV)",
      join_schemas({structure_case_keys(), structural_analysis_case_keys(), probes_case_keys()}),
      argc, argv, run, RankUse::AllRanks);
}

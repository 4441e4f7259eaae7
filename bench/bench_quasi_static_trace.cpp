// bench_quasi_static_trace: the cost of the quasi-static pull-in curve of the default switch
// (cases/switch_plate without gas: plate + parallel-plate, displacement control through the
// fold; coupling/quasi_static_pull_in.hpp) against the mesh, measured in one run.
//
// 1. --section orderings: the bordered displacement-control Jacobian at the fold of each mesh
//    factorised with each fill-reducing ordering KLU offers here (AMD on A + A^T, COLAMD,
//    METIS nested dissection), and with UMFPACK (its METIS ordering; its symmetric strategy on
//    the nested-dissection order): entries of L + U, the time of the symbolic analysis with a
//    factorisation with fresh pivoting, of a refactorisation (KLU: keeping the pivots), and of
//    one solve (each the median of --repeat).
// 2. --section trace: the whole curve (the case's 40 points to 0.9 g0, fold to 0.01 V) on each
//    mesh with KLU and each ordering, and with UMFPACK at every size (`umfpack`: its symmetric
//    strategy on the nested-dissection order, QuasiStaticOptions' choice from 1000 unknowns):
//    wall and CPU time, solves, Newton iterations, factorisations with fresh pivoting (UMFPACK:
//    with a symbolic analysis) and refactorisations, V_PI.
//
// Output: one JSON object per line on stdout.
//   bench_quasi_static_trace [--nx 40 80 160] [--section orderings trace] [--repeat 3]
#include <CLI/CLI.hpp>
#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>

#include "bench_support.hpp"
#include "bench_switch_scene.hpp"
#include "coupling/displacement_control_system.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/switch_scene.hpp"
#include "solvers/klu_factorization.hpp"
#include "solvers/umfpack_factorization.hpp"

using namespace rfmems;
using namespace rfmems::bench;
using json = nlohmann::json;

namespace {

// The default switch without gas on nx x nx/10 cells.
std::unique_ptr<Scene> plate_switch(int nx) {
  return load_scene(default_cases_dir() + "/switch_plate/case.yaml",
                    {"gas.model=none",
                     "mesh.cells=[" + std::to_string(nx) + "," + std::to_string(nx / 10) + "]"});
}

const std::vector<std::pair<std::string, KluOrdering>> kOrderings = {
    {"amd", KluOrdering::Amd},
    {"colamd", KluOrdering::Colamd},
    {"nested_dissection", KluOrdering::NestedDissection}};

QuasiStaticOptions case_sampling(KluOrdering ordering) {
  QuasiStaticOptions o;  // the case's: 40 points to 0.9 g0, the fold to 0.01 V
  o.n_points = 40;
  o.max_fraction = 0.9;
  o.voltage_tolerance = 0.01;
  o.ordering = ordering;
  return o;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void orderings(int nx, int repeat) {
  auto sc = plate_switch(nx);
  ParallelPlateActuation& act = *sc->scene.actuation;
  const QuasiStaticPullIn fold = trace_pull_in(act, sc->scene.control, case_sampling({}));
  DisplacementControlSystem system(act, sc->scene.control, stiffness_scale(act));
  system.set_target(fold.pull_in_displacement);
  const CsrPattern& pattern = system.jacobian_pattern();
  std::vector<Real> values(pattern.nnz()), zero(system.size(), 0.0);
  system.jacobian(0.0, 0.0, fold.fold_state, zero, values);
  // Analyse + factorise, refactorise and solve with the factorisation make() builds, each the
  // median of `repeat`; one line of output.
  auto measure = [&](const std::string& name, auto&& make) {
    std::vector<double> factor, refactor, solve;
    long entries = 0;
    for (int r = 0; r < repeat; ++r) {
      double t0 = cpu_now();
      auto lu = make();
      factor.push_back(cpu_now() - t0);
      t0 = cpu_now();
      lu.refactor(values);
      refactor.push_back(cpu_now() - t0);
      std::vector<Real> b(system.size(), 1.0);
      t0 = cpu_now();
      lu.solve(b);
      solve.push_back(cpu_now() - t0);
      entries = lu.factor_entries();
    }
    emit(json{{"section", "orderings"},
              {"nx", nx},
              {"ny", nx / 10},
              {"unknowns", system.size()},
              {"matrix_entries", pattern.nnz()},
              {"ordering", name},
              {"factor_entries", entries},
              {"analyze_factor_cpu_s", median(factor)},
              {"refactor_cpu_s", median(refactor)},
              {"solve_cpu_s", median(solve)}});
  };
  for (const auto& [name, ordering] : kOrderings)
    measure(name,
            [&] { return KluFactorization(pattern, values, ordering, KluSystem::MixedUnits); });
  // UMFPACK, its METIS ordering and its symmetric strategy on the nested-dissection order
  // (the trace's from QuasiStaticOptions::umfpack_from), without iterative refinement.
  for (const auto& [name, ordering] :
       {std::pair{"umfpack_metis", UmfpackOrdering::Metis},
        std::pair{"umfpack_symmetric_nd", UmfpackOrdering::SymmetricNestedDissection}})
    measure(name, [&] { return UmfpackFactorization(pattern, values, 0, ordering); });
}

void trace(int nx, const std::vector<std::string>& only) {
  // KLU with each ordering, then UMFPACK (its own METIS ordering) at every size.
  std::vector<std::pair<std::string, KluOrdering>> variants = kOrderings;
  variants.push_back({"umfpack", KluOrdering::BySize});
  for (const auto& [name, ordering] : variants) {
    if (std::find(only.begin(), only.end(), name) == only.end()) continue;
    auto sc = plate_switch(nx);
    QuasiStaticOptions options = case_sampling(ordering);
    options.umfpack_from = name == "umfpack" ? 0 : std::numeric_limits<Index>::max();
    const double w0 = now(), c0 = cpu_now();
    const QuasiStaticPullIn r = trace_pull_in(*sc->scene.actuation, sc->scene.control, options);
    const double wall = now() - w0, cpu = cpu_now() - c0;
    emit(json{{"section", "trace"},
              {"nx", nx},
              {"ny", nx / 10},
              {"unknowns", sc->scene.actuation->size() + 1},
              {"ordering", name},
              {"wall_s", wall},
              {"cpu_s", cpu},
              {"solves", r.solves},
              {"newton_iters", r.newton_iterations},
              {"fresh_factorizations", r.last.fresh_factorizations},
              {"refactorizations", r.last.refactorizations},
              {"factor_entries", r.last.factor_entries},
              {"pull_in_voltage", r.pull_in_voltage}});
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"cost of the quasi-static pull-in curve against the mesh"};
  std::vector<int> nx{40, 80, 160};
  std::vector<std::string> sections{"orderings", "trace"};
  int repeat = 3;
  std::vector<std::string> only{"amd", "colamd", "nested_dissection", "umfpack"};
  app.add_option("--nx", nx, "cells along the switch (nx x nx/10)");
  app.add_option("--section", sections, "orderings, trace");
  app.add_option("--ordering", only, "the orderings of the trace section (and umfpack)");
  app.add_option("--repeat", repeat, "repetitions of each factorisation (median)");
  CLI11_PARSE(app, argc, argv);
  for (const std::string& s : sections)
    for (int n : nx) {
      if (s == "orderings") orderings(n, repeat);
      if (s == "trace") trace(n, only);
    }
  return 0;
}

// bench_electrostatics_mpi: CPU per immersed field solve, serial KLU against the distributed
// solve (GMRES + KLU on the rank-local blocks), docs/mpi.md, "Distributed immersed electrostatics".
//
// Problem: the cantilever switch of cases/cantilever_switch (beam 45 x 1.5 um on 185 x 11
// cells, background 75 x 10 um, electrode under the beam, 100 V), the beam bent down as
// u_y = -d (x / L)^2 with d rising by 5 nm per load to `steps` x 5 nm (the coupled run's
// motion: most loads keep the marking's pattern, a few re-mark). Per background, in one run
// under mpirun -np P (rank 0 prints one JSON line per background and variant):
//   klu:     every rank solves the whole field (ImmersedElectrostatics' serial path, the
//            kept LU refactored while the pattern holds): what each rank does today;
//   ras, bj: the distributed solve with restricted additive Schwarz on the ghost overlap, or
//            block Jacobi on the owned block (warm start from the last potential).
// Figures: CPU seconds of the field solve per load (ImmersedPhysicsTimes::electrostatics:
// assembly, factorisation, solve, charges), the largest over the ranks and their sum, after a
// first load that analyses; GMRES iterations per load; the potential's largest difference
// from the KLU one at the last load, relative to V. The load average at the start is in
// every line (a shared machine: compare within a line).
//
//   mpirun --allow-run-as-root --bind-to none -np 2 build/bench/bench_electrostatics_mpi
//     --cells 76x26 151x51 301x101
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "ibm/immersed_boundary_field.hpp"
#include "mesh/structured_mesh.hpp"
#include "parallel/communicator.hpp"

using namespace rfmems;
using json = nlohmann::json;

namespace {

constexpr Real um = 1e-6;

double load_average() {
  std::ifstream in("/proc/loadavg");
  double one = -1;
  in >> one;
  return one;
}

struct Run {
  double cpu_per_load = 0;  // after the first load
  double iterations_per_load = 0;
  long analyses = 0;
  std::vector<Real> potential;  // last load
};

Run run_loads(ImmersedBoundaryField& scene, const ElasticityOperator& beam, int steps,
              Real voltage) {
  const Mesh& mesh = beam.mesh();
  std::vector<Real> u(beam.size(), 0.0);
  double cpu_first = 0;
  long iterations_first = 0;
  scene.reset_times();
  for (int step = 1; step <= steps; ++step) {
    const Real d = 5e-9 * step;
    for (Index c = 0; c < mesh.n_cells(); ++c) {
      const Real s = mesh.cell_centroid(c).x() / (45 * um);
      u[2 * c + 1] = -d * s * s;
    }
    scene.electrostatic_load(u, voltage);
    if (step == 1) {
      cpu_first = scene.times().electrostatics;
      iterations_first = scene.times().electrostatic_krylov_iterations;
    }
  }
  Run r;
  r.cpu_per_load = (scene.times().electrostatics - cpu_first) / (steps - 1);
  r.iterations_per_load =
      static_cast<double>(scene.times().electrostatic_krylov_iterations - iterations_first) /
      (steps - 1);
  r.analyses = scene.times().electrostatic_analyses;
  const std::span<const Real> phi = scene.potential();
  r.potential.assign(phi.begin(), phi.end());
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  MpiSession session(&argc, &argv);
  CLI::App app{"CPU per immersed field solve: serial KLU vs distributed GMRES"};
  std::vector<std::string> cells{"76x26", "151x51"};
  int steps = 21;
  app.add_option("--cells", cells, "backgrounds NXxNY");
  app.add_option("--steps", steps, "loads per variant (the first analyses)");
  CLI11_PARSE(app, argc, argv);
  const Communicator world = Communicator::world();
  const double load = load_average();

  BoxSpec spec;
  spec.lower = Vec3(0, 1.5 * um, 0);
  spec.upper = Vec3(45 * um, 3.0 * um, 0);
  spec.n[0] = 185;
  spec.n[1] = 11;
  const Mesh beam_mesh = make_structured_mesh(spec);
  std::vector<ElasticityBoundary> bcs(beam_mesh.patches().size());
  bcs[beam_mesh.find_patch("left")].kind = ElasticityBoundary::Kind::Fixed;
  ElasticityOperator beam(beam_mesh, LinearElastic{200e9, 0.3, 8912, Hypothesis::PlaneStress}, bcs);
  for (const std::string& c : cells) {
    int nx = 0, ny = 0;
    if (std::sscanf(c.c_str(), "%dx%d", &nx, &ny) != 2) return 2;
    ImmersedBoundaryGeometry g;
    g.background_upper = Vec3(75 * um, 10 * um, 0);
    g.background_cells[0] = nx;
    g.background_cells[1] = ny;
    g.electrode_end = 45 * um;
    ImmersedBoundaryField scene(beam, g, LinearFunctional::unknown(2 * 184 + 1));  // tip cell's u_y
    const Run klu = run_loads(scene, beam, steps, 100.0);
    Index fluid = 0;
    for (Real v : klu.potential) fluid += std::isfinite(v);
    for (const char* variant : {"ras", "bj"}) {
      DistributedLinearOptions o;
      o.overlap = std::string(variant) == "ras";
      scene.distribute_electrostatics(world, o);
      const Run dist = run_loads(scene, beam, steps, 100.0);
      Real error = 0;
      for (std::size_t i = 0; i < klu.potential.size(); ++i)
        if (std::isfinite(klu.potential[i]))
          error = std::max(error, std::abs(dist.potential[i] - klu.potential[i]) / 100.0);
      json j{{"bench", "electrostatics_mpi"},
             {"ranks", world.size()},
             {"cells", c},
             {"unknowns", fluid},
             {"loads", steps - 1},
             {"load_average", load},
             {"klu_cpu_per_load_max", world.max(klu.cpu_per_load)},
             {"klu_cpu_per_load_sum", world.sum(klu.cpu_per_load)},
             {"klu_analyses", klu.analyses},
             {"variant", variant},
             {"cpu_per_load_max", world.max(dist.cpu_per_load)},
             {"cpu_per_load_sum", world.sum(dist.cpu_per_load)},
             {"gmres_per_load", dist.iterations_per_load},
             {"analyses", dist.analyses},
             {"max_potential_error_over_V", world.max(error)}};
      j["ratio_max_cpu_dist_over_klu"] =
          j["cpu_per_load_max"].get<double>() / j["klu_cpu_per_load_max"].get<double>();
      if (world.is_root()) bench::emit(j);
      scene.distribute_electrostatics(Communicator::serial());
    }
  }
  return 0;
}

// bench_structure_distributed: the cantilever's static solve with the structure on
// distributed vectors (docs/mpi.md, "Distributed structure") against the serial KLU solve.
//
// Problem: cases/cantilever_static (plane stress, L = 2 m, h = 0.04 m, clamped left end, end
// shear 1000 Pa), nx x ny cells, cubic reconstruction. Run under mpirun -np P; one JSON line
// per mesh from rank 0:
//   serial:      KINSOL + KLU on the whole mesh (rank 0 alone, the others wait at a barrier):
//                wall and CPU seconds;
//   distributed: DistributedElasticity (METIS parts, 4 ghost layers) + KINSOL on the parallel
//                N_Vector with GMRES and block-Jacobi KLU: setup (partition, local operator)
//                and solve seconds (wall of rank 0; CPU: the largest per-rank CPU seconds),
//                Newton and GMRES iterations, |u - u_KLU| / |u|; once with block Jacobi
//                and once with restricted additive Schwarz on the ghost overlap.
// The load average at the start is in every line (a shared machine: compare within a line).
//
// Sample runs:
//   mpirun --allow-run-as-root --bind-to none -np 1 build/bench/bench_structure_distributed
//   mpirun --allow-run-as-root --bind-to none -np 2 build/bench/bench_structure_distributed --cells
//   160x16
#include <CLI/CLI.hpp>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "mesh/structured_mesh.hpp"
#include "parallel/communicator.hpp"
#include "physics/elasticity/distributed_elasticity.hpp"
#include "solvers/distributed_static_solve.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using json = nlohmann::json;

namespace {

double load_average() {
  std::ifstream in("/proc/loadavg");
  double one = -1;
  in >> one;
  return one;
}

std::unique_ptr<ElasticityOperator> cantilever(const Mesh& mesh) {
  std::vector<ElasticityBoundary> bcs;
  for (const Patch& p : mesh.patches()) {
    if (p.name == "left")
      bcs.push_back({ElasticityBoundary::Kind::Fixed, {}});
    else if (p.name == "right")
      bcs.push_back({ElasticityBoundary::Kind::Traction,
                     [](const Vec3&, double) { return Vec3(0, -1000, 0); }});
    else
      bcs.push_back({ElasticityBoundary::Kind::Traction, {}});
  }
  return std::make_unique<ElasticityOperator>(
      mesh, LinearElastic{200e9, 0.31, 7854, Hypothesis::PlaneStress}, bcs);
}

}  // namespace

int main(int argc, char** argv) {
  MpiSession session(&argc, &argv);
  const Communicator comm = Communicator::world();
  CLI::App app{"bench_structure_distributed: distributed static cantilever vs serial KLU"};
  std::vector<std::string> cells{"160x16", "320x32"};
  app.add_option("--cells", cells, "meshes nx x ny");
  CLI11_PARSE(app, argc, argv);

  for (const std::string& spec_text : cells) {
    BoxSpec spec;
    char x = 0;
    std::istringstream(spec_text) >> spec.n[0] >> x >> spec.n[1];
    spec.lower = Vec3(0, -0.02, 0);
    spec.upper = Vec3(2, 0.02, 0);
    const Mesh mesh = make_structured_mesh(spec);
    auto op = cantilever(mesh);
    json j{{"bench", "structure_distributed"},
           {"cells", spec_text},
           {"unknowns", op->size()},
           {"ranks", comm.size()},
           {"load_average", load_average()}};

    // Serial KLU on rank 0 (the reference and the cost to beat).
    std::vector<Real> serial_y;
    comm.barrier();
    if (comm.is_root()) {
      const double w0 = bench::now(), c0 = bench::cpu_now();
      serial_y = solve_static(*op, 0.0).y;
      j["serial_wall_s"] = bench::now() - w0;
      j["serial_cpu_s"] = bench::cpu_now() - c0;
    }
    comm.barrier();
    double w0 = bench::now(), c0 = bench::cpu_now();
    DistributedElasticity dist(*op, comm);
    const double setup_wall = bench::now() - w0, setup_cpu = comm.max(bench::cpu_now() - c0);
    for (const bool overlap : {false, true}) {
      comm.barrier();
      w0 = bench::now();
      c0 = bench::cpu_now();
      DistributedNewtonOptions options;
      options.preconditioner = overlap ? DistributedLinearization::Family::Schwarz
                                       : DistributedLinearization::Family::BlockJacobi;
      const DistributedStaticSolution s = solve_static_distributed(dist, 0.0, options);
      const double solve_wall = bench::now() - w0, solve_cpu = comm.max(bench::cpu_now() - c0);

      const std::vector<Real> all = dist.gather_to_root(s.y);  // compared on the root
      double diff = 0, scale = 0;
      for (std::size_t i = 0; i < all.size(); ++i) {
        diff = std::max(diff, std::abs(all[i] - serial_y[i]));
        scale = std::max(scale, std::abs(serial_y[i]));
      }
      const Index edge_cut = dist.distributed_mesh().partition.edge_cut;
      if (comm.is_root()) {
        j["setup_wall_s"] = setup_wall;
        j["setup_cpu_s"] = setup_cpu;
        j["solve_wall_s"] = solve_wall;
        j["solve_cpu_s"] = solve_cpu;
        j["newton_iters"] = s.stats.newton_iters;
        j["gmres_iters"] = s.stats.linear_iters;
        j["rel_diff_vs_klu"] = diff / scale;
        j["edge_cut"] = edge_cut;
        j["solve_wall_over_serial"] = solve_wall / j["serial_wall_s"].get<double>();
        j["solve_cpu_over_serial"] = solve_cpu / j["serial_cpu_s"].get<double>();
        j["preconditioner"] = overlap ? "additive_schwarz" : "block_jacobi";
        bench::emit(j);
      }
    }
  }
  return 0;
}

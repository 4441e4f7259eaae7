// bench_gas_scaling: strong and weak scaling of the distributed kinetic solvers (thesis
// ch. 5: COMET 13.4-14.1x on 16 ranks, the sequential solver 1.7-4.5x), one
// JSON line per run and one per scaling row.
//
// Problem: the heat-transfer square of bench_comet_vs_sequential (argon ESBGK, diffuse top
// 327.78 K / bottom 273.15 K, specular sides, gas at rest at 273.15 K and rho0 = 9.28e-6
// kg/m^3, side L = lambda0 / Kn), n x n cells, nv^3 velocities over +-3.5 sqrt(2 R T0); COMET
// at Kn = 0.01 (forced COMET, the library's default multigrid), the sequential solver at
// Kn = 0.1 (at 0.01 it needs thousands of iterations); both to ||r|| / ||r_0|| <= 1e-6.
// METIS k-way parts, one ghost layer (rfmems-gas's distribution).
//
//   strong: the same n x n mesh on 1 and P ranks: speed-up S = T_1 / T_P, iteration-normalised
//           speed-up S (it_P / it_1) (the thesis's "normalised speed-up": the cost of an
//           iteration, apart from the iterations block Jacobi between parts adds), efficiency
//           S / P. T = the largest per-rank CPU seconds of the solve (immune to the other
//           processes of a shared machine; wall seconds are in the lines too).
//   weak:   n x n cells per rank: a (P L) x L domain of (P n) x n cells on P ranks; with
//           specular sides the heat transfer stays one-dimensional, so the problem per rank
//           is the same; efficiency T_1 / T_P.
// Communication, counted by the exchange layer (parallel/communication_counters.hpp), per
// rank: point-to-point messages, bytes, ghost exchanges and reductions per iteration (COMET:
// per V-cycle), with the rank's owned / ghost cells and neighbour count (the inputs of the
// communication model in docs/mpi.md).
//
// The bench launches itself under mpirun (`--mpirun`, default "mpirun --allow-run-as-root
// --oversubscribe") once per (solver, mesh, P) and collects the workers' lines: run it
// without mpirun. `--worker` is the per-run mode the launcher uses.
//
// Sample runs:
//   build/bench/bench_gas_scaling                                   # 50, 100; 1 -> 2 ranks
//   build/bench/bench_gas_scaling --cells 20 --nv 6 --ranks 1,2,3   # a quick check
//   build/bench/bench_gas_scaling --solvers comet --cells 100 --weak-cells 0
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <array>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "core/error.hpp"
#include "mesh/structured_mesh.hpp"
#include "parallel/communication_counters.hpp"
#include "parallel/distributed_mesh.hpp"
#include "physics/gas/comet/comet_solver.hpp"
#include "physics/gas/kinetic/sequential_solver.hpp"

using namespace rfmems;
using json = nlohmann::json;

namespace {

constexpr Real kT0 = 273.15, kTHot = 327.78, kRho0 = 9.28e-6;

std::array<double, 3> load_average() {
  std::array<double, 3> l{0, 0, 0};
  std::ifstream in("/proc/loadavg");
  in >> l[0] >> l[1] >> l[2];
  return l;
}

struct WorkerArgs {
  std::string solver = "comet";
  int nx = 50, ny = 50, nv = 8;
  Real kn = 0.01, width = 1.0, tolerance = 1e-6;
  int max_iterations = 100000;
};

// One run on the ranks of mpirun: builds, distributes, solves, and the root prints one line.
int run_worker(const WorkerArgs& a) {
  const Communicator comm = Communicator::world();
  const int p = comm.size();
  const KineticGas gas = KineticGas::argon(CollisionModel::Esbgk);
  const Real length = gas.mean_free_path(kRho0, kT0) / a.kn;
  BoxSpec spec;
  spec.upper = Vec3(a.width * length, length, 0);
  spec.n[0] = a.nx;
  spec.n[1] = a.ny;
  const Mesh global = make_structured_mesh(spec);
  std::unique_ptr<DistributedMesh> d;
  FaceGraph graph;
  if (comm.is_serial()) {
    graph = face_graph_of(global);
  } else {
    d = std::make_unique<DistributedMesh>(distribute_mesh(global, comm, 1));
    graph = face_graph_of(d->local.mesh);
  }
  std::vector<KineticBoundary> bcs;
  for (const std::string& patch : graph.patch_names)
    bcs.push_back(patch == "top"      ? KineticBoundary::diffuse_wall(kTHot)
                  : patch == "bottom" ? KineticBoundary::diffuse_wall(kT0)
                                      : KineticBoundary::specular_wall());  // sides, processor
  VelocityGrid grid = VelocityGrid::uniform(a.nv, a.nv, a.nv, 3.5 * gas.thermal_speed(kT0));
  KineticOperator op(graph, std::move(grid), gas, std::move(bcs));
  if (d) op.set_parallel(comm, &d->exchange);
  std::vector<Real> f(op.size());
  op.initialize(f, [](const Vec3&) { return GasState{kRho0, Vec3::Zero(), kT0}; });

  const auto load0 = load_average();
  comm.barrier();
  const double cpu0 = bench::cpu_now(), wall0 = bench::now();
  const CommunicationCounters sent0 = communication_counters();
  int iterations = 0, levels = 1;
  bool converged = false;
  if (a.solver == "comet") {
    CometOptions o;
    o.tolerance = a.tolerance;
    o.max_cycles = a.max_iterations;
    o.sequential_above_knudsen = 0;
    CometSolver solver(op, o);
    const CometResult r = solver.solve(f);
    iterations = r.cycles;
    levels = r.levels;
    converged = r.converged;
  } else if (a.solver == "sequential") {
    SequentialOptions o;
    o.tolerance = a.tolerance;
    o.max_iterations = a.max_iterations;
    const KineticSolveResult r = solve_sequential(op, f, o);
    iterations = r.iterations;
    converged = r.converged;
  } else {
    throw InputError("--solver: '" + a.solver + "' (comet | sequential)");
  }
  const double cpu = bench::cpu_now() - cpu0, wall = bench::now() - wall0;
  const CommunicationCounters sent = communication_counters() - sent0;
  const int top = graph.find_patch("top");
  const Real heat_top = op.wall_heat_flow(top, f);  // collective

  // Per-rank figures, summed into rank slots.
  enum {
    kCpu,
    kWall,
    kOwned,
    kGhosts,
    kNeighbours,
    kMessages,
    kBytes,
    kExchanges,
    kReductions,
    kWaitCpu,
    kWaitWall,
    kN
  };
  std::vector<Real> per(kN * p, 0.0);
  auto set = [&](int what, Real x) { per[what * p + comm.rank()] = x; };
  set(kCpu, cpu);
  set(kWall, wall);
  set(kOwned, Real(graph.n_owned_cells));
  set(kGhosts, Real(graph.n_cells() - graph.n_owned_cells));
  set(kNeighbours, d ? Real(d->exchange.n_neighbours()) : 0.0);
  set(kMessages, Real(sent.messages));
  set(kBytes, Real(sent.bytes));
  set(kExchanges, Real(sent.exchanges));
  set(kReductions, Real(sent.reductions));
  set(kWaitCpu, sent.wait_cpu_seconds);
  set(kWaitWall, sent.wait_wall_seconds);
  comm.sum_in_place(per);
  if (!comm.is_root()) return 0;
  auto column = [&](int what) {
    return std::vector<Real>(per.begin() + what * p, per.begin() + (what + 1) * p);
  };
  auto per_iteration = [&](int what) {
    std::vector<Real> v = column(what);
    for (Real& x : v) x /= std::max(iterations, 1);
    return v;
  };
  json j;
  j["run"] = "worker";
  j["solver"] = a.solver;
  j["ranks"] = p;
  j["cells"] = {a.nx, a.ny};
  j["velocities"] = a.nv * a.nv * a.nv;
  j["knudsen"] = a.kn;
  j["width_factor"] = a.width;
  j["converged"] = converged;
  j["iterations"] = iterations;
  j["levels"] = levels;
  j["heat_flow_top_W_per_m"] = heat_top;
  j["edge_cut"] = d ? d->partition.edge_cut : 0;
  j["imbalance"] = d ? d->partition.imbalance : 1.0;
  j["cpu_s"] = column(kCpu);
  j["wall_s"] = column(kWall);
  j["mpi_wait_cpu_s"] = column(kWaitCpu);
  j["mpi_wait_wall_s"] = column(kWaitWall);
  j["owned_cells"] = column(kOwned);
  j["ghost_cells"] = column(kGhosts);
  j["neighbours"] = column(kNeighbours);
  j["messages_per_iteration"] = per_iteration(kMessages);
  j["bytes_per_iteration"] = per_iteration(kBytes);
  j["exchanges_per_iteration"] = per_iteration(kExchanges);
  j["reductions_per_iteration"] = per_iteration(kReductions);
  j["load_average_start"] = load0;
  j["load_average_end"] = load_average();
  bench::emit(j);
  return 0;
}

std::string self_path() {
  char buf[4096];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) throw SolverError("cannot find this program's path");
  return std::string(buf, n);
}

// Runs one worker under mpirun -np p and returns its JSON line.
json launch(const std::string& mpirun, int p, const WorkerArgs& a) {
  std::ostringstream cmd;
  cmd << mpirun << " -np " << p << " " << self_path() << " --worker --solver " << a.solver
      << " --nx " << a.nx << " --ny " << a.ny << " --nv " << a.nv << " --kn " << a.kn << " --width "
      << a.width << " --tolerance " << a.tolerance;
  std::FILE* pipe = popen(cmd.str().c_str(), "r");
  if (!pipe) throw SolverError("cannot run: " + cmd.str());
  std::string out;
  char buf[4096];
  while (std::fgets(buf, sizeof buf, pipe)) out += buf;
  const int status = pclose(pipe);
  const auto start = out.find("{\"");
  if (status != 0 || start == std::string::npos)
    throw SolverError("worker failed (" + cmd.str() + "): " + out);
  return json::parse(out.substr(start, out.find('\n', start) - start));
}

double largest(const json& values) {
  double m = 0;
  for (const auto& v : values) m = std::max(m, v.get<double>());
  return m;
}

json scaling_row(const char* kind, const json& one, const json& many) {
  const int p = many["ranks"];
  const double t1 = largest(one["cpu_s"]), tp = largest(many["cpu_s"]);
  const double w1 = largest(one["wall_s"]), wp = largest(many["wall_s"]);
  const double it1 = one["iterations"], itp = many["iterations"];
  const bool strong = std::string(kind) == "strong";
  json j;
  j["run"] = kind;
  j["solver"] = many["solver"];
  j["cells_1"] = one["cells"];
  j["cells_P"] = many["cells"];
  j["ranks"] = p;
  j["iterations_1"] = it1;
  j["iterations_P"] = itp;
  j["cpu_s_1"] = t1;
  j["cpu_s_P"] = tp;
  j["wall_s_1"] = w1;
  j["wall_s_P"] = wp;
  // strong: S = T1 / TP, efficiency S / P; weak: efficiency T1 / TP.
  const double s = t1 / tp;
  j["speed_up_cpu"] = strong ? s : s * p;
  j["speed_up_wall"] = strong ? w1 / wp : w1 / wp * p;
  j["speed_up_iteration_normalised"] = (strong ? s : s * p) * itp / it1;
  j["efficiency_cpu"] = strong ? s / p : s;
  j["efficiency_iteration_normalised"] = (strong ? s / p : s) * itp / it1;
  // Outside the waits of the exchange layer: what the speed-up would be if communication
  // and waiting for the partner cost nothing (the compute part of the scaling).
  double tp_compute = 0, wait_share = 0;
  for (std::size_t r = 0; r < many["cpu_s"].size(); ++r) {
    const double c = many["cpu_s"][r].get<double>(), wcpu = many["mpi_wait_cpu_s"][r].get<double>();
    tp_compute = std::max(tp_compute, c - wcpu);
    wait_share = std::max(wait_share, wcpu / c);
  }
  j["cpu_s_P_outside_waits"] = tp_compute;
  j["mpi_wait_cpu_share"] = wait_share;
  j["speed_up_cpu_outside_waits"] = strong ? t1 / tp_compute : t1 / tp_compute * p;
  j["heat_flow_relative_difference"] = many["heat_flow_top_W_per_m"].get<double>() /
                                           one["heat_flow_top_W_per_m"].get<double>() /
                                           (strong ? 1.0 : double(p)) -
                                       1.0;
  j["load_average"] = many["load_average_end"];
  return j;
}

std::vector<int> parse_list(const std::string& s) {
  std::vector<int> v;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) v.push_back(std::stoi(item));
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench_gas_scaling: strong and weak scaling of COMET and the sequential solver"};
  bool worker = false;
  WorkerArgs w;
  std::string ranks = "1,2", cells = "50,100", solvers_list = "comet,sequential";
  std::string mpirun = "mpirun --allow-run-as-root --oversubscribe";
  int weak_cells = 50, nv = 8;
  Real kn_comet = 0.01, kn_sequential = 0.1;
  app.add_flag("--worker", worker, "one run under mpirun (the launcher's mode)");
  app.add_option("--solver", w.solver);
  app.add_option("--nx", w.nx);
  app.add_option("--ny", w.ny);
  app.add_option("--kn", w.kn);
  app.add_option("--width", w.width);
  app.add_option("--tolerance", w.tolerance);
  app.add_option("--nv", nv, "velocity points per direction");
  app.add_option("--ranks", ranks, "rank counts, the first is the reference (1)");
  app.add_option("--cells", cells, "strong scaling: n x n meshes");
  app.add_option("--weak-cells", weak_cells, "weak scaling: n x n cells per rank (0: skip)");
  app.add_option("--solvers", solvers_list, "comet,sequential");
  app.add_option("--kn-comet", kn_comet);
  app.add_option("--kn-sequential", kn_sequential);
  app.add_option("--mpirun", mpirun);
  CLI11_PARSE(app, argc, argv);
  w.nv = nv;
  try {
    if (worker) {
      MpiSession session(&argc, &argv);
      return run_worker(w);
    }
    std::vector<std::string> solvers;
    {
      std::stringstream in(solvers_list);
      std::string s;
      while (std::getline(in, s, ',')) solvers.push_back(s);
    }
    const std::vector<int> rank_counts = parse_list(ranks);
    for (const std::string& solver : solvers) {
      WorkerArgs a = w;
      a.solver = solver;
      a.kn = solver == "comet" ? kn_comet : kn_sequential;
      std::map<int, json> strong_reference;  // 1-rank runs by n
      for (int n : parse_list(cells)) {
        a.nx = a.ny = n;
        a.width = 1.0;
        const json one = launch(mpirun, rank_counts.front(), a);
        bench::emit(one);
        strong_reference[n] = one;
        for (std::size_t i = 1; i < rank_counts.size(); ++i) {
          const json many = launch(mpirun, rank_counts[i], a);
          bench::emit(many);
          bench::emit(scaling_row("strong", one, many));
        }
      }
      if (weak_cells > 0) {
        a.ny = weak_cells;
        json one;
        for (std::size_t i = 0; i < rank_counts.size(); ++i) {
          const int p = rank_counts[i];
          a.nx = weak_cells * p;
          a.width = p;
          // The reference is the strong-scaling run of the same mesh when there was one.
          const bool reuse = i == 0 && strong_reference.count(weak_cells) > 0;
          const json run = reuse ? strong_reference.at(weak_cells) : launch(mpirun, p, a);
          if (!reuse) bench::emit(run);
          if (i == 0)
            one = run;
          else
            bench::emit(scaling_row("weak", one, run));
        }
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_gas_scaling: %s\n", e.what());
    return 1;
  }
  return 0;
}

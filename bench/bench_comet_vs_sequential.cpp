// bench_comet_vs_sequential: COMET (point-coupled Gauss-Seidel + FAS agglomeration multigrid,
// physics/gas/comet) against the sequential source iteration (physics/gas/kinetic) on the two
// convergence problems of thesis ch. 5, one JSON line per (case, Kn) row with
// both solvers' iterations, wall times and the speed-up (thesis Tables 5.3-5.4).
//
//   heat_transfer  square of side L, diffuse top 327.78 K / bottom 273.15 K, specular sides
//   cavity         square of side L, all walls diffuse at 273.15 K, lid (top) at 10 m/s
// Argon (ESBGK, Pr = 2/3, mu = 2.117e-5 (T/273.15)^0.81 Pa s), gas initially at rest at
// 273.15 K and rho0 = 9.28e-6 kg/m^3 (0.528 Pa); L = lambda0 / Kn as in the thesis
// (Kn = 1, 0.1, 0.01 <-> L ~ 1.2 cm, 12 cm, 1.2 m); n x n cells (--cells, default 40; 80 as in
// the second mesh); nv^3 velocities over +-3.5 sqrt(2 R T0) (--nv, default 10).
// Both solvers stop at ||r||_2 / ||r_0||_2 <= 1e-6 of the same residual
// (kinetic_operator.hpp). Both domains are closed, so their steady states form a family by
// mass, which the steady equation leaves free: both solvers hold the initial mass
// (KineticOperator::restore_mass after every sweep / cycle) and converge to the same steady
// state: the row reports the max field differences (T over 54.63 K, rho over rho0, u over 10 m/s in
// the cavity or the thermal speed sqrt(2 R T0) in the heat transfer).
//
// COMET runs as COMET at every Kn here (--sequential-above-knudsen 0); with the library's
// default regime switch (0.2) the Kn = 1 rows run the sequential iteration (comet_method).
//
// Sweep cost: on the converged state, the CPU time of one COMET pass on the fine level per
// cell-ordinate update, against a streaming bound: 24 bytes per update (read f_c, write f_c,
// read the upwind neighbour's f once) over the memory bandwidth measured here by a triad
// a = b + s c on 3 x 64 MB arrays (24 bytes per element counted).
//
// Sample runs:
//   build/bench/bench_comet_vs_sequential                      # 40 x 40, Kn 1 0.1 0.01, both cases
//   build/bench/bench_comet_vs_sequential --cells 80 --kn 0.01 --cases heat_transfer
//   build/bench/bench_comet_vs_sequential --cells 10 --nv 8    # a quick check
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "core/error.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/gas/comet/comet_solver.hpp"
#include "physics/gas/kinetic/sequential_solver.hpp"

using namespace rfmems;
using json = nlohmann::json;

namespace {

constexpr Real kT0 = 273.15, kTHot = 327.78, kRho0 = 9.28e-6, kLid = 10.0;

struct Problem {
  FaceGraph graph;
  std::unique_ptr<KineticOperator> op;
  std::vector<Real> f0;
  Real length = 0;
};

// The case's operator and initial state (the driver's cases/gas_* files describe the same
// problems; built here directly so the bench depends on the library only).
std::unique_ptr<Problem> make_problem(const std::string& name, Real kn, int n, int nv,
                                      CollisionModel model) {
  auto p = std::make_unique<Problem>();
  const KineticGas gas = KineticGas::argon(model);
  p->length = gas.mean_free_path(kRho0, kT0) / kn;
  BoxSpec spec;
  spec.upper = Vec3(p->length, p->length, 0);
  spec.n[0] = spec.n[1] = n;
  p->graph = face_graph_of(make_structured_mesh(spec));
  std::vector<KineticBoundary> bcs;
  for (const std::string& patch : p->graph.patch_names) {
    if (name == "heat_transfer")
      bcs.push_back(patch == "top"      ? KineticBoundary::diffuse_wall(kTHot)
                    : patch == "bottom" ? KineticBoundary::diffuse_wall(kT0)
                                        : KineticBoundary::specular_wall());
    else if (name == "cavity")
      bcs.push_back(patch == "top" ? KineticBoundary::diffuse_wall(kT0, Vec3(kLid, 0, 0))
                                   : KineticBoundary::diffuse_wall(kT0));
    else
      throw InputError("unknown case '" + name + "' (heat_transfer | cavity)");
  }
  VelocityGrid grid = VelocityGrid::uniform(nv, nv, nv, 3.5 * gas.thermal_speed(kT0));
  p->op = std::make_unique<KineticOperator>(p->graph, std::move(grid), gas, std::move(bcs));
  p->f0.resize(p->op->size());
  p->op->initialize(p->f0, [](const Vec3&) { return GasState{kRho0, Vec3::Zero(), kT0}; });
  return p;
}

struct Fields {
  std::vector<Real> rho, T;
  std::vector<Vec3> u;
};

Fields fields(KineticOperator& op, const std::vector<Real>& f) {
  op.update_collision(f);
  Fields out;
  for (Index c = 0; c < op.n_owned_cells(); ++c) {
    out.rho.push_back(op.macro(c).rho);
    out.T.push_back(op.macro(c).T);
    out.u.push_back(op.macro(c).u);
  }
  return out;
}

// Triad bandwidth in bytes/s (best of 5), 24 bytes per element.
double triad_bandwidth() {
  const std::size_t n = std::size_t(8) << 20;  // 8 Mi doubles = 64 MB per array
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  double best = 1e300;
  for (int rep = 0; rep < 5; ++rep) {
    const double t0 = bench::now();
    const double s = 1.0 + 1e-3 * rep;
    for (std::size_t i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
    best = std::min(best, bench::now() - t0);
  }
  volatile double sink = a[n / 2];
  (void)sink;
  return 24.0 * double(n) / best;
}

// The 1-minute load average (the machine is shared: CPU-time ratios are the figures to quote).
double load_average() {
  double load = -1;
  if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf", &load) != 1) load = -1;
    std::fclose(f);
  }
  return load;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"COMET vs the sequential solver on heat transfer and cavity (JSON lines)"};
  int cells = 40, nv = 10;
  std::vector<Real> kns{1.0, 0.1, 0.01};
  std::vector<std::string> cases{"heat_transfer", "cavity"};
  std::string model_name = "esbgk", coupling_name = "conserved";
  double seq_max_seconds = 3600;
  bool skip_sequential = false, no_multigrid = false;
  int pre = 1, post = 1, symmetric = 1, coarse_symmetric = 1, coarsest = 4, min_coarse = 8;
  std::string cycle_name = "auto";
  Real tolerance = 1e-6, sequential_above_knudsen = 0, f_below_knudsen = 0.02;
  app.add_option("--cells", cells, "cells per side (40; 80 for the issue's fine mesh)");
  app.add_option("--nv", nv, "velocities per direction (10)");
  app.add_option("--kn", kns, "Knudsen numbers");
  app.add_option("--cases", cases, "heat_transfer and/or cavity");
  app.add_option("--model", model_name, "bgk | esbgk");
  app.add_option("--coupling", coupling_name,
                 "COMET point coupling: conserved | velocity (thesis)");
  app.add_option("--pre", pre, "COMET pre-smoothing sweeps");
  app.add_option("--post", post, "COMET post-smoothing sweeps");
  app.add_option("--tolerance", tolerance, "both solvers: ||r|| / ||r_0|| to reach (1e-6)");
  app.add_option("--sequential-above-knudsen", sequential_above_knudsen,
                 "COMET's regime switch (0: COMET at every Kn, the default here; the library's "
                 "default is 0.2)");
  app.add_option("--symmetric", symmetric, "COMET sweeps forward + backward (1) or forward (0)");
  app.add_option("--coarse-symmetric", coarse_symmetric,
                 "COMET coarse-level sweeps forward + backward (1) or forward (0)");
  app.add_option("--coarsest", coarsest, "COMET sweeps on the coarsest level");
  app.add_option("--cycle", cycle_name, "COMET cycle: auto (the library default) | V | W | F");
  app.add_option("--f-below-knudsen", f_below_knudsen,
                 "COMET cycle auto: F-cycles (one-pass coarse sweeps) below this Kn (0.02)");
  app.add_option("--min-coarse", min_coarse, "COMET: fewest cells on the coarsest level (8)");
  app.add_option("--seq-max-seconds", seq_max_seconds, "stop the sequential solver after this");
  app.add_flag("--skip-sequential", skip_sequential, "COMET only");
  app.add_flag("--no-multigrid", no_multigrid, "single-level COMET");
  CLI11_PARSE(app, argc, argv);
  const CollisionModel model = collision_model_from_name(model_name);
  const double bandwidth = triad_bandwidth();
  bench::emit(json{{"triad_bandwidth_GBps", bandwidth * 1e-9}});

  for (const std::string& name : cases)
    for (Real kn : kns) {
      json row{{"case", name},
               {"kn", kn},
               {"cells", cells},
               {"nv", nv},
               {"model", model_name},
               {"coupling", coupling_name},
               {"pre", pre},
               {"post", post},
               {"coarsest", coarsest},
               {"coarse_symmetric", coarse_symmetric},
               {"cycle", cycle_name},
               {"f_below_knudsen", f_below_knudsen},
               {"min_coarse", min_coarse}};
      auto p = make_problem(name, kn, cells, nv, model);
      KineticOperator& op = *p->op;
      row["length_m"] = p->length;
      const Real mass0 = op.total_mass(p->f0);

      std::vector<Real> f_seq = p->f0;
      if (!skip_sequential) {
        SequentialOptions so;
        so.tolerance = tolerance;
        const double t_start = bench::now();
        so.monitor = [&](int, Real) { return bench::now() - t_start < seq_max_seconds; };
        const double cpu0 = bench::cpu_now();
        const KineticSolveResult rs = solve_sequential(op, f_seq, so);
        row["seq_cpu_seconds"] = bench::cpu_now() - cpu0;
        row["seq_iterations"] = rs.iterations;
        row["seq_seconds"] = rs.seconds;
        row["seq_converged"] = rs.converged;
        row["seq_ratio"] = rs.residual_ratio;
        row["seq_mass_error"] = op.total_mass(f_seq) / mass0 - 1;
      }

      std::vector<Real> f = p->f0;
      CometOptions co;
      co.coupling = comet_coupling_from_name(coupling_name);
      co.multigrid = !no_multigrid;
      co.pre_sweeps = pre;
      co.post_sweeps = post;
      co.symmetric = symmetric != 0;
      co.coarse_symmetric = coarse_symmetric != 0;
      co.tolerance = tolerance;
      co.sequential_above_knudsen = sequential_above_knudsen;
      co.coarsest_sweeps = coarsest;
      co.cycle_shape = comet_cycle_from_name(cycle_name);
      co.min_coarse_cells = min_coarse;
      co.f_cycle_below_knudsen = f_below_knudsen;
      CometSolver comet(op, co);
      const double cpu0 = bench::cpu_now();
      const CometResult rc = comet.solve(f);
      row["comet_cpu_seconds"] = bench::cpu_now() - cpu0;
      row["comet_method"] = rc.method;
      row["comet_cycles"] = rc.cycles;
      row["comet_seconds"] = rc.wall_seconds;
      row["comet_converged"] = rc.converged;
      row["comet_ratio"] = rc.residual_ratio;
      row["comet_levels"] = rc.levels;
      row["comet_fine_sweep_equivalents"] = rc.fine_sweep_equivalents;
      row["comet_damped_steps"] = rc.damped_steps;
      row["comet_history"] = rc.history;
      row["comet_cycle_run"] = comet_cycle_name(rc.cycle_shape);
      row["comet_coarse_symmetric"] = rc.coarse_symmetric;
      row["comet_level_seconds"] = rc.level_seconds;
      row["comet_mass_error"] = op.total_mass(f) / mass0 - 1;
      if (!skip_sequential) {
        row["speedup"] = row["seq_seconds"].get<double>() / rc.wall_seconds;
        row["speedup_cpu"] =
            row["seq_cpu_seconds"].get<double>() / row["comet_cpu_seconds"].get<double>();
        const Fields a = fields(op, f_seq), b = fields(op, f);
        const Real u_scale = name == "cavity" ? kLid : op.gas().thermal_speed(kT0);
        Real dT = 0, drho = 0, du = 0;
        for (std::size_t c = 0; c < a.T.size(); ++c) {
          dT = std::max(dT, std::abs(a.T[c] - b.T[c]) / (kTHot - kT0));
          drho = std::max(drho, std::abs(a.rho[c] - b.rho[c]) / kRho0);
          du = std::max(du, (a.u[c] - b.u[c]).norm() / u_scale);
        }
        row["max_diff_T"] = dT;

        row["max_diff_rho"] = drho;
        row["max_diff_u"] = du;
      }

      // Cost of one fine-level pass on the converged state.
      op.update_collision(f);
      PointCoupledSmoother smoother(op, co.coupling);
      const double t0 = bench::now(), c0 = bench::cpu_now();
      const int passes = 2;
      for (int s = 0; s < passes; ++s) smoother.sweep(f, {}, s % 2 == 0);
      const double updates = passes * double(op.n_owned_cells()) * op.n_ordinates();
      const double per_update = (bench::cpu_now() - c0) / updates;
      row["sweep_ns_per_cell_ordinate"] = per_update * 1e9;  // CPU time
      row["sweep_wall_ns_per_cell_ordinate"] = (bench::now() - t0) / updates * 1e9;
      row["load_average_1min"] = load_average();
      row["streaming_bound_ns"] = 24.0 / bandwidth * 1e9;
      row["sweep_over_bound"] = per_update / (24.0 / bandwidth);
      bench::emit(row);
    }
  return 0;
}

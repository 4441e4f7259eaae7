// bench_amg_rigid_body_modes: does algebraic multigrid suit thin 3D structures once its
// interpolation fits the rigid-body rotations? One static solve of a 3D strip, K u = f, by GMRES
// (solvers/split_preconditioned_gmres.hpp, right-preconditioned, to --tolerance) on the
// operator's own (quadratic reconstruction) stiffness, preconditioned by one BoomerAMG V-cycle
// of the linear reconstruction's (the compact stencil, as the solid driver's multigrid on one
// rank), in two variants of solvers/boomer_amg.hpp:
//   unknown   the settings rfmems-solid uses: unknown-based interpolation, one level of
//             aggressive coarsening;
//   rotations AmgOptions::rigid_body_points at the cell centroids: nodal coarsening,
//             interpolation fitted to the rotations too (GM variant 2), no aggressive level.
// The strip is the creep benchmark's (physics/creep/continuum_plate_comparison.hpp): L = 240 um,
// L/h = --slenderness, width L/100, clamped at x = 0, a symmetry plane at x = L/2 (the half
// span, nx cells), 6e4 Pa on its top; nz cells through the thickness, 3 across. Per mesh and
// variant one JSON line: iterations, relative residual, AMG levels and operator complexity,
// set-up and solve CPU seconds, and the centre deflection against a sparse LU solve's.
//
//   build/bench/bench_amg_rigid_body_modes [--meshes "60,8;120,8;240,12;480,24"]
//       [--slenderness 60] [--tolerance 1e-8] [--no-lu]
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "physics/creep/continuum_plate_comparison.hpp"
#include "solvers/boomer_amg.hpp"
#include "solvers/sparse_lu.hpp"
#include "solvers/split_preconditioned_gmres.hpp"

using namespace rfmems;
using json = nlohmann::ordered_json;

int main(int argc, char** argv) {
  MpiSession mpi(&argc, &argv);  // hypre needs MPI (one rank here)
  CLI::App app{"BoomerAMG with and without the rigid-body rotations on a thin 3D strip"};
  std::string meshes_arg = "60,8;120,8;240,12;480,24";
  double slenderness = 60, tolerance = 1e-8;
  bool no_lu = false;
  app.add_option("--meshes", meshes_arg, "nx,nz;... (half span; 3 cells across)");
  app.add_option("--slenderness", slenderness, "L/h");
  app.add_option("--tolerance", tolerance, "GMRES relative residual");
  app.add_flag("--no-lu", no_lu, "skip the sparse LU reference");
  CLI11_PARSE(app, argc, argv);
  bench::emit(bench::run_header<json>("bench_amg_rigid_body_modes", argc, argv));

  FixedFixedCreepProblem problem;
  problem.slenderness = slenderness;
  problem.width = 0.01 * problem.length;
  problem.continuum_half_length = true;
  for (auto [nx, nz, unused] : bench::parse_meshes(meshes_arg, "--meshes")) {
    if (nx < 1 || nz < 1) throw InputError("--meshes: '" + meshes_arg + "' needs nx,nz;...");
    const ContinuumStrip strip = make_continuum_strip(problem, nx, nz, 3);
    const ContinuumStripStatics statics(strip);
    const Index n = statics.op.size(), probe = strip.centre_cell;
    Real w_lu = 0;
    if (!no_lu) {
      std::vector<Real> u = statics.load;
      SparseLu lu(statics.op.stiffness_pattern(), statics.stiffness);
      lu.solve_refined(u);
      w_lu = u[3 * probe + 1];
    }
    for (const bool rotations : {false, true}) {
      AmgOptions options;
      options.unknowns_per_cell = 3;
      if (rotations) {
        const std::span<const Vec3> centroids = strip.mesh.cell_centroids();
        options.rigid_body_points.assign(centroids.begin(), centroids.end());
      }
      const double t0 = bench::cpu_now();
      BoomerAmg amg(statics.compact.stiffness_pattern(), options);
      amg.setup(statics.compact_stiffness);
      const double t1 = bench::cpu_now();
      std::vector<Real> u(n, 0.0);
      SplitGmresOptions gmres;
      gmres.relative_tolerance = tolerance;
      gmres.krylov_dimension = 100;
      gmres.max_restarts = 30;
      const SplitGmresResult r = split_preconditioned_gmres(
          statics.op.stiffness_pattern(), statics.stiffness,
          [&amg](std::span<Real> z) { amg.apply(z, z); }, statics.load, u, gmres);
      const double t2 = bench::cpu_now();
      const AmgStats stats = amg.stats();
      json j{{"section", "strip"},
             {"mesh", {nx, nz, 3}},
             {"slenderness", slenderness},
             {"unknowns", n},
             {"variant", rotations ? "rotations" : "unknown"},
             {"iterations", r.iterations},
             {"converged", r.converged},
             {"relative_residual", r.relative_residual},
             {"levels", stats.levels},
             {"operator_complexity", stats.operator_complexity},
             {"setup_cpu_s", t1 - t0},
             {"solve_cpu_s", t2 - t1},
             {"w_centre", u[3 * probe + 1]}};
      if (!no_lu) j["w_centre_lu"] = w_lu;
      bench::emit(j);
    }
  }
}

// bench_creep_plate_vs_continuum: creep of the fixed-fixed strip of thesis sec. 4.6.1 (Tables
// 4.1-4.2) in the plate model (PlateCreepSystem) and in the continuum (ContinuumCreepSystem:
// the plane-stress section, and with --solid-meshes the 3D strip), each at a sequence of
// meshes, for the wall time of each model at equal accuracy of the plastic centre deflection
// after --hours (thesis, L/h = 60: plate 0.03 h against 97 h for its 3D model, > 3000x), and
// of the set-up and static solve at equal accuracy of the elastic deflection.
//
// Set-up (physics/creep/continuum_plate_comparison.hpp): L = 240 um, h = L/(L/h), E = 200 GPa,
// nu = 0.3, ends clamped, uniform q (Table 4.1: 6e4 Pa for L/h >= 30, 4e6 Pa at L/h = 10),
// plate width --width-ratio * L (default 0.01: the narrow strip the plane-stress section
// models), Table 4.1 creep law (A = 8.33e-6 /s, B = 1.8e8, m = n = 2, sigma_y0 = 1 GPa) or
// --law coble (sec. 4.6.2). IDA (adaptive BDF, --rtol, atol = 1e-2 rtol w_beam on every
// unknown: the strains are of the size of w in metres; 1e-4 failed at t = 0 on 81 x 3); the
// plate with its Schur-complement preconditioned SPGMR (the exact Jacobian solve), the
// continuum with GMRES and the block preconditioner of
// physics/creep/continuum_creep_preconditioner.hpp (the stiffness's LU; the full Jacobian never
// factorised), or with --continuum-solver direct a sparse LU of the full Jacobian (KLU, UMFPACK
// from IdaOptions::umfpack_from unknowns or --umfpack-from). --creep-stress: the diagnostic of
// ContinuumCreepSystem::set_creep_stress_mask ("xx,zz": the plate's bending-only creep).
// --half-length: the continuum on x <= L/2 with a symmetry plane at the centre, the same
// problem at half the unknowns (the 3D meshes that converge its creep deflection to 1 %).
//
// Accuracy: each model's mesh error, |w_p(mesh) - w_p(finest)| / |w_p(finest)| over its own
// mesh sequence (the two models converge to values that differ by the model difference,
// printed as plate_error = 1 - w_p,plate / w_p,continuum, the thesis's "percentage error").
// For --target, the cheapest mesh of each model within it (and every finer one) is
// chosen and the wall-time ratio reported: one summary line per continuum model.
//
// Output: one JSON object per line on stdout (each run, then a summary); progress on stderr.
//   bench_creep_plate_vs_continuum [--slenderness 60] [--load 6e4] [--hours 500] [--law table41]
//       [--rtol 1e-6] [--width-ratio 0.01] [--target 0.01] [--creep-stress xx,yy,zz,xy,yz,xz]
//       [--plate-meshes "21,3;41,3;81,5"] [--plane-meshes "241,8;481,12;481,16" | none]
//       [--solid-meshes "nx,nz,nw;..."] [--umfpack-from N] [--half-length] [--quick]
//       [--continuum-solver krylov | direct]
#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "physics/creep/continuum_plate_comparison.hpp"

using namespace rfmems;

namespace {

struct Run {
  std::string model;
  int n1, n2, n3;  // n3: cells across the width (3D), 0 for the plate and the section
  CreepRunResult result;
  bool half_length = false;  // a continuum on x <= L/2: n1 counts the half's cells
  std::string solver;        // the linear solver of IDA's Newton steps
};

// The process's peak resident memory so far (getrusage: KiB on Linux).
double max_rss_gib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / (1024.0 * 1024.0);
}

void print(const Run& r, Real slenderness) {
  std::printf(
      "{\"kind\": \"run\", \"model\": \"%s\", \"slenderness\": %g, \"mesh\": [%d, %d%s], "
      "\"unknowns\": %ld, \"w_elastic\": %.8e, \"w_plastic\": %.8e, \"steps\": %ld, "
      "\"newton_iters\": %ld, \"linear_iters\": %ld, \"linear_setups\": %ld, "
      "\"umfpack\": %s, \"elastic_s\": %.4f, \"wall_s\": %.4f, \"elastic_cpu_s\": %.4f, "
      "\"cpu_s\": %.4f, \"max_rss_gib\": %.2f, \"solver\": \"%s\"%s}\n",
      r.model.c_str(), slenderness, r.n1, r.n2,
      r.n3 > 0 ? (", " + std::to_string(r.n3)).c_str() : "", static_cast<long>(r.result.unknowns),
      r.result.w_elastic, r.result.w_plastic, r.result.stats.steps, r.result.stats.newton_iters,
      r.result.stats.linear_iters, r.result.stats.linear_setups,
      r.result.stats.umfpack ? "true" : "false", r.result.elastic_seconds, r.result.wall_seconds,
      r.result.elastic_cpu_seconds, r.result.cpu_seconds, max_rss_gib(), r.solver.c_str(),
      r.half_length ? ", \"half_length\": true" : "");
  std::fflush(stdout);
}

// Index of the cheapest run that, with every finer run, has quantity(run) within target of
// the finest.
template <class Quantity>
std::size_t cheapest_within(const std::vector<Run>& runs, Real target, Quantity&& quantity) {
  const Real reference = quantity(runs.back());
  std::size_t chosen = runs.size() - 1;
  for (std::size_t k = runs.size() - 1; k-- > 0;) {
    if (std::abs(quantity(runs[k]) / reference - 1) > target) break;
    chosen = k;
  }
  return chosen;
}

Real plastic(const Run& r) { return r.result.w_plastic; }
Real elastic(const Run& r) { return r.result.w_elastic; }

// The continuum model's comparison with the plate at equal accuracy: in the creep deflection
// (whole run) and in the elastic deflection (set-up and static solve).
void print_summary(const std::vector<Run>& plate_runs, const std::vector<Run>& runs,
                   const FixedFixedCreepProblem& problem, const std::string& law, Real hours,
                   Real width_ratio, const std::string& creep_stress, Real target) {
  const Run& plate = plate_runs[cheapest_within(plate_runs, target, plastic)];
  const Run& continuum = runs[cheapest_within(runs, target, plastic)];
  const Run& plate_static = plate_runs[cheapest_within(plate_runs, target, elastic)];
  const Run& continuum_static = runs[cheapest_within(runs, target, elastic)];
  const Real wp_plate = plate_runs.back().result.w_plastic, wp = runs.back().result.w_plastic;
  const Real we_plate = plate_runs.back().result.w_elastic, we = runs.back().result.w_elastic;
  std::printf(
      "{\"kind\": \"summary\", \"model\": \"%s\", \"slenderness\": %g, \"load\": %g, "
      "\"law\": \"%s\", \"hours\": %g, \"width_ratio\": %g, \"creep_stress\": \"%s\", "
      "\"target\": %g, \"w_plastic_plate\": %.8e, \"w_plastic_continuum\": %.8e, "
      "\"plate_error\": %.5f, \"plate_mesh\": [%d, %d], \"plate_wall_s\": %.4f, "
      "\"continuum_mesh\": [%d, %d, %d], \"continuum_wall_s\": %.4f, \"wall_ratio\": %.2f, "
      "\"w_elastic_plate\": %.8e, \"w_elastic_continuum\": %.8e, \"plate_elastic_error\": %.5f, "
      "\"plate_static_mesh\": [%d, %d], \"plate_static_s\": %.4f, "
      "\"continuum_static_mesh\": [%d, %d, %d], \"continuum_static_s\": %.4f, "
      "\"static_ratio\": %.2f, \"plate_cpu_s\": %.4f, \"continuum_cpu_s\": %.4f, \"cpu_ratio\": "
      "%.2f, "
      "\"plate_static_cpu_s\": %.4f, \"continuum_static_cpu_s\": %.4f, \"static_cpu_ratio\": "
      "%.2f}\n",
      runs.back().model.c_str(), problem.slenderness, problem.load, law.c_str(), hours, width_ratio,
      creep_stress.c_str(), target, wp_plate, wp, 1 - wp_plate / wp, plate.n1, plate.n2,
      plate.result.wall_seconds, continuum.n1, continuum.n2, continuum.n3,
      continuum.result.wall_seconds, continuum.result.wall_seconds / plate.result.wall_seconds,
      we_plate, we, 1 - we_plate / we, plate_static.n1, plate_static.n2,
      plate_static.result.elastic_seconds, continuum_static.n1, continuum_static.n2,
      continuum_static.n3, continuum_static.result.elastic_seconds,
      continuum_static.result.elastic_seconds / plate_static.result.elastic_seconds,
      plate.result.cpu_seconds, continuum.result.cpu_seconds,
      continuum.result.cpu_seconds / plate.result.cpu_seconds,
      plate_static.result.elastic_cpu_seconds, continuum_static.result.elastic_cpu_seconds,
      continuum_static.result.elastic_cpu_seconds / plate_static.result.elastic_cpu_seconds);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"creep: plate vs plane-stress and 3D continuum at equal accuracy"};
  FixedFixedCreepProblem problem;
  Real hours = 500, rtol = 1e-6, width_ratio = 0.01, target = 0.01;
  std::string law = "table41", plate_meshes_arg, plane_meshes_arg, solid_meshes_arg;
  long umfpack_from = 0;
  bool quick = false;
  Real atol_factor = 1e-2;
  std::string plate_solver = "spgmr";
  app.add_option("--slenderness", problem.slenderness, "L/h");
  app.add_option("--load", problem.load, "q [Pa]");
  app.add_option("--hours", hours, "creep time [h]");
  app.add_option("--law", law, "table41 | coble");
  app.add_option("--rtol", rtol, "IDA relative tolerance");
  app.add_option("--width-ratio", width_ratio, "plate width / L");
  app.add_option("--target", target, "relative mesh error of w_p for the timing comparison");
  app.add_option("--atol-factor", atol_factor, "atol = factor rtol w_beam");
  app.add_option("--plate-solver", plate_solver, "spgmr (Schur complement) | klu");
  app.add_option("--plate-meshes", plate_meshes_arg, "nx,ny;nx,ny;...");
  app.add_option("--plane-meshes", plane_meshes_arg, "nx,nz;nx,nz;... | none");
  app.add_option("--solid-meshes", solid_meshes_arg, "3D strip: nx,nz,nw;... (default: none)");
  app.add_option("--umfpack-from", umfpack_from,
                 "continuum IDA solves factorise with UMFPACK from this many unknowns (default "
                 "the library's)");
  app.add_option("--reconstruction-degree", problem.continuum_reconstruction_degree,
                 "continuum displacement reconstruction degree (0: cubic in 2D, quadratic in 3D)");
  app.add_option("--source-degree", problem.continuum_source_degree,
                 "continuum sigma_p reconstruction degree");
  std::string creep_stress = "xx,yy,zz,xy,yz,xz";
  app.add_option("--creep-stress", creep_stress,
                 "stress components the continuum's creep law sees (xx,zz: the plate's "
                 "bending-only assumption; default all)");
  app.add_flag("--half-length", problem.continuum_half_length,
               "continuum models on x <= L/2, a symmetry plane at the centre (nx: the half's "
               "cells)");
  std::string continuum_solver = "krylov";
  app.add_option("--continuum-solver", continuum_solver,
                 "krylov (GMRES, block preconditioner with the stiffness's LU; the default) | "
                 "direct (IDA's sparse LU of the full Jacobian)")
      ->check(CLI::IsMember({"direct", "krylov"}));
  app.add_flag("--quick", quick, "two coarse meshes per model (a smoke run)");
  CLI11_PARSE(app, argc, argv);
  using ContinuumSolver = ContinuumCreepSystem::LinearSolver;
  problem.continuum_linear_solver =
      continuum_solver == "krylov" ? ContinuumSolver::Krylov : ContinuumSolver::Direct;
  if (law == "coble") problem.law = CreepLaw{2.08e-10, 20, 1, 0.5, 0.7e9};
  problem.width = width_ratio * problem.length;
  const char* names[6] = {"xx", "yy", "zz", "xy", "yz", "xz"};
  for (int m = 0; m < 6; ++m)
    problem.continuum_creep_stress[m] = creep_stress.find(names[m]) != std::string::npos;
  const Real end = hours * 3600;

  // Plate: mid-surface nx x 3 (narrow strip), Simpson points fixed at 20 intervals (thesis).
  // Continuum: the section nx x nz, cells ~ (L/nx) x (h/nz), nx grown with nz; 3D (only when
  // --solid-meshes is given): nx x nz x nw, nw cells across the width.
  std::vector<std::array<int, 3>> plate_meshes = {{21, 3, 0}, {41, 3, 0}, {81, 5, 0}};
  std::vector<std::array<int, 3>> plane_meshes = {{241, 8, 0}, {481, 12, 0}, {481, 16, 0}};
  std::vector<std::array<int, 3>> solid_meshes;
  if (quick) {
    plate_meshes = {{21, 3, 0}, {41, 3, 0}};
    plane_meshes = {{61, 4, 0}, {121, 6, 0}};
  }
  if (!plate_meshes_arg.empty())
    plate_meshes = bench::parse_meshes(plate_meshes_arg, "--plate-meshes");
  if (plane_meshes_arg == "none")
    plane_meshes.clear();
  else if (!plane_meshes_arg.empty())
    plane_meshes = bench::parse_meshes(plane_meshes_arg, "--plane-meshes");
  if (!solid_meshes_arg.empty())
    solid_meshes = bench::parse_meshes(solid_meshes_arg, "--solid-meshes");

  // atol from the elastic deflection scale (beam theory, clamped-clamped, plane stress).
  const Real h = problem.thickness();
  const Real w_scale = problem.load * std::pow(problem.length, 4) / (32 * problem.E * h * h * h);
  IdaOptions options;
  options.rtol = rtol;
  options.atol = atol_factor * rtol * w_scale;
  if (umfpack_from > 0) options.umfpack_from = umfpack_from;

  std::vector<Run> plate_runs, plane_runs, solid_runs;
  for (auto [nx, ny, unused] : plate_meshes) {
    std::fprintf(stderr, "plate %d x %d ...\n", nx, ny);
    IdaOptions o = options;
    if (plate_solver == "spgmr") o.linear_solver = IdaOptions::LinearSolver::Spgmr;
    plate_runs.push_back(
        {"plate", nx, ny, 0, run_plate_creep(problem, nx, ny, 20, o, end), false, plate_solver});
    print(plate_runs.back(), problem.slenderness);
  }
  for (auto [nx, nz, unused] : plane_meshes) {
    std::fprintf(stderr, "plane stress %d x %d ...\n", nx, nz);
    plane_runs.push_back({"plane_stress", nx, nz, 0,
                          run_continuum_creep(problem, nx, nz, options, end),
                          problem.continuum_half_length, continuum_solver});
    print(plane_runs.back(), problem.slenderness);
  }
  for (auto [nx, nz, nw] : solid_meshes) {
    std::fprintf(stderr, "3D %d x %d x %d ...\n", nx, nz, nw);
    solid_runs.push_back({"3d", nx, nz, nw, run_continuum_creep(problem, nx, nz, options, end, nw),
                          problem.continuum_half_length, continuum_solver});
    print(solid_runs.back(), problem.slenderness);
  }
  for (const auto* runs : {&plane_runs, &solid_runs})
    if (!runs->empty())
      print_summary(plate_runs, *runs, problem, law, hours, width_ratio, creep_stress, target);
  return 0;
}

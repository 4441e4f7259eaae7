// bench_creep_plate_vs_continuum: creep of the fixed-fixed strip of thesis sec. 4.6.1 (Tables
// 4.1-4.2) in the plate model (PlateCreepSystem) and in the plane-stress continuum
// (ContinuumCreepSystem), each at a sequence of meshes, for the wall time of each model at
// equal accuracy of the plastic centre deflection after --hours (thesis, L/h = 60: plate
// 0.03 h against 97 h for its 3D model, > 3000x).
//
// Set-up (physics/creep/continuum_plate_comparison.hpp): L = 240 um, h = L/(L/h), E = 200 GPa,
// nu = 0.3, ends clamped, uniform q (Table 4.1: 6e4 Pa for L/h >= 30, 4e6 Pa at L/h = 10),
// plate width --width-ratio * L (default 0.01: the narrow strip the plane-stress section
// models), Table 4.1 creep law (A = 8.33e-6 /s, B = 1.8e8, m = n = 2, sigma_y0 = 1 GPa) or
// --law coble (sec. 4.6.2). IDA (adaptive BDF, --rtol, atol = 1e-2 rtol w_beam on every
// unknown: the strains are of the size of w in metres; 1e-4 failed at t = 0 on 81 x 3); the
// plate with its Schur-complement preconditioned SPGMR (the exact Jacobian solve), the
// continuum with KLU on the full Jacobian. --creep-stress: the diagnostic of
// ContinuumCreepSystem::set_creep_stress_mask ("xx,zz": the plate's bending-only creep).
//
// Accuracy: each model's mesh error, |w_p(mesh) - w_p(finest)| / |w_p(finest)| over its own
// mesh sequence (the two models converge to values that differ by the model difference,
// printed as plate_error = 1 - w_p,plate / w_p,continuum, the thesis's "percentage error").
// For --target, the cheapest mesh of each model within it (and every finer one) is
// chosen and the wall-time ratio reported.
//
// Output: one JSON object per line on stdout (each run, then a summary); progress on stderr.
//   bench_creep_plate_vs_continuum [--slenderness 60] [--load 6e4] [--hours 500] [--law table41]
//       [--rtol 1e-6] [--width-ratio 0.01] [--target 0.01] [--creep-stress xx,yy,zz,xy]
//       [--plate-meshes "21,3;41,3;81,5"] [--plane-meshes "241,8;481,12;481,16"] [--quick]
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "physics/creep/continuum_plate_comparison.hpp"

using namespace rfmems;

namespace {

struct Run {
  std::string model;
  int n1, n2;
  CreepRunResult result;
};

void print(const Run& r, Real slenderness) {
  std::printf(
      "{\"kind\": \"run\", \"model\": \"%s\", \"slenderness\": %g, \"mesh\": [%d, %d], "
      "\"unknowns\": %ld, \"w_elastic\": %.8e, \"w_plastic\": %.8e, \"steps\": %ld, "
      "\"newton_iters\": %ld, \"linear_iters\": %ld, \"wall_s\": %.4f}\n",
      r.model.c_str(), slenderness, r.n1, r.n2, static_cast<long>(r.result.unknowns),
      r.result.w_elastic, r.result.w_plastic, r.result.stats.steps, r.result.stats.newton_iters,
      r.result.stats.linear_iters, r.result.wall_seconds);
  std::fflush(stdout);
}

// Index of the cheapest run that, with every finer run, is within target of the finest.
std::size_t cheapest_within(const std::vector<Run>& runs, Real target) {
  const Real reference = runs.back().result.w_plastic;
  std::size_t chosen = runs.size() - 1;
  for (std::size_t k = runs.size() - 1; k-- > 0;) {
    if (std::abs(runs[k].result.w_plastic / reference - 1) > target) break;
    chosen = k;
  }
  return chosen;
}

// "nx,ny;nx,ny" -> pairs.
std::vector<std::pair<int, int>> parse_meshes(const std::string& text) {
  std::vector<std::pair<int, int>> out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    const std::string item = text.substr(start, end - start);
    const std::size_t comma = item.find(',');
    out.push_back({std::stoi(item.substr(0, comma)), std::stoi(item.substr(comma + 1))});
    start = end + 1;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"creep: plate vs plane-stress continuum at equal accuracy"};
  FixedFixedCreepProblem problem;
  Real hours = 500, rtol = 1e-6, width_ratio = 0.01, target = 0.01;
  std::string law = "table41", plate_meshes_arg, plane_meshes_arg;
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
  app.add_option("--plane-meshes", plane_meshes_arg, "nx,nz;nx,nz;...");
  app.add_option("--source-degree", problem.continuum_source_degree,
                 "continuum sigma_p reconstruction degree");
  std::string creep_stress = "xx,yy,zz,xy";
  app.add_option("--creep-stress", creep_stress,
                 "stress components the continuum's creep law sees (xx,zz: the plate's "
                 "bending-only assumption; default all)");
  app.add_flag("--quick", quick, "two coarse meshes per model (a smoke run)");
  CLI11_PARSE(app, argc, argv);
  if (law == "coble") problem.law = CreepLaw{2.08e-10, 20, 1, 0.5, 0.7e9};
  problem.width = width_ratio * problem.length;
  const char* names[6] = {"xx", "yy", "zz", "xy", "yz", "xz"};
  for (int m = 0; m < 6; ++m)
    problem.continuum_creep_stress[m] = creep_stress.find(names[m]) != std::string::npos;
  const Real end = hours * 3600;

  // Plate: mid-surface nx x 3 (narrow strip), Simpson points fixed at 20 intervals (thesis).
  // Continuum: the section nx x nz, cells ~ (L/nx) x (h/nz), nx grown with nz.
  std::vector<std::pair<int, int>> plate_meshes = {{21, 3}, {41, 3}, {81, 5}};
  std::vector<std::pair<int, int>> plane_meshes = {{241, 8}, {481, 12}, {481, 16}};
  if (quick) {
    plate_meshes = {{21, 3}, {41, 3}};
    plane_meshes = {{61, 4}, {121, 6}};
  }
  if (!plate_meshes_arg.empty()) plate_meshes = parse_meshes(plate_meshes_arg);
  if (!plane_meshes_arg.empty()) plane_meshes = parse_meshes(plane_meshes_arg);

  // atol from the elastic deflection scale (beam theory, clamped-clamped, plane stress).
  const Real h = problem.thickness();
  const Real w_scale = problem.load * std::pow(problem.length, 4) / (32 * problem.E * h * h * h);
  IdaOptions options;
  options.rtol = rtol;
  options.atol = atol_factor * rtol * w_scale;

  std::vector<Run> plate_runs, plane_runs;
  for (auto [nx, ny] : plate_meshes) {
    std::fprintf(stderr, "plate %d x %d ...\n", nx, ny);
    IdaOptions o = options;
    if (plate_solver == "spgmr") o.linear_solver = IdaOptions::LinearSolver::Spgmr;
    plate_runs.push_back({"plate", nx, ny, run_plate_creep(problem, nx, ny, 20, o, end)});
    print(plate_runs.back(), problem.slenderness);
  }
  for (auto [nx, nz] : plane_meshes) {
    std::fprintf(stderr, "plane stress %d x %d ...\n", nx, nz);
    plane_runs.push_back(
        {"plane_stress", nx, nz, run_continuum_creep(problem, nx, nz, options, end)});
    print(plane_runs.back(), problem.slenderness);
  }
  const Run& plate = plate_runs[cheapest_within(plate_runs, target)];
  const Run& plane = plane_runs[cheapest_within(plane_runs, target)];
  const Real wp_plate = plate_runs.back().result.w_plastic,
             wp_plane = plane_runs.back().result.w_plastic;
  std::printf(
      "{\"kind\": \"summary\", \"slenderness\": %g, \"load\": %g, \"law\": \"%s\", \"hours\": %g, "
      "\"width_ratio\": %g, \"creep_stress\": \"%s\", \"target\": %g, \"w_plastic_plate\": %.8e, "
      "\"w_plastic_plane\": %.8e, "
      "\"plate_error\": %.5f, \"plate_mesh\": [%d, %d], \"plate_wall_s\": %.4f, "
      "\"plane_mesh\": [%d, %d], \"plane_wall_s\": %.4f, \"wall_ratio\": %.2f}\n",
      problem.slenderness, problem.load, law.c_str(), hours, width_ratio, creep_stress.c_str(),
      target, wp_plate, wp_plane, 1 - wp_plate / wp_plane, plate.n1, plate.n2,
      plate.result.wall_seconds, plane.n1, plane.n2, plane.result.wall_seconds,
      plane.result.wall_seconds / plate.result.wall_seconds);
  return 0;
}

// bench_creep_linear_solvers: the linear solve inside implicit plate creep (IDA), KLU on the
// full Jacobian against SPGMR preconditioned by the exact Schur-complement solve
// (physics/creep/plate_creep_schur_complement.hpp), on the 500 h fixed-fixed plate creep of
// thesis sec. 4.6.1 (bench_creep_support.hpp) for meshes 21 x 5, 41 x 11 and the thesis's
// 81 x 21, the Table 4.1 law (L/h = 60, q = 60 kPa) and the Coble law (L/h = 60, q = 1.2 MPa).
//
// Sample runs:
//   build/bench/bench_creep_linear_solvers                          # all meshes, both laws
//   build/bench/bench_creep_linear_solvers --mesh 21x5 --solver klu --cap 120
//
// Per run one JSON line: mesh, law, solver, rtol, steps, Newton and Krylov iterations,
// preconditioner setups, residual evaluations, w_el, w_p(500 h), wall seconds. A KLU run past
// --cap wall-seconds is stopped at the next decade of time and reported incomplete.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_creep_support.hpp"
#include "bench_support.hpp"

using namespace rfmems;
using Json = nlohmann::ordered_json;

int main(int argc, char** argv) {
  CLI::App app{"implicit plate creep: KLU vs Schur-complement linear solves"};
  std::vector<std::string> meshes{"21x5", "41x11", "81x21"}, laws{"table41", "coble"},
      solvers{"schur", "klu"};
  double rtol = 1e-6, cap = 300, hours = 500;
  std::vector<double> lags{0};
  app.add_option("--mesh", meshes, "meshes NXxNY");
  app.add_option("--law", laws, "table41 and/or coble");
  app.add_option("--solver", solvers, "schur and/or klu");
  app.add_option("--rtol", rtol, "IDA relative tolerance");
  app.add_option("--cap", cap, "wall-seconds after which a run is stopped");
  app.add_option("--hours", hours, "simulated time [h]");
  app.add_option("--lag", lags, "Schur refactor tolerances (0: exact at every setup)");
  CLI11_PARSE(app, argc, argv);

  for (const std::string& mesh : meshes) {
    int nx = 0, ny = 0;
    if (std::sscanf(mesh.c_str(), "%dx%d", &nx, &ny) != 2) throw InputError("--mesh NXxNY");
    for (const std::string& law : laws) {
      const Real load = law == "coble" ? 1.2e6 : 6e4;
      for (const std::string& solver : solvers)
        for (double lag : solver == "schur" ? lags : std::vector<double>{0}) {
          auto plate = bench::make_creep_plate(60, load, bench::creep_law_by_name(law), nx, ny);
          const auto r = bench::run_creep_implicit(*plate, rtol, solver == "schur",
                                                   hours * bench::kHour, cap, lag);
          Json j;
          j["bench"] = "creep_linear_solvers";
          j["mesh"] = mesh;
          j["unknowns"] = plate->system->size();
          j["law"] = law;
          j["solver"] = solver;
          j["refactor_tolerance"] = lag;
          j["rtol"] = rtol;
          j["complete"] = r.complete;
          j["t_reached_h"] = r.t_reached / bench::kHour;
          bench::add_integrator_stats(j, r.stats);
          j["linear_iters"] = r.stats.linear_iters;
          j["preconditioner_setups"] = r.stats.preconditioner_setups;
          j["schur_factorizations"] = r.factorizations;
          j["w_elastic"] = r.w_elastic;
          j["w_plastic"] = r.w_plastic;
          j["wall_s"] = r.wall;
          j["cpu_s"] = r.cpu;
          bench::emit(j);
        }
    }
  }
}

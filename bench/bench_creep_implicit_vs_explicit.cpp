// bench_creep_implicit_vs_explicit: 500 h creep of the fixed-fixed plate of thesis sec. 4.6.1
// (bench_creep_support.hpp: L/h = 60, clamped short edges), implicit IDA against the thesis's
// explicit Euler (ExplicitCreepIntegrator) at equal final accuracy (the goal:
// implicit >= 20x faster).
//
//   reference  IDA (Schur-preconditioned SPGMR) at --ref-rtol (1e-9): w_p,ref(500 h)
//   implicit   IDA at each --rtol: error e = |w_p / w_p,ref - 1|, steps, CPU and wall seconds
//   explicit   Euler at dt = 1 h (the thesis's setting, as-is), then dt = 1 h / 4^k until its
//              error is below the implicit run's or the next run is predicted to take longer
//              than --cap CPU seconds (cost per step x steps)
//   summary    per implicit run: the explicit dt giving the same error (log-log interpolation
//              between the bracketing explicit runs; beyond the last run, extrapolated with the
//              observed order of the last two, and marked so), its cost (CPU seconds per step
//              of the explicit runs x 500 h / dt: measured if bracketed, else predicted), and
//              the ratio explicit / implicit CPU time.
// Laws: coble (sec. 4.6.2, q = 1.2 MPa: mild, Euler at 1 h is accurate) and table41 (Table 4.1,
// q = 60 kPa: the hardening rate Jacobian ~ -70 /s at t = 0 makes Euler at 1 h overshoot).
//
// Sample runs:
//   build/bench/bench_creep_implicit_vs_explicit                        # 41 x 11, both laws
//   build/bench/bench_creep_implicit_vs_explicit --mesh 81x21 --law coble --cap 600
//
// Output: one JSON object per run and one per summary line (stdout); progress on stderr.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_creep_support.hpp"
#include "bench_support.hpp"

using namespace rfmems;
using Json = nlohmann::ordered_json;

namespace {

struct ExplicitPoint {
  Real dt, error;
  double cpu, cpu_per_step;
};

Json run_json(const std::string& law, const std::string& mesh, const std::string& kind,
              const bench::CreepRun& r, Real error) {
  Json j;
  j["bench"] = "creep_implicit_vs_explicit";
  j["law"] = law;
  j["mesh"] = mesh;
  j["run"] = kind;
  j["steps"] = r.steps;
  j["w_elastic"] = r.w_elastic;
  j["w_plastic"] = r.w_plastic;
  j["error"] = error;
  j["cpu_s"] = r.cpu;
  j["wall_s"] = r.wall;
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"500 h plate creep: implicit IDA vs explicit Euler at equal accuracy"};
  std::string mesh = "41x11";
  std::vector<std::string> laws{"coble", "table41"};
  std::vector<double> rtols{1e-4, 1e-5, 1e-6};
  double ref_rtol = 1e-9, cap = 300, hours = 500;
  app.add_option("--mesh", mesh, "mesh NXxNY");
  app.add_option("--law", laws, "coble and/or table41");
  app.add_option("--rtol", rtols, "implicit relative tolerances");
  app.add_option("--ref-rtol", ref_rtol, "reference run's relative tolerance");
  app.add_option("--cap", cap, "CPU seconds beyond which an explicit run is not started");
  app.add_option("--hours", hours, "simulated time [h]");
  CLI11_PARSE(app, argc, argv);
  int nx = 0, ny = 0;
  if (std::sscanf(mesh.c_str(), "%dx%d", &nx, &ny) != 2) throw InputError("--mesh NXxNY");
  const Real end = hours * bench::kHour;

  for (const std::string& law_name : laws) {
    const Real load = law_name == "coble" ? 1.2e6 : 6e4;
    auto plate = bench::make_creep_plate(60, load, bench::creep_law_by_name(law_name), nx, ny);
    const auto reference = bench::run_creep_implicit(*plate, ref_rtol, true, end);
    const Real w_ref = reference.w_plastic;
    auto error = [&](const bench::CreepRun& r) { return std::abs(r.w_plastic / w_ref - 1); };
    bench::emit(run_json(law_name, mesh, "reference", reference, 0.0));

    std::vector<std::pair<Real, bench::CreepRun>> implicit;
    for (double rtol : rtols) {
      const auto r = bench::run_creep_implicit(*plate, rtol, true, end);
      Json j = run_json(law_name, mesh, "implicit", r, error(r));
      j["rtol"] = rtol;
      bench::add_integrator_stats(j, r.stats);
      bench::emit(j);
      implicit.push_back({rtol, r});
    }
    Real target = 1e300;  // the smallest implicit error: explicit refines down to it
    for (const auto& [rtol, r] : implicit) target = std::min(target, error(r));

    std::vector<ExplicitPoint> euler;
    for (Real dt = bench::kHour;; dt /= 4) {
      if (!euler.empty() && euler.back().cpu_per_step * (end / dt) > cap) break;
      std::cerr << law_name << ": explicit dt = " << dt << " s\n";
      const auto r = bench::run_creep_explicit(*plate, dt, end);
      Json j = run_json(law_name, mesh, "explicit", r, error(r));
      j["dt_s"] = dt;
      bench::emit(j);
      euler.push_back({dt, error(r), r.cpu, r.cpu / static_cast<double>(r.steps)});
      if (error(r) <= target) break;
    }

    // Explicit dt and CPU time at each implicit run's error.
    for (const auto& [rtol, r] : implicit) {
      const Real e = error(r);
      Json j;
      j["bench"] = "creep_implicit_vs_explicit";
      j["law"] = law_name;
      j["mesh"] = mesh;
      j["run"] = "summary";
      j["rtol"] = rtol;
      j["implicit_error"] = e;
      j["implicit_steps"] = r.steps;
      j["implicit_cpu_s"] = r.cpu;
      j["implicit_wall_s"] = r.wall;
      j["explicit_1h_error"] = euler.front().error;
      j["explicit_1h_cpu_s"] = euler.front().cpu;
      j["ratio_at_1h"] = euler.front().cpu / r.cpu;
      // The first explicit run at least as accurate, interpolated with its predecessor.
      std::size_t k = 0;
      while (k < euler.size() && euler[k].error > e) ++k;
      Real dt;
      bool measured = k < euler.size();
      if (k == 0) {
        dt = euler[0].dt;  // Euler at 1 h is already as accurate: no finer dt needed
      } else {
        const auto& a = euler[std::min(k, euler.size() - 1) - 1];
        const auto& b = euler[std::min(k, euler.size() - 1)];
        const Real order = std::log(a.error / b.error) / std::log(a.dt / b.dt);
        j["explicit_observed_order"] = order;
        dt = b.dt * std::pow(e / b.error, 1 / order);
      }
      const double cpu = euler.back().cpu_per_step * std::ceil(end / dt);
      j["explicit_dt_s"] = dt;
      j["explicit_steps"] = std::ceil(end / dt);
      j["explicit_cpu_s"] = k == 0 ? euler[0].cpu : cpu;
      j["explicit_cost"] = measured ? "measured (interpolated)" : "predicted (extrapolated)";
      j["ratio"] = (k == 0 ? euler[0].cpu : cpu) / r.cpu;
      bench::emit(j);
    }
  }
}

// bench_pullin_models: cost of the pull-in voltage of the fixed-fixed switch (L = 400 um,
// h = 4 um, E = 200 GPa, nu = 0.31, gap 3.75 um, electrode under the whole length) with the
// two structural + electrostatic models, at matched accuracy, and the time of the default
// case's complete dynamic study.
//
//   plate + parallel-plate  cases/switch_plate (Mindlin-Reissner plate, 40 um wide strip,
//                           p = eps0 V^2 / (2 g^2) per cell), no gas;
//   plane + Laplace         cases/switch_plane_laplace (plane stress beam, FV Laplace field in
//                           a gap mesh that follows the beam, strongly coupled with Aitken).
//
// 1. Quasi-static V_PI (the fold of the displacement-controlled curve): plate by KINSOL
//    (coupling/quasi_static_pull_in.hpp), plane + Laplace by the Aitken iteration
//    (coupling/laplace_pull_in.hpp). Both with the same sampling (20 points to 0.6 g0, fold to
//    0.01 V) on mesh sequences refined by 2 in every direction (plate nx x nx/10; beam
//    nx x nx/12.5 with gap_cells = 2 ny). Error of each mesh: against the model's finest mesh
//    and against the Richardson value of its three finest (observed order p from them).
// 2. Dynamic V_PI (step voltage from rest, bisection on V between 0.8 and 1.02 x the model's
//    own quasi-static V_PI, no gas, IDA rtol 1e-3, atol 1e-4 g0, BDF orders <= 2, contact at
//    2 % of g0, end 40 us): a plane beam + Laplace dynamic model is not implemented, so the
//    plane beam here is the same case with electrostatics: parallel_plate (the pull_in_study
//    does the same for a laplace scene's dynamic study). Plate (20, 40, 80 cells long) vs
//    plane + parallel-plate (25, 50, 100), bisection to --dyn-tolerance (0.1 V). The
//    three-mesh Richardson value is reported as computed; with a pre-asymptotic coarsest mesh
//    (the 25 x 2 beam) it is meaningless (docs/pull-in.md).
// 2b. Dynamic V_PI with the full field (--sections laplace_dynamic; docs/pull-in.md, "Plate +
// parallel plate against plane + Laplace"):
//    plane + Laplace (coupling/laplace_dynamic_switch.hpp: the field recomputed once per IDA
//    step, gap-scaled lagged load inside the step; beams nx x nx/12.5, gap cells 2 ny) against
//    the plate + parallel-plate (monolithic IDA), the same bisection (0.8-1.02 x each model's
//    own quasi-static V_PI, to --laplace-dyn-tolerance) and the same IDA settings for both:
//    rtol --laplace-dyn-rtol (1e-4), order <= 2, per-kind error weights (state_tolerances.hpp:
//    atol rtol g0 on displacements, rtol g0 omega_1 on velocities, omega_1 = 2 pi 131 kHz, the
//    measured first mode, docs/pull-in.md). The scalar atol 1e-4 g0 of item 2 puts 3.75e-10 m/s on
//    the velocities and makes the plane beam take ~5500 steps per run (measured on 50 x 4),
//    each with a field solve. Accuracy of each model against its own finer mesh.
// 3. The default case (cases/switch_plate/case.yaml as the driver runs it: plate 40 x 4 +
//    parallel-plate + Reynolds gas at 1 atm; quasi-static curve, then bisection to 0.5 V
//    between 0.8 and 1.02 x the quasi-static V_PI): wall and CPU time of the scene build, the
//    quasi-static trace and the bisection; also with gas.model=none. The process is
//    single-threaded (KLU, KINSOL, IDA serial), so its CPU time is the one-core time.
//
// Matched accuracy: for each target error (1 %, 0.5 %, 0.1 %), the cheapest mesh of each model
// whose error against its own Richardson value is within it; wall time of each and ratio.
//
// Output: one JSON object per line on stdout; progress on stderr.
//   bench_pullin_models [--quick] [--plate-nx 20 40 80 160] [--plane-nx 50 100 200]
//                       [--sections default quasi_static dynamic laplace_dynamic]
#include <time.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "bench_switch_scene.hpp"
#include "coupling/dynamic_pull_in.hpp"
#include "coupling/field_coupled_structure.hpp"
#include "coupling/pull_in_study.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/switch_scene.hpp"
#include "coupling/switch_system.hpp"
#include "io/case_file.hpp"
#include "physics/elasticity/elasticity_scene.hpp"

using namespace rfmems;
using OJson = nlohmann::ordered_json;  // rfmems::Json is unordered

namespace {

using namespace rfmems::bench;

struct Timer {
  double wall0 = now(), cpu0 = cpu_now();
  double wall() const { return now() - wall0; }
  double cpu() const { return cpu_now() - cpu0; }
};

// The 1-minute load average (/proc/loadavg), recorded beside each timing.
double load_average_1min() {
  double load = -1;
  if (FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf", &load) != 1) load = -1;
    std::fclose(f);
  }
  return load;
}

std::string cells(int nx, int ny) {
  return "mesh.cells=[" + std::to_string(nx) + "," + std::to_string(ny) + "]";
}

QuasiStaticOptions sampling() {
  QuasiStaticOptions o;
  o.n_points = 20;
  o.max_fraction = 0.6;
  o.voltage_tolerance = 0.01;
  return o;
}

DynamicOptions dynamic_options(double gap) {
  DynamicOptions o;
  o.end_time = 40e-6;
  o.contact_gap = 0.02 * gap;
  o.ida.rtol = 1e-3;
  o.ida.atol = 1e-4 * gap;
  o.ida.max_order = 2;
  o.ida.max_steps = 10000000;
  return o;
}

struct Point {
  std::string mesh;
  double cost_measure = 0;  // cells (for reporting)
  double value = 0, wall = 0, cpu = 0;
};

// Errors of a mesh sequence (coarse to fine) against its finest value and against the
// Richardson extrapolation of its three finest; returns the Richardson value (NaN if < 3).
double sequence_errors(std::vector<Point>& seq, OJson& out) {
  const std::size_t n = seq.size();
  double rich = std::numeric_limits<double>::quiet_NaN(), p = rich;
  if (n >= 3) {
    const double v1 = seq[n - 3].value, v2 = seq[n - 2].value, v3 = seq[n - 1].value;
    const double ratio = (v1 - v2) / (v2 - v3);
    if (ratio > 1) {
      p = std::log(ratio) / std::log(2.0);
      rich = v3 + (v3 - v2) / (std::pow(2.0, p) - 1);
    }
  }
  out["observed_order"] = p;
  out["richardson_value"] = rich;
  OJson rows = OJson::array();
  for (const Point& pt : seq)
    rows.push_back({{"mesh", pt.mesh},
                    {"value", pt.value},
                    {"error_vs_finest", std::abs(pt.value / seq.back().value - 1)},
                    {"error_vs_richardson",
                     std::isnan(rich) ? OJson(nullptr) : OJson(std::abs(pt.value / rich - 1))},
                    {"wall_s", pt.wall},
                    {"cpu_s", pt.cpu}});
  out["sequence"] = rows;
  return rich;
}

// The cheapest point whose error against `ref` is within target (NaN wall if none).
const Point* cheapest_within(const std::vector<Point>& seq, double ref, double target) {
  const Point* best = nullptr;
  for (const Point& pt : seq)
    if (std::abs(pt.value / ref - 1) <= target && (!best || pt.cpu < best->cpu)) best = &pt;
  return best;
}

OJson matched(const std::vector<Point>& a, double ref_a, const std::vector<Point>& b, double ref_b,
              const char* name_a, const char* name_b) {
  OJson out = OJson::array();
  for (double target : {1e-2, 5e-3, 1e-3}) {
    const Point* pa = cheapest_within(a, ref_a, target);
    const Point* pb = cheapest_within(b, ref_b, target);
    OJson t{{"target", target}};
    t[name_a] =
        pa ? OJson{{"mesh", pa->mesh}, {"wall_s", pa->wall}, {"cpu_s", pa->cpu}} : OJson(nullptr);
    t[name_b] =
        pb ? OJson{{"mesh", pb->mesh}, {"wall_s", pb->wall}, {"cpu_s", pb->cpu}} : OJson(nullptr);
    if (pa && pb) {
      t["ratio_wall"] = pb->wall / pa->wall;
      t["ratio_cpu"] = pb->cpu / pa->cpu;
    }
    out.push_back(t);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Plate + parallel-plate vs plane + Laplace pull-in at matched accuracy, and the "
      "time of the default dynamic study (JSON lines)"};
  std::string cases = default_cases_dir();
  std::vector<int> plate_nx{20, 40, 80, 160}, plane_nx{50, 100, 200};
  std::vector<int> dyn_plate_nx{20, 40, 80}, dyn_plane_nx{25, 50, 100};
  double dyn_tolerance = 0.1;
  std::vector<int> laplace_plate_nx{40, 80}, laplace_plane_nx{50, 100};
  double laplace_tolerance = 0.1, laplace_rtol = 1e-4;
  std::vector<std::string> sections{"default", "quasi_static", "dynamic", "laplace_dynamic"};
  bool quick = false;
  app.add_option("--cases", cases, "the repository's cases/ directory");
  app.add_option("--plate-nx", plate_nx, "plate meshes nx (ny = nx/10), quasi-static");
  app.add_option("--plane-nx", plane_nx,
                 "beam meshes nx (ny = nx/12.5, gap cells 2 ny), quasi-static");
  app.add_option("--dyn-plate-nx", dyn_plate_nx, "plate meshes, dynamic");
  app.add_option("--dyn-plane-nx", dyn_plane_nx, "beam meshes, dynamic (parallel-plate)");
  app.add_option("--dyn-tolerance", dyn_tolerance, "bisection tolerance of the mesh studies [V]");
  app.add_option("--laplace-plate-nx", laplace_plate_nx, "plate meshes of sec. 2b");
  app.add_option("--laplace-plane-nx", laplace_plane_nx, "plane + Laplace meshes of sec. 2b");
  app.add_option("--laplace-dyn-tolerance", laplace_tolerance, "bisection tolerance, sec. 2b [V]");
  app.add_option("--laplace-dyn-rtol", laplace_rtol, "IDA rtol of sec. 2b");
  app.add_option("--sections", sections, "default quasi_static dynamic laplace_dynamic");
  app.add_flag("--quick", quick, "smoke run: two coarse meshes per model");
  CLI11_PARSE(app, argc, argv);
  if (quick) {
    plate_nx = {20, 40};
    plane_nx = {50};
    dyn_plate_nx = {20};
    dyn_plane_nx = {50};
    dyn_tolerance = 0.5;
    laplace_plate_nx = {20};
    laplace_plane_nx = {25};
    laplace_tolerance = 0.5;
  }
  auto wanted = [&](const std::string& name) {
    return std::find(sections.begin(), sections.end(), name) != sections.end();
  };
  const std::string plate_case = cases + "/switch_plate/case.yaml";
  const std::string plane_case = cases + "/switch_plane_laplace/case.yaml";
  OJson common{{"bench", "pullin_models"}};

  // ---- 3 first: the default case's complete dynamic study, as the driver runs it ----------
  for (const std::string gas : {"reynolds", "none"}) {
    if (!wanted("default")) break;
    Timer total;
    auto sc = load_scene(plate_case, {"gas.model=" + gas});
    SwitchScene& s = sc->scene;
    const PullInSettings settings = read_pull_in_settings(sc->file.root(), s);
    const double build_wall = total.wall(), build_cpu = total.cpu();
    Timer qs_timer;
    const QuasiStaticPullIn qs = trace_pull_in(*s.actuation, s.control, settings.quasi_static);
    const double qs_wall = qs_timer.wall(), qs_cpu = qs_timer.cpu();
    Timer dyn_timer;
    const std::unique_ptr<SwitchSystem> system = make_switch_system(s);
    const DynamicPullIn d =
        find_dynamic_pull_in(*system, s.control, 0.8 * qs.pull_in_voltage,
                             1.02 * qs.pull_in_voltage, settings.tolerance, settings.run);
    OJson j = common;
    j["variant"] = "default_case_study";
    j["gas"] = gas;
    j["quasi_static_v_pi"] = qs.pull_in_voltage;
    j["dynamic_v_pi"] = d.voltage;
    j["not_pulling_in"] = d.lower;
    j["pull_in_time_s"] = d.pull_in_time;
    j["bisection_runs"] = d.runs;
    j["steps"] = d.steps;
    j["residual_evals"] = d.residual_evals;
    j["build_wall_s"] = build_wall;
    j["quasi_static_wall_s"] = qs_wall;
    j["bisection_wall_s"] = dyn_timer.wall();
    j["total_wall_s"] = total.wall();
    j["build_cpu_s"] = build_cpu;
    j["quasi_static_cpu_s"] = qs_cpu;
    j["bisection_cpu_s"] = dyn_timer.cpu();
    j["total_cpu_s"] = total.cpu();
    emit(j);
    std::fprintf(stderr,
                 "default case, gas %s: V_qs %.2f V, V_dyn %.2f V, t_PI %.3f us; "
                 "qs %.2f s, bisection (%d runs) %.2f s, total %.2f s wall / %.2f s CPU\n",
                 gas.c_str(), qs.pull_in_voltage, d.voltage, d.pull_in_time * 1e6, qs_wall, d.runs,
                 dyn_timer.wall(), total.wall(), total.cpu());
  }

  // ---- 1. quasi-static V_PI on mesh sequences ------------------------------------------
  std::vector<Point> plate_qs, plane_qs;
  if (!wanted("quasi_static")) plate_nx.clear(), plane_nx.clear();
  for (int nx : plate_nx) {
    const int ny = std::max(1, nx / 10);
    Timer t;
    auto sc = load_scene(plate_case, {"gas.model=none", cells(nx, ny)});
    const QuasiStaticPullIn r = trace_pull_in(*sc->scene.actuation, sc->scene.control, sampling());
    Point p{std::to_string(nx) + "x" + std::to_string(ny), double(nx * ny), r.pull_in_voltage,
            t.wall(), t.cpu()};
    plate_qs.push_back(p);
    OJson j = common;
    j["variant"] = "quasi_static";
    j["model"] = "plate+parallel_plate";
    j["mesh"] = p.mesh;
    j["unknowns"] = sc->scene.structure->structure().size();
    j["v_pi"] = p.value;
    j["solves"] = r.solves;
    j["newton_iterations"] = r.newton_iterations;
    j["wall_s"] = p.wall;
    j["cpu_s"] = p.cpu;
    emit(j);
    std::fprintf(stderr, "qs plate %s: V_PI %.4f V, %.3f s\n", p.mesh.c_str(), p.value, p.wall);
  }
  for (int nx : plane_nx) {
    const int ny = std::max(1, static_cast<int>(std::lround(nx / 12.5)));
    const int gap_cells = 2 * ny;
    Timer t;
    auto sc = load_scene(
        plane_case, {cells(nx, ny), "actuation.laplace.gap_cells=" + std::to_string(gap_cells)});
    SwitchScene& s = sc->scene;
    auto* beam = dynamic_cast<ElasticityScene*>(s.structure.get());
    FieldCoupledStructure coupled(*beam->op, *s.laplace, LinearFunctional::unknown(s.control));
    const QuasiStaticPullIn r = coupled.trace_quasi_static(sampling());
    Point p{std::to_string(nx) + "x" + std::to_string(ny) + "+gap" + std::to_string(gap_cells),
            double(nx * ny), r.pull_in_voltage, t.wall(), t.cpu()};
    plane_qs.push_back(p);
    OJson j = common;
    j["variant"] = "quasi_static";
    j["model"] = "plane+laplace";
    j["mesh"] = p.mesh;
    j["unknowns"] = beam->op->size();
    j["gap_cells_total"] = s.laplace->gap_cells_total();
    j["v_pi"] = p.value;
    j["solves"] = r.solves;
    j["laplace_solves"] = s.laplace->solves();
    j["wall_s"] = p.wall;
    j["cpu_s"] = p.cpu;
    emit(j);
    std::fprintf(stderr, "qs plane+Laplace %s: V_PI %.4f V, %.3f s, %ld Laplace solves\n",
                 p.mesh.c_str(), p.value, p.wall, s.laplace->solves());
  }
  if (wanted("quasi_static")) {
    OJson j = common;
    j["variant"] = "quasi_static_summary";
    OJson a, b;
    const double ra = sequence_errors(plate_qs, a), rb = sequence_errors(plane_qs, b);
    j["plate+parallel_plate"] = a;
    j["plane+laplace"] = b;
    // Matched accuracy against each model's Richardson value (finest mesh if unavailable).
    j["matched"] = matched(plate_qs, std::isnan(ra) ? plate_qs.back().value : ra, plane_qs,
                           std::isnan(rb) ? plane_qs.back().value : rb, "plate+parallel_plate",
                           "plane+laplace");
    j["matched_reference"] =
        std::string(std::isnan(ra) || std::isnan(rb) ? "finest mesh" : "richardson");
    emit(j);
  }

  // ---- 2. dynamic V_PI on mesh sequences (no gas) ---------------------------------------
  auto dynamic_point = [&](const std::string& model, const std::string& path,
                           const std::vector<std::string>& overrides, const std::string& mesh) {
    Timer t;
    auto sc = load_scene(path, overrides);
    SwitchScene& s = sc->scene;
    const QuasiStaticPullIn qs = trace_pull_in(*s.actuation, s.control, sampling());
    const double qs_wall = t.wall();
    // A plane beam has no quasi-static components: every unknown is inertial (the
    // ReducedInertiaSystem with no flags, since 018c69b).
    const std::unique_ptr<SwitchSystem> system = make_switch_system(s);
    const DynamicPullIn d =
        find_dynamic_pull_in(*system, s.control, 0.8 * qs.pull_in_voltage,
                             1.02 * qs.pull_in_voltage, dyn_tolerance, dynamic_options(s.gap));
    // The bracket's midpoint: within tolerance / 2 of the threshold.
    Point p{mesh, 0, 0.5 * (d.voltage + d.lower), t.wall(), t.cpu()};
    OJson j = common;
    j["variant"] = "dynamic";
    j["model"] = model;
    j["mesh"] = mesh;
    j["unknowns"] = system->size();
    j["quasi_static_v_pi"] = qs.pull_in_voltage;
    j["dynamic_v_pi"] = d.voltage;
    j["not_pulling_in"] = d.lower;
    j["v_mid"] = p.value;
    j["ratio_to_quasi_static"] = p.value / qs.pull_in_voltage;
    j["pull_in_time_s"] = d.pull_in_time;
    j["runs"] = d.runs;
    j["steps"] = d.steps;
    j["residual_evals"] = d.residual_evals;
    j["quasi_static_wall_s"] = qs_wall;
    j["wall_s"] = p.wall;
    j["cpu_s"] = p.cpu;
    emit(j);
    std::fprintf(stderr,
                 "dyn %s %s: V_dyn in (%.3f, %.3f] V (qs %.3f), %d runs, %ld steps, %.2f s\n",
                 model.c_str(), mesh.c_str(), d.lower, d.voltage, qs.pull_in_voltage, d.runs,
                 d.steps, p.wall);
    return p;
  };
  std::vector<Point> plate_dyn, plane_dyn;
  if (!wanted("dynamic")) dyn_plate_nx.clear(), dyn_plane_nx.clear();
  for (int nx : dyn_plate_nx) {
    const int ny = std::max(1, nx / 10);
    plate_dyn.push_back(dynamic_point("plate+parallel_plate", plate_case,
                                      {"gas.model=none", cells(nx, ny)},
                                      std::to_string(nx) + "x" + std::to_string(ny)));
  }
  for (int nx : dyn_plane_nx) {
    const int ny = std::max(1, static_cast<int>(std::lround(nx / 12.5)));
    plane_dyn.push_back(dynamic_point("plane+parallel_plate", plane_case,
                                      {cells(nx, ny), "actuation.electrostatics=parallel_plate"},
                                      std::to_string(nx) + "x" + std::to_string(ny)));
  }
  if (wanted("dynamic")) {
    OJson j = common;
    j["variant"] = "dynamic_summary";
    j["bisection_tolerance"] = dyn_tolerance;
    OJson a, b;
    const double ra = sequence_errors(plate_dyn, a), rb = sequence_errors(plane_dyn, b);
    j["plate+parallel_plate"] = a;
    j["plane+parallel_plate"] = b;
    j["matched"] = matched(plate_dyn, std::isnan(ra) ? plate_dyn.back().value : ra, plane_dyn,
                           std::isnan(rb) ? plane_dyn.back().value : rb, "plate+parallel_plate",
                           "plane+parallel_plate");
    j["matched_reference"] =
        std::string(std::isnan(ra) || std::isnan(rb) ? "finest mesh" : "richardson");
    emit(j);
  }
  // ---- 2b. dynamic V_PI: plate + parallel-plate against plane + Laplace -----------------
  if (!wanted("laplace_dynamic")) return 0;
  auto weighted = [&](double gap) {
    DynamicOptions o = dynamic_options(gap);
    o.ida.rtol = laplace_rtol;
    o.ida.atol = laplace_rtol * gap;
    o.tolerances.displacement = laplace_rtol * gap;
    o.tolerances.velocity_rate = 2 * M_PI * 131.1e3;
    return o;
  };
  auto report = [&](OJson j, const std::string& model, const std::string& mesh, double v_qs,
                    const DynamicPullIn& d, const Timer& t, double qs_wall, double qs_cpu) {
    Point p{mesh, 0, 0.5 * (d.voltage + d.lower), t.wall(), t.cpu()};
    j["variant"] = "laplace_dynamic";
    j["model"] = model;
    j["mesh"] = mesh;
    j["quasi_static_v_pi"] = v_qs;
    j["dynamic_v_pi"] = d.voltage;
    j["not_pulling_in"] = d.lower;
    j["v_mid"] = p.value;
    j["ratio_to_quasi_static"] = p.value / v_qs;
    j["pull_in_time_s"] = d.pull_in_time;
    j["runs"] = d.runs;
    j["steps"] = d.steps;
    j["residual_evals"] = d.residual_evals;
    j["quasi_static_wall_s"] = qs_wall;
    j["quasi_static_cpu_s"] = qs_cpu;
    j["wall_s"] = p.wall;
    j["cpu_s"] = p.cpu;
    j["rtol"] = laplace_rtol;
    j["bisection_tolerance"] = laplace_tolerance;
    j["load_average_1min"] = load_average_1min();
    emit(j);
    std::fprintf(stderr,
                 "dyn %s %s: V_dyn in (%.3f, %.3f] V (qs %.3f), %d runs, %ld steps, "
                 "%.2f s wall, %.2f s CPU\n",
                 model.c_str(), mesh.c_str(), d.lower, d.voltage, v_qs, d.runs, d.steps, p.wall,
                 p.cpu);
    return p;
  };
  std::vector<Point> plate_l, plane_l;
  for (int nx : laplace_plate_nx) {
    const int ny = std::max(1, nx / 10);
    const std::string mesh = std::to_string(nx) + "x" + std::to_string(ny);
    Timer t;
    auto sc = load_scene(plate_case, {"gas.model=none", cells(nx, ny)});
    SwitchScene& s = sc->scene;
    const QuasiStaticPullIn qs = trace_pull_in(*s.actuation, s.control, sampling());
    const double qs_wall = t.wall(), qs_cpu = t.cpu();
    const std::unique_ptr<SwitchSystem> system = make_switch_system(s);
    const DynamicOptions o = weighted(s.gap);
    const DynamicPullIn d = find_dynamic_pull_in(*system, s.control, 0.8 * qs.pull_in_voltage,
                                                 1.02 * qs.pull_in_voltage, laplace_tolerance, o);
    OJson j = common;
    j["unknowns"] = system->size();
    plate_l.push_back(
        report(j, "plate+parallel_plate", mesh, qs.pull_in_voltage, d, t, qs_wall, qs_cpu));
  }
  for (int nx : laplace_plane_nx) {
    const int ny = std::max(1, static_cast<int>(std::lround(nx / 12.5)));
    const int gap_cells = 2 * ny;
    const std::string mesh =
        std::to_string(nx) + "x" + std::to_string(ny) + "+gap" + std::to_string(gap_cells);
    Timer t;
    auto sc = load_scene(
        plane_case, {cells(nx, ny), "actuation.laplace.gap_cells=" + std::to_string(gap_cells)});
    SwitchScene& s = sc->scene;
    auto* beam = dynamic_cast<ElasticityScene*>(s.structure.get());
    FieldCoupledStructure coupled(*beam->op, *s.laplace, LinearFunctional::unknown(s.control));
    const QuasiStaticPullIn qs = coupled.trace_quasi_static(sampling());
    const double qs_wall = t.wall(), qs_cpu = t.cpu();
    const Json field0 = s.laplace->counters();
    const DynamicOptions o = weighted(s.gap);
    const double v_qs = qs.pull_in_voltage;
    const DynamicPullIn d =
        find_dynamic_pull_in([&](Real v) { return coupled.run(v, o); }, 0.8 * v_qs, 1.02 * v_qs,
                             laplace_tolerance, o.end_time);
    const Json field = s.laplace->counters();
    OJson j = common;
    j["unknowns"] = 2 * beam->op->size();
    j["gap_cells_total"] = s.laplace->gap_cells_total();
    j["field_solves"] = field["field_solves"].get<long>() - field0["field_solves"].get<long>();
    j["cpu_field_s"] = field["field_s"].get<double>() - field0["field_s"].get<double>();
    j["cpu_mesh_motion_s"] = field["move_s"].get<double>() - field0["move_s"].get<double>();
    j["cpu_structure_s"] = coupled.times().structure;
    plane_l.push_back(report(j, "plane+laplace", mesh, v_qs, d, t, qs_wall, qs_cpu));
  }
  {
    OJson j = common;
    j["variant"] = "laplace_dynamic_summary";
    // Each model's error against its own finest mesh; matched: the cheapest mesh within the
    // target of its own finest (the finest themselves have no reference and are left out).
    OJson models = OJson::object();
    for (auto* seq : {&plate_l, &plane_l}) {
      OJson rows = OJson::array();
      for (const Point& p : *seq)
        rows.push_back({{"mesh", p.mesh},
                        {"v_mid", p.value},
                        {"error_vs_finest", std::abs(p.value / seq->back().value - 1)},
                        {"wall_s", p.wall},
                        {"cpu_s", p.cpu}});
      models[seq == &plate_l ? "plate+parallel_plate" : "plane+laplace"] = rows;
    }
    j["models"] = models;
    if (!plate_l.empty() && !plane_l.empty()) {
      j["ratio_cpu_finest"] = plane_l.back().cpu / plate_l.back().cpu;
      j["ratio_wall_finest"] = plane_l.back().wall / plate_l.back().wall;
      j["ratio_cpu_coarsest"] = plane_l.front().cpu / plate_l.front().cpu;
      j["ratio_wall_coarsest"] = plane_l.front().wall / plate_l.front().wall;
    }
    emit(j);
  }
  return 0;
}

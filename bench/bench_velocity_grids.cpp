// bench_velocity_grids: work against error of the velocity grids (physics/gas/kinetic/
// velocity_quadrature.hpp) on the three linearised-BGK problems between diffuse parallel
// plates, one JSON line per (problem, delta, grid) run.
//
//   couette     cases/gas_couette, BGK, walls at -+0.5 m/s along z: P = -p_xy v0 / (p0 U)
//   heat        cases/gas_heat_transfer, BGK, walls at T0 -+ 0.5 %:    q* = q / (p0 v0 dT / T0)
//   poiseuille  cases/gas_poiseuille, BGK, body force, periodic:       G
// each at delta = p0 H / (mu0 v0) = 0.01, 0.1, 1, 10 (Kn = sqrt(pi) / (2 delta)), with the set-up
// of test/drivers/test_gas_linearised_bgk.sh: one column of cells across H = 1 m (10 cells at
// delta <= 0.1, 40 at 1, 50 at 10), second-order transport, the sequential solver (COMET for
// Couette and heat at delta = 10) to 1e-6. The answer is read from the run's JSON summary
// (kinetic_summary, as rfmems-gas --json prints it) and compared with the discrete-ordinates
// reference of python/linearised_bgk_reference.py (7 digits, below).
//
// Grids: the uniform ones the driver test uses today (extent 4 v0: 8 x 64 x 8 for the shear
// and the flow rate, 12 x 64 x 12 for the heat flux, 32 across at delta = 10) and their
// refinements, against product grids of Gauss-Hermite along the walls and a wall-refined rule
// across them (half-range Gauss-Hermite, or sinh-stretched midpoints). A row records the
// velocities, the CPU seconds of building the run (grid, scene, initial state) and solving it
// (this process; the machine is shared), the iterations and the relative error.
//
// Sample runs:
//   build/bench/bench_velocity_grids > docs/figures/velocity_grids.jsonl   # every row
//   build/bench/bench_velocity_grids --problems couette --deltas 1
//   build/bench/bench_velocity_grids --grids "gh+hr 3x16x3"
//   build/bench/bench_velocity_grids --grids "gh+hr 3x12x3 200 cells"
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "io/case_file.hpp"
#include "io/json_summary.hpp"
#include "physics/gas/kinetic/kinetic_case.hpp"
#include "physics/gas/kinetic/kinetic_results.hpp"

using namespace rfmems;
using json = nlohmann::json;

namespace {

// python/linearised_bgk_reference.py <problem> 0.01,0.1,1,10 (Richardson-extrapolated); Poiseuille
// at delta = 0.01 with 256 half-range points instead of 128 (3.0496187 with 128: the flow rate
// near the free-molecular limit is carried by molecules nearly parallel to the walls).
const std::map<std::string, std::map<std::string, double>> kReference = {
    {"couette", {{"0.01", 0.5593366}, {"0.1", 0.5223249}, {"1", 0.3389252}, {"10", 0.0831122}}},
    {"heat", {{"0.01", 0.5599495}, {"0.1", 0.5276072}, {"1", 0.3615623}, {"10", 0.0991778}}},
    {"poiseuille", {{"0.01", 3.0496501}, {"0.1", 2.0327143}, {"1", 1.5386784}, {"10", 2.7686424}}}};

// A grid: a label, one rule per direction and the points; cells across, when not the set-up's.
struct GridSpec {
  std::string label;
  std::array<std::string, 3> type;
  std::array<int, 3> n;
  int cells = 0;
};

std::string points_text(const std::array<int, 3>& n) {
  return "[" + std::to_string(n[0]) + ", " + std::to_string(n[1]) + ", " + std::to_string(n[2]) +
         "]";
}

// The grids of a problem at a delta: today's uniform grid and finer uniform ones; Gauss-Hermite
// (gh) along the walls with half-range Gauss-Hermite (hr) or sinh-stretched midpoints (sinh)
// across them.
std::vector<GridSpec> grids_for(const std::string& problem, const std::string& delta) {
  const int along = problem == "heat" ? 12 : 8;  // today's points along the walls
  const int gh = problem == "heat" ? 4 : 3;      // Gauss-Hermite points along the walls
  std::vector<GridSpec> g;
  const std::array<std::string, 3> u = {"uniform", "uniform", "uniform"};
  for (int ny : {32, 64, 128, 200}) g.push_back({"uniform", u, {along, ny, along}});
  std::vector<int> across = {8, 12, 16, 24, 32, 48};
  // Near the free-molecular limit the flow rate is carried by molecules nearly parallel to the
  // walls: more points across.
  if (problem == "poiseuille" && std::stod(delta) <= 0.1)
    across.insert(across.end(), {64, 96, 128});
  for (int ny : across)
    g.push_back({"gh+hr", {"gauss_hermite", "half_range_hermite", "gauss_hermite"}, {gh, ny, gh}});
  for (int ny : {16, 32, 64})
    g.push_back({"gh+sinh", {"gauss_hermite", "sinh_stretched", "gauss_hermite"}, {gh, ny, gh}});
  for (int ny : {16, 32})
    g.push_back({"gh", {"gauss_hermite", "gauss_hermite", "gauss_hermite"}, {gh, ny, gh}});
  // Poiseuille at delta = 10: on 50 cells every non-uniform grid converges to the 50-cell
  // spatial error (-0.09 %), which today's uniform grid cancels with its own velocity error; the
  // half-range grids on 100 and 200 cells show what the velocities cost once space is resolved.
  if (problem == "poiseuille" && std::stod(delta) >= 10)
    for (int cells : {100, 200})
      for (int ny : {8, 12, 16})
        g.push_back({"gh+hr",
                     {"gauss_hermite", "half_range_hermite", "gauss_hermite"},
                     {gh, ny, gh},
                     cells});
  return g;
}

struct Setup {
  std::string case_file;
  std::vector<std::string> overrides;
  int cells = 0;
};

Setup setup_for(const std::string& cases, const std::string& problem, double delta) {
  Setup s;
  s.cells = delta <= 0.1 ? 10 : delta <= 1 ? 40 : 50;
  const double knudsen = std::sqrt(M_PI) / (2 * delta);
  s.overrides = {"initial.knudsen=" + fmt::format("{:.17g}", knudsen),
                 "mesh.cells=[1, " + std::to_string(s.cells) + "]", "velocity_grid.extent=4"};
  if (problem == "poiseuille") {
    s.case_file = cases + "/gas_poiseuille/case.yaml";
    return s;
  }
  const bool comet = delta >= 10;
  s.overrides.insert(s.overrides.end(),
                     {"gas.collision=bgk", "solver.transport=second_order",
                      std::string("solver.type=") + (comet ? "comet" : "sequential")});
  if (problem == "couette") {
    s.case_file = cases + "/gas_couette/case.yaml";
    s.overrides.insert(s.overrides.end(), {"boundaries.bottom.velocity=[0 m/s, 0 m/s, -0.5 m/s]",
                                           "boundaries.top.velocity=[0 m/s, 0 m/s, 0.5 m/s]"});
  } else {
    s.case_file = cases + "/gas_heat_transfer/case.yaml";
    s.overrides.insert(s.overrides.end(),
                       {"mesh.size=[1 m, 1 m]", "initial.reference_length=1 m",
                        "boundaries.bottom.T=271.78425 K", "boundaries.top.T=274.51575 K"});
  }
  return s;
}

// The problem's normalised answer from the run's summary.
double answer(const std::string& problem, const Json& summary) {
  if (problem == "poiseuille") return summary["flow_rate"]["normalised_flow_rate"].get<double>();
  const char* key = problem == "couette" ? "normalised_shear" : "normalised_heat_flux";
  return summary["walls"]["bottom"][key].get<double>();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Velocity grids: work against error on Couette shear, heat flux, Poiseuille G"};
  std::vector<std::string> problems = {"couette", "heat", "poiseuille"};
  std::vector<std::string> deltas = {"0.01", "0.1", "1", "10"};
  std::vector<std::string> labels;
  std::string cases = bench::default_cases_dir();
  app.add_option("--problems", problems, "couette, heat, poiseuille");
  app.add_option("--deltas", deltas, "rarefaction parameters (of the reference table)");
  app.add_option("--grids", labels, "only these grids: 'label NxNyxNz', e.g. 'gh+hr 3x16x3'");
  app.add_option("--cases", cases, "the repository's cases/ directory");
  CLI11_PARSE(app, argc, argv);

  for (const std::string& problem : problems)
    for (const std::string& delta_text : deltas) {
      const double delta = std::stod(delta_text);
      const double reference = kReference.at(problem).at(delta_text);
      for (const GridSpec& grid : grids_for(problem, delta_text)) {
        const std::string name =
            grid.label + " " + std::to_string(grid.n[0]) + "x" + std::to_string(grid.n[1]) + "x" +
            std::to_string(grid.n[2]) +
            (grid.cells > 0 ? " " + std::to_string(grid.cells) + " cells" : "");
        if (!labels.empty() && std::find(labels.begin(), labels.end(), name) == labels.end())
          continue;
        Setup s = setup_for(cases, problem, delta);
        if (grid.cells > 0) {
          s.cells = grid.cells;
          s.overrides.push_back("mesh.cells=[1, " + std::to_string(s.cells) + "]");
        }
        s.overrides.push_back("velocity_grid.points=" + points_text(grid.n));
        const char* axes[3] = {"x", "y", "z"};
        for (int d = 0; d < 3; ++d)
          s.overrides.push_back(std::string("velocity_grid.") + axes[d] +
                                "={type: " + grid.type[d] + "}");
        json row = {{"problem", problem},    {"delta", delta},   {"grid", grid.label},
                    {"types", grid.type},    {"points", grid.n}, {"cells", s.cells},
                    {"reference", reference}};
        try {
          const CaseFile file = CaseFile::load(s.case_file, s.overrides);
          const double cpu0 = bench::cpu_now(), wall0 = bench::now();
          KineticScene scene = build_kinetic_scene(file.root(), "");
          std::vector<Real> f(scene.op->size());
          scene.op->initialize(f, [&](const Vec3&) { return scene.initial; });
          const KineticSolveResult result = kinetic_solvers().at(scene.solver.type)(
              *scene.op, f, scene.solver, [](int, Real) { return true; });
          scene.op->update_collision(f);
          const double cpu = bench::cpu_now() - cpu0, wall = bench::now() - wall0;
          const Json summary = kinetic_summary(scene, result, f);
          const double value = answer(problem, summary);
          row["ordinates"] = scene.op->grid().size();
          row["solver"] = result.method;
          row["iterations"] = result.iterations;
          row["converged"] = result.converged;
          row["cpu_s"] = cpu;
          row["wall_s"] = wall;
          row["value"] = value;
          row["error"] = value / reference - 1;
        } catch (const std::exception& e) {
          row["failure"] = e.what();
        }
        bench::emit(row);
      }
    }
  return 0;
}

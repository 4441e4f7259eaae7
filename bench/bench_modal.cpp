// Cost of the modal analysis (physics/structure/modal_analysis.hpp), and the first frequency it
// gives against the transient-and-fit route on the same mesh.
//
// Sections (one JSON line each, plus a header line with the command and the date):
//   modes      the --modes lowest modes of cases/switch_plate's plate (40 x 4 = 160 cells) and of
//              the same plate on --large-cells (default 400 x 100 = 40,000 cells): wall and CPU
//              seconds of the whole analysis (the stiffness, the KLU factorisation, the Arnoldi
//              iteration), best of --repeat runs, the factorisation and iteration times, the
//              operator applications and the frequencies;
//   transient  the same 160-cell plate at rest, then a step pressure of -1 Pa (no film, no
//              electrostatics: the structure alone), integrated by IDA over --periods periods of
//              the thesis's 122 kHz at --rtol, the centre deflection recorded every --samples per
//              period, and its first frequency from the step-response fit
//              (physics/structure/step_response_fit.hpp; the library's route) and from the
//              spacing of its extrema (free_response.hpp, log_decrement), each against the modal
//              first frequency of the same mesh, with the transient's wall and CPU time;
//   bias       the first frequency of the 160-cell switch (plate + parallel-plate actuation, no
//              film; cases/switch_plate, or --bias-case) against DC bias: the stable branch of its
//              quasi-static pull-in curve (coupling/quasi_static_pull_in.hpp, displacement control,
//              so states up to the fold are reached), the plate linearised about each state
//              (linearised_modes: the actuation's exact Jacobian, the electrostatic softening
//              included), against the 1-DOF parallel-plate actuator's omega^2 = (k - eps0 A V^2 /
//              g^3) / m in its dimensionless form: (f / f0)^2 = 1 - (8/27) v^2 / x^3 with v = V /
//              V_PI and x = g / g0 from x^2 (1 - x) = (4/27) v^2 (coupling/bias_modes.hpp, as
//              rfmems-pullin's pull_in.quasi_static.modes); modal_wall_s is per state, its
//              re-solve included.
//
//   build/bench/bench_modal                       # docs/modal.md's run
//   build/bench/bench_modal --large-cells 200,50  # a quicker large plate
#include <CLI/CLI.hpp>
#include <cmath>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "bench_support.hpp"
#include "coupling/bias_modes.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/switch_scene.hpp"
#include "io/case_file.hpp"
#include "io/progress.hpp"
#include "physics/structure/free_response.hpp"
#include "physics/structure/modal_analysis.hpp"
#include "physics/structure/step_response_fit.hpp"
#include "physics/structure/structural_analysis.hpp"
#include "physics/structure/structure_from_case.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using nlohmann::json;

namespace {

std::unique_ptr<StructuralModel> switch_plate(const std::string& cases, AnalysisType type,
                                              std::vector<std::string> sets) {
  const std::string dir = cases + "/switch_plate";
  const CaseFile cf = CaseFile::load(dir + "/case.yaml", sets);
  return build_structure(cf.root(), dir, type);
}

json modes_run(const std::string& cases, const std::string& cells, Index n_modes, int repeat) {
  std::vector<std::string> sets;
  if (!cells.empty()) sets.push_back("mesh.cells=[" + cells + "]");
  double best_wall = 1e300, best_cpu = 1e300;
  StructuralModes best;
  Index n_cells = 0, unknowns = 0, nnz = 0;
  for (int r = 0; r < repeat; ++r) {
    std::unique_ptr<StructuralModel> model = switch_plate(cases, AnalysisType::Modal, sets);
    n_cells = model->structure_mesh().n_cells();
    unknowns = model->structure().size();
    nnz = model->structure().stiffness_pattern().nnz();
    const double wall = bench::now(), cpu = bench::cpu_now();
    StructuralModes modes = structural_modes(*model, n_modes, 0.0);
    const double w = bench::now() - wall, c = bench::cpu_now() - cpu;
    if (w < best_wall) {
      best_wall = w;
      best = std::move(modes);
    }
    best_cpu = std::min(best_cpu, c);
  }
  json frequencies = json::array(), complex = json::array();
  for (const StructuralMode& m : best.stats.modes) {
    frequencies.push_back(m.frequency);
    complex.push_back(m.complex);
  }
  const ShiftInvertStats& s = best.stats.eigen;
  return {{"section", "modes"},
          {"case", "switch_plate"},
          {"cells", n_cells},
          {"unknowns", unknowns},
          {"stiffness_nonzeros", nnz},
          {"modes", n_modes},
          {"repeat", repeat},
          {"wall_s", best_wall},
          {"cpu_s", best_cpu},
          {"factorization", s.factorization},
          {"factor_s", s.factor_seconds},
          {"iterate_s", s.solve_seconds},
          {"operator_applications", s.operator_applications},
          {"restarts", s.restarts},
          {"subspace", s.subspace},
          {"frequencies_hz", frequencies},
          {"complex", complex}};
}

// Records the deflection of one cell at every output.
struct CellHistory : AnalysisObserver {
  Index unknown = 0;
  std::vector<Real> t, w;
  void output(int, Real time, std::span<const Real> u, std::span<const Real>) override {
    t.push_back(time);
    w.push_back(u[unknown]);
  }
};

json transient_run(const std::string& cases, double periods, int samples, double rtol) {
  const std::vector<std::string> sets = {"pressure={value: -1 Pa}"};
  // The modal route on this mesh (its own clock).
  std::unique_ptr<StructuralModel> modal_model = switch_plate(cases, AnalysisType::Modal, sets);
  const double modal_wall = bench::now(), modal_cpu = bench::cpu_now();
  const StructuralModes modes = structural_modes(*modal_model, 1, 0.0);
  const double modal_wall_s = bench::now() - modal_wall, modal_cpu_s = bench::cpu_now() - modal_cpu;
  const double f_modal = modes.stats.modes[0].frequency;

  // The transient route: a step load from rest, IDA, the centre deflection's history.
  std::unique_ptr<StructuralModel> model = switch_plate(cases, AnalysisType::Transient, sets);
  const Mesh& mesh = model->structure_mesh();
  Index centre = 0;
  const Vec3 middle(200e-6, 20e-6, 0);
  for (Index c = 1; c < mesh.n_cells(); ++c)
    if ((mesh.cell_centroid(c) - middle).norm() < (mesh.cell_centroid(centre) - middle).norm())
      centre = c;
  const double f_thesis = 122e3;  // the case's first-mode estimate, to size the run only
  AnalysisSettings settings;
  settings.type = AnalysisType::Transient;
  settings.end_time = periods / f_thesis;
  settings.output_interval = 1 / (f_thesis * samples);
  settings.ida.rtol = rtol;
  settings.ida.atol = rtol * 1e-3 * 1e-9;  // the deflection is ~1e-9 m under 1 Pa
  settings.ida.max_order = 2;
  CellHistory history;
  history.unknown = model->gap_unknown(centre);
  ProgressReporter quiet(true, settings.end_time);
  const double wall = bench::now(), cpu = bench::cpu_now();
  const AnalysisStats stats = run_analysis(*model, settings, history, quiet);
  const double transient_wall = bench::now() - wall, transient_cpu = bench::cpu_now() - cpu;
  const double fit_wall = bench::now();
  const StepResponseFit fit = fit_step_response(history.t, history.w);
  const double fit_s = bench::now() - fit_wall;
  const LogDecrement decrement = log_decrement(history.t, history.w);
  json j = {{"section", "transient"},
            {"case", "switch_plate"},
            {"cells", mesh.n_cells()},
            {"load", "step pressure -1 Pa, no film, no electrostatics"},
            {"periods", periods},
            {"samples_per_period", samples},
            {"rtol", rtol},
            {"modal_frequency_hz", f_modal},
            {"modal_wall_s", modal_wall_s},
            {"modal_cpu_s", modal_cpu_s},
            {"transient_wall_s", transient_wall},
            {"transient_cpu_s", transient_cpu},
            {"fit_wall_s", fit_s},
            {"samples", history.t.size()},
            {"fitted", fit.fitted},
            {"fit_frequency_hz", fit.natural_frequency},
            {"fit_damping_ratio", fit.damping_ratio},
            {"fit_residual", fit.residual},
            {"extrema_frequency_hz", decrement.frequency},
            {"extrema_swings", decrement.swings},
            {"fit_over_modal", fit.natural_frequency / f_modal - 1},
            {"extrema_over_modal", decrement.frequency / f_modal - 1}};
  bench::add_integrator_stats(j, stats.transient);
  return j;
}

std::vector<json> bias_run(const std::string& cases, const std::string& name, int n_points) {
  const std::string dir = cases + "/" + name;
  const CaseFile cf = CaseFile::load(dir + "/case.yaml", {"gas.model=none"});
  SwitchScene scene = build_switch_scene(cf.root(), dir);
  QuasiStaticOptions options;
  options.n_points = n_points;
  const double wall = bench::now();
  const QuasiStaticPullIn curve = trace_pull_in(*scene.actuation, scene.control, options);
  const double trace_s = bench::now() - wall;
  const double modes_wall = bench::now();
  const std::vector<BiasedModes> states = modes_along_curve(
      *scene.actuation, scene.control, curve, modal_mass(*scene.structure), 1, options);
  const double modal_s = (bench::now() - modes_wall) / static_cast<double>(states.size());
  std::vector<json> rows;
  const double f0 = states.front().modes[0].frequency;
  for (const BiasedModes& state : states) {
    const StructuralMode& first = state.modes[0];
    const double v = state.voltage / curve.pull_in_voltage;
    const double x_lumped = lumped_gap_fraction(std::min(v, 1.0));
    rows.push_back({{"section", "bias"},
                    {"case", name},
                    {"gas", "none"},
                    {"voltage", state.voltage},
                    {"pull_in_voltage", curve.pull_in_voltage},
                    {"control_displacement", state.displacement},
                    {"frequency_hz", first.frequency},
                    {"complex", first.complex},
                    {"frequency_ratio", first.frequency / f0},
                    {"lumped_ratio_of_voltage",
                     std::sqrt(std::max(0.0, 1 - 8.0 / 27 * v * v / std::pow(x_lumped, 3)))},
                    {"modal_wall_s", modal_s},
                    {"trace_wall_s", trace_s}});
  }
  return rows;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"modal analysis: cost, and against the transient-and-fit route"};
  std::string cases = bench::default_cases_dir(), large = "400,100";
  int n_modes = 10, repeat = 5, samples = 40;
  double periods = 5, rtol = 1e-4;
  int bias_points = 40;
  std::string bias_case = "switch_plate";
  std::vector<std::string> sections = {"modes", "transient", "bias"};
  app.add_option("--cases", cases, "the cases directory");
  app.add_option("--modes", n_modes, "how many modes");
  app.add_option("--repeat", repeat, "runs of the small plate (best of; the large: 1)");
  app.add_option("--large-cells", large, "the large plate's cells, nx,ny");
  app.add_option("--periods", periods, "transient: periods of the first mode");
  app.add_option("--samples", samples, "transient: outputs per period");
  app.add_option("--rtol", rtol, "transient: IDA's relative tolerance");
  app.add_option("--bias-points", bias_points, "bias: samples of the pull-in curve");
  app.add_option("--bias-case", bias_case, "bias: the switch case (a plate + parallel plate)");
  app.add_option("--sections", sections, "modes, transient, bias");
  CLI11_PARSE(app, argc, argv);

  bench::emit(bench::run_header<json>("bench_modal", argc, argv));
  for (const std::string& section : sections) {
    if (section == "modes") {
      bench::emit(modes_run(cases, "", n_modes, repeat));
      bench::emit(modes_run(cases, large, n_modes, 1));
    } else if (section == "transient") {
      bench::emit(transient_run(cases, periods, samples, rtol));
    } else if (section == "bias") {
      for (const json& row : bias_run(cases, bias_case, bias_points)) bench::emit(row);
    }
  }
}

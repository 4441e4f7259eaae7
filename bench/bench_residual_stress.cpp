// What a residual stress does to the switch: cases/switch_plate's plate (40 x 4 cells, no film)
// with a tensile stress sigma_xx along its span (the stress a bridge with free sides keeps of a
// film's biaxial stress), for each of --stresses [MPa]:
//   - the quasi-static pull-in voltage (coupling/quasi_static_pull_in.hpp) and the three lowest
//     modes (physics/structure/modal_analysis.hpp), each against the stress-free plate;
//   - the lumped spring's ratio sqrt(1 + k_s/k_b) for both (a stiffness k = k_b + k_s scales
//     V_PI and f1 alike), with the bending spring k_b = 32 E' b h^3/L^3 (E' = E/(1 - nu^2)) and
//     the stress's k_s = 8 sigma_xx b h/L of a fixed-fixed beam under a uniform load (Rebeiz,
//     RF MEMS: Theory, Design and Technology, 2003, sec. 2.4): k_s/k_b = sigma_xx L^2/(4 E' h^2);
//   - the wall time of each trace and modal analysis.
// One JSON line per stress, after a header line with the command and the date.
//
//   build/bench/bench_residual_stress                    # docs/residual-stress.md's run
//   build/bench/bench_residual_stress --stresses 0,50
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "bench_support.hpp"
#include "bench_switch_scene.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "physics/plate/plate_scene.hpp"
#include "physics/structure/modal_analysis.hpp"

using namespace rfmems;
using nlohmann::json;

int main(int argc, char** argv) {
  CLI::App app{"residual stress against the stress-free switch: pull-in voltage and modes"};
  std::string cases = bench::default_cases_dir();
  std::vector<double> stresses = {0, 10, 20, 34.5, 50, 100, 200};
  app.add_option("--cases", cases, "the cases directory");
  app.add_option("--stresses", stresses, "sigma_xx [MPa]")->delimiter(',');
  CLI11_PARSE(app, argc, argv);
  bench::emit(bench::run_header<json>("bench_residual_stress", argc, argv));

  double v0 = 0, f0 = 0;
  for (const double sigma : stresses) {
    auto s = bench::load_scene(
        cases + "/switch_plate/case.yaml",
        {"gas.model=none", fmt::format("material.residual_stress=[{} MPa, 0 MPa, 0 MPa]", sigma)});
    const auto& plate = dynamic_cast<const PlateScene&>(*s->scene.structure);
    const PlateSection& section = plate.section;
    double length = 0;
    for (const Vec3& x : plate.mesh->nodes()) length = std::max(length, x.x());
    const double e_plate = section.E / (1 - section.nu * section.nu);
    const double ks_over_kb =
        sigma * 1e6 * length * length / (4 * e_plate * section.thickness * section.thickness);

    double wall = bench::now();
    const StructuralModes modes = structural_modes(*s->scene.structure, 3, 0.0);
    const double modal_s = bench::now() - wall;
    QuasiStaticOptions o;
    o.voltage_tolerance = 1e-4;
    wall = bench::now();
    const QuasiStaticPullIn trace = trace_pull_in(*s->scene.actuation, s->scene.control, o);
    const double trace_s = bench::now() - wall;
    if (sigma == 0) v0 = trace.pull_in_voltage, f0 = modes.stats.modes[0].frequency;
    json frequencies = json::array();
    for (const StructuralMode& m : modes.stats.modes) frequencies.push_back(m.frequency);
    bench::emit(json{{"section", "sweep"},
                     {"residual_stress_mpa", sigma},
                     {"membrane_force_n_per_m", sigma * 1e6 * section.thickness},
                     {"tension_parameter", sigma * 1e6 * section.thickness * length * length /
                                               section.bending_stiffness()},
                     {"pull_in_voltage", trace.pull_in_voltage},
                     {"voltage_ratio", v0 > 0 ? trace.pull_in_voltage / v0 : 0.0},
                     {"frequencies_hz", frequencies},
                     {"frequency_ratio", f0 > 0 ? modes.stats.modes[0].frequency / f0 : 0.0},
                     {"lumped_ratio", std::sqrt(1 + ks_over_kb)},
                     {"trace_wall_s", trace_s},
                     {"modal_wall_s", modal_s}});
  }
}

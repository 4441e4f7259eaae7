// Reynolds-film damping of the gas damping study's beam (docs/gas_damping.md): the
// quasi-static, linearised Reynolds equation with Veijola's effective viscosity on a strip
// (lib/physics/gas/reynolds_film.hpp, reynolds_quasi_static.hpp), width w = 45 um (and
// w + 2 dL with Veijola-Pursula-Raback's edge elongation dL = 0.8488 g (1 + 2.676 Kn^0.659),
// coefficients unverified: docs/gas_damping.md "Edge correction"),
// gap 7 um, argon at 273.15 K (mu = 2.117e-5 Pa s, Bird's mean free path), Open long sides,
// per pressure of the sweep: the damping per unit length c = -F / (g' L), the analytic
// mu_eff w^3 / g^3 it must equal up to the scheme's factor 1 + 2 (h/w)^2
// (test_reynolds_rarefaction.cpp), and the CPU seconds of the solve (the cost per point to
// set against the ESBGK runs of python/gas_damping_regimes_study.py). With a flow-factor table
// (materials/flow_factor_table.hpp), the same strip with the table's Q(Kn) in place of
// Veijola's fit too, where the table reaches (docs/gas_damping.md "Kinetic flow factor against
// Veijola's fit").
//
//   build/bench/bench_reynolds_strip_damping [--cells 100] [--repeat 20]
//                                            [--flow-factor-table docs/data/flow_factor_bgk.csv]
#include <CLI/CLI.hpp>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/gas/reynolds_film.hpp"
#include "physics/gas/reynolds_quasi_static.hpp"

using namespace rfmems;

namespace {

constexpr Real kW = 45e-6, kGap = 7e-6, kLength = 10e-6, kGapRate = -1e-8;
constexpr Real kR = 208.13, kT = 273.15, kMu = 2.117e-5, kPref = 1e5;

Real strip_damping(Real width, const GasProperties& gas, int cells) {
  BoxSpec spec;
  spec.upper = Vec3(width, kLength, 0);
  spec.n[0] = cells;
  spec.n[1] = 1;
  Mesh mesh = make_structured_mesh(spec);
  std::vector<FilmBoundary> bcs(mesh.patches().size());
  for (std::size_t i = 0; i < bcs.size(); ++i) {
    const std::string& name = mesh.patches()[i].name;
    bcs[i].kind =
        (name == "left" || name == "right") ? FilmBoundary::Kind::Open : FilmBoundary::Kind::Wall;
  }
  ReynoldsFilm film(mesh, gas, bcs);
  std::vector<Real> gap(film.size(), kGap), rate(film.size(), kGapRate);
  return -film.total_force(quasi_static_pressure(film, gap, rate, 2)) / (kGapRate * kLength);
}

}  // namespace

int main(int argc, char** argv) {
  int cells = 100, repeat = 20;
  std::string table_path;
  CLI::App app{
      "bench_reynolds_strip_damping: Reynolds/Veijola damping of the regime study's strip"};
  app.add_option("--cells", cells, "cells across the strip");
  app.add_option("--repeat", repeat, "solves per point (the CPU time is their mean)");
  app.add_option("--flow-factor-table", table_path, "also the film with this Q(Kn) table");
  CLI11_PARSE(app, argc, argv);
  std::shared_ptr<const FlowFactorTable> table;
  if (!table_path.empty())
    table = std::make_shared<const FlowFactorTable>(FlowFactorTable::read(table_path));
  const double load = [] {
    double l[1] = {0};
    return getloadavg(l, 1) == 1 ? l[0] : -1.0;
  }();
  for (Real p : {0.1, 1.0, 10.0, 100.0, 300.0, 1e3, 3e3, 1e4, 3e4, 1e5}) {
    GasProperties gas;
    gas.viscosity = kMu;
    gas.reference_pressure = kPref;
    gas.mean_free_path = kMu / kPref * std::sqrt(std::numbers::pi * kR * kT / 2);
    gas.ambient_pressure = p;
    const Real kn = gas.knudsen(p, kGap);
    const Real elongation = 0.8488 * kGap * (1 + 2.676 * std::pow(kn, 0.659));
    const double start = bench::cpu_now();
    Real c = 0;
    for (int i = 0; i < repeat; ++i) c = strip_damping(kW, gas, cells);
    const double cpu = (bench::cpu_now() - start) / repeat;
    const Real c_edge = strip_damping(kW + 2 * elongation, gas, cells);
    const Real exact = gas.effective_viscosity(p, kGap) * std::pow(kW / kGap, 3);
    nlohmann::json j;
    j["pressure"] = p;
    j["knudsen"] = kn;
    j["cells"] = cells;
    j["reynolds_veijola"] = c;
    j["reynolds_veijola_elongation"] = c_edge;
    j["analytic_mu_eff_w3_over_g3"] = exact;
    j["fv_over_analytic"] = c / exact;
    j["cpu_seconds_per_solve"] = cpu;
    j["load_average"] = load;
    if (table && kn <= table->max_extrapolated_knudsen()) {
      GasProperties kinetic = gas;
      kinetic.rarefaction = Rarefaction::Table;
      kinetic.flow_factor_table = table;
      const Real c_table = strip_damping(kW, kinetic, cells);
      j["flow_factor_veijola"] = gas.rarefaction_factor(kn);
      j["flow_factor_table"] = kinetic.rarefaction_factor(kn);
      j["reynolds_table"] = c_table;
      j["table_over_veijola"] = c_table / c;
    }
    bench::emit(j);
  }
}

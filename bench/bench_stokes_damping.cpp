// Continuum reference for the gas damping case (docs/gas_damping.md): steady Stokes
// flow around the beam of cases/gas_damping_regimes (half domain 43.5 x 29.5 um, beam half
// width b = 22.5 um, thickness 1.5 um, gap 7 um, symmetry at x = 0, open right and top), the
// beam moving at -0.1 m/s through the fixed geometry (quasi-steady, as the kinetic case),
// argon at 273.15 K (mu = 2.117e-5 Pa s), walls no-slip or with first-order Maxwell slip
// l = ((2 - sigma)/sigma) lambda, sigma = 1, lambda = (mu/p) sqrt(pi R T / 2), R = 208.13
// (the kinetic code's). MAC grid of spacing h (lib/physics/gas/stokes), KLU.
//
// Prints one JSON line per mesh: h, cells, unknowns, c = F_y / V for the whole beam (twice the
// half domain) without slip and with slip at each pressure, CPU seconds (assembly + solve per
// solve), the share of the swept flux V b leaving through the right side (slip); then, over the
// last three meshes (halving h), Richardson extrapolation of each c with its observed order p =
// log2((c1 - c2) / (c2 - c3)), c -> c3 + (c3 - c2) / (2^p - 1), and the estimated error of the
// finest mesh, |c_inf - c3|.
//
// --open-impedance C gives the open sides the normal impedance Z = C p / sqrt(2 R T) of the
// kinetic pressure boundary (stokes_boundary.hpp; C = 2.05 for the case's ESBGK on 8^3
// velocities, test_kinetic_pressure_boundary.cpp), p the solve's pressure (the no-slip solve:
// the first of --pressures), and with --open velocity --open-slip adds the slip length lambda
// to u_t = 0: the continuum limit of that boundary.
//
//   build/bench/bench_stokes_damping [--h 0.5,0.25,0.125] [--pressures 1e5,1e4]
//                                    [--open zero_gradient|zero_stress|velocity]
//                                    [--open-impedance C] [--open-slip] [--margin 3]
// (--margin: the open sides' distance from the beam in gaps, 3 in the kinetic case.)
#include <CLI/CLI.hpp>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "physics/gas/stokes/stokes_force.hpp"
#include "physics/gas/stokes/stokes_solve.hpp"

using namespace rfmems;

namespace {

constexpr Real kUm = 1e-6, kB = 22.5 * kUm, kT = 1.5 * kUm, kGap = 7 * kUm;
constexpr Real kMu = 2.117e-5, kR = 208.13, kTemperature = 273.15, kSpeed = 0.1;

Real mean_free_path(Real p) {
  return kMu / p * std::sqrt(std::numbers::pi * kR * kTemperature / 2);
}

struct Solve {
  Real damping, cpu;
  Index unknowns, nnz;
  Real right_outflow;  // through the right side, of the half domain [m^2/s]
};

// The open sides of a solve at pressure p.
struct OpenSides {
  OpenTangential tangential = OpenTangential::ZeroGradient;
  Real impedance_coefficient = 0;  // C of Z = C p / sqrt(2 R T)
  bool slip = false;               // u_t slip length lambda (Velocity)

  StokesSide at(Real p) const {
    StokesSide s = StokesSide::open(0.0, tangential);
    s.normal_impedance = impedance_coefficient * p / std::sqrt(2 * kR * kTemperature);
    if (slip) s.tangential_slip_length = mean_free_path(p);
    return s;
  }
};

Solve damping(const MacGrid& grid, Real slip, const StokesSide& open) {
  const double start = bench::cpu_now();
  StokesBoundaries b;
  b.sides[static_cast<int>(Side::Left)] = StokesSide::symmetry();
  b.sides[static_cast<int>(Side::Right)] = open;
  b.sides[static_cast<int>(Side::Top)] = open;
  b.sides[static_cast<int>(Side::Bottom)] = StokesSide::make_wall({.slip_length = slip});
  b.blocks = {{[](const Point2&) { return Point2(0, -kSpeed); }, slip}};
  StokesOperator op(grid, {kMu, b, {}});
  const std::vector<Real> x = solve_stokes(op);
  const Real force = boundary_force(op, x, Across::block(0)).y();
  return {2 * force / kSpeed, bench::cpu_now() - start, op.size(), op.pattern().nnz(),
          side_outflow(op, x, Side::Right)};
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<double> spacings{0.5, 0.25, 0.125}, pressures{1e5, 1e4};
  std::string open_name = "zero_gradient";
  OpenSides sides;
  double margin = 3;
  CLI::App app{"bench_stokes_damping: Stokes (no slip / Maxwell slip) damping of the beam"};
  app.add_option("--h", spacings, "grid spacings [um], halving")->delimiter(',');
  app.add_option("--pressures", pressures, "pressures of the slip solves [Pa]")->delimiter(',');
  app.add_option("--open", open_name, "tangential condition on the open sides")
      ->check(CLI::IsMember({"zero_gradient", "zero_stress", "velocity"}));
  app.add_option("--open-impedance", sides.impedance_coefficient,
                 "C of the open sides' normal impedance C p / sqrt(2 R T)");
  app.add_flag("--open-slip", sides.slip, "slip length lambda on the open sides' u_t = 0");
  app.add_option("--margin", margin, "open sides' distance from the beam [gaps]");
  CLI11_PARSE(app, argc, argv);
  const std::map<std::string, OpenTangential> opens{{"zero_gradient", OpenTangential::ZeroGradient},
                                                    {"zero_stress", OpenTangential::ZeroStress},
                                                    {"velocity", OpenTangential::Velocity}};
  sides.tangential = opens.at(open_name);
  double load[1] = {-1};
  getloadavg(load, 1);
  // series[key]: c per mesh; key "no_slip" or "slip_<p>".
  std::map<std::string, std::vector<Real>> series;
  for (double h_um : spacings) {
    const MacGrid grid(kB + margin * kGap, kGap + kT + margin * kGap, h_um * kUm,
                       {{0, kB, kGap, kGap + kT}});
    nlohmann::json j;
    j["h_um"] = h_um;
    j["cells"] = grid.fluid_cells();
    j["open"] = open_name;
    j["open_impedance"] = sides.impedance_coefficient;
    j["open_slip"] = sides.slip;
    j["margin_gaps"] = margin;
    j["load_average"] = load[0];
    const Solve none = damping(grid, 0.0, sides.at(pressures.front()));
    j["unknowns"] = none.unknowns;
    j["nnz"] = none.nnz;
    j["c_no_slip"] = none.damping;
    j["cpu_seconds_no_slip"] = none.cpu;
    series["no_slip"].push_back(none.damping);
    for (double p : pressures) {
      const std::string key = "slip_" + nlohmann::json(p).dump();
      const Solve slip = damping(grid, maxwell_slip_length(1.0, mean_free_path(p)), sides.at(p));
      j["c_" + key] = slip.damping;
      j["cpu_seconds_" + key] = slip.cpu;
      // The share of the beam's swept flux V b that leaves through the right side.
      j["right_outflow_share_" + key] = slip.right_outflow / (kSpeed * kB);
      j["knudsen_" + key] = mean_free_path(p) / kGap;
      series[key].push_back(slip.damping);
    }
    bench::emit(j);
  }
  if (spacings.size() < 3) return 0;
  nlohmann::json r;
  r["richardson_h_um"] = std::vector<double>(spacings.end() - 3, spacings.end());
  for (const auto& [key, c] : series) {
    const Real c1 = c[c.size() - 3], c2 = c[c.size() - 2], c3 = c.back();
    const Real order = std::log2((c1 - c2) / (c2 - c3));
    const Real limit = c3 + (c3 - c2) / (std::pow(2.0, order) - 1);
    r["c_" + key] = {{"order", order},
                     {"extrapolated", limit},
                     {"finest_error", std::abs(limit - c3)},
                     {"order2_extrapolated", c3 + (c3 - c2) / 3}};
  }
  bench::emit(r);
}

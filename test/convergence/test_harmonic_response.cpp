// The structural harmonic analysis (analysis.type: harmonic, physics/structure/
// structural_analysis.hpp) against closed forms, with the observed order over three meshes.
//
// 1. Simply supported plate strip (Mindlin-Reissner plate, nu = 0, free long edges: a
//    Timoshenko beam; L = 1 m, h = 10 mm, width L/10; rotations quasi-static, as in the
//    transients) under a uniform pressure q exp(i w t): by modes, w(x) = sum over odd n of
//      (4 q / (n pi)) sin(k_n x) / (K_n - rho h w^2),   K_n = D k_n^4 / (1 + D k_n^2/(kappa G h)),
//    k_n = n pi / L, undamped, so the response is real: in phase below the first resonance, in
//    antiphase between the first and the third. The centre deflection at 0.5, 1.5 and 5 times
//    the first natural frequency, 20/40/80 x 2 cells. Measured: errors 1.7e-4 ... 6.6e-4 on 80
//    cells, orders 1.96-2.02.
// 2. Its quasi-static limit: at 1e-6 of the first frequency the response is the static solve's
//    to 1e-9, with one factorisation for the whole sweep.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <string>

#include "../support/convergence_order.hpp"
#include "io/case_file.hpp"
#include "io/probes.hpp"
#include "physics/structure/structural_analysis.hpp"
#include "physics/structure/structure_from_case.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using std::numbers::pi;

namespace {

constexpr double L = 1.0, h = 0.01, E = 200e9, rho = 7854, q = 1e3;

std::string strip(int nx, const std::string& analysis) {
  return fmt::format(
      "mesh: {{type: rectangle, lower: [0 m, 0 m], size: [{} m, {} m], cells: [{}, 2]}}\n"
      "material: {{E: 200 GPa, nu: 0, density: 7854 kg/m^3}}\n"
      "model: {{structure: plate, thickness: {} m}}\n"
      "boundaries: {{left: {{type: simply_supported}}, right: {{type: simply_supported}}, "
      "bottom: {{type: free}}, top: {{type: free}}}}\n"
      "pressure: {{value: {} Pa}}\n"
      "probes: [{{name: centre, at: [0.5 m, 0.05 m]}}]\n"
      "analysis: {}\n",
      L, L / 10, nx, h, q, analysis);
}

// The centre deflection at each frequency, from the analysis's outputs.
struct CentreResponse : AnalysisObserver {
  const StructuralModel& model;
  std::vector<Probe> probes;
  std::vector<std::complex<double>> w;
  CentreResponse(const StructuralModel& m, std::vector<Probe> p) : model(m), probes(std::move(p)) {}
  void output(int, Real, std::span<const Real>, std::span<const Real>) override {}
  void harmonic_output(int, Real, Real t, std::span<const Real> re,
                       std::span<const Real> im) override {
    w.emplace_back(model.probe_values(probes, t, re)[0][0],
                   model.probe_values(probes, t, im)[0][0]);
  }
};

std::vector<std::complex<double>> centre_response(int nx, const std::string& analysis,
                                                  AnalysisStats* stats = nullptr) {
  const CaseFile cf = CaseFile::parse(strip(nx, analysis), "strip.yaml");
  const AnalysisType type = read_analysis_type(cf.root());
  std::unique_ptr<StructuralModel> model = build_structure(cf.root(), "", type);
  const AnalysisSettings settings = read_analysis_settings(cf.root(), *model);
  CentreResponse observer(*model, read_probes(cf.root().child("probes"), model->structure_mesh()));
  ProgressReporter quiet(true, 0.0);
  const AnalysisStats s = run_analysis(*model, settings, observer, quiet);
  if (stats) *stats = s;
  return observer.w;
}

double stiffness(int n) {
  const double D = E * h * h * h / 12, S = 5.0 / 6.0 * E / 2 * h, k = n * pi / L;
  return D * std::pow(k, 4) / (1 + D * k * k / S);
}

double exact_centre(double omega) {
  double w = 0;
  for (int n = 1; n < 20001; n += 2)
    w += 4 * q / (n * pi) * std::sin(n * pi / 2) / (stiffness(n) - rho * h * omega * omega);
  return w;
}

}  // namespace

TEST(HarmonicResponse, PlateStripFollowsTheModalSeriesAtSecondOrder) {
  const double f1 = std::sqrt(stiffness(1) / (rho * h)) / (2 * pi);
  const double ratios[3] = {0.5, 1.5, 5.0};
  std::string list = "[";
  for (double r : ratios) list += fmt::format("{}{} Hz", list.size() > 1 ? ", " : "", r * f1);
  list += "]";
  double error[3][3];
  const int meshes[3] = {20, 40, 80};
  for (int m = 0; m < 3; ++m) {
    const auto w = centre_response(meshes[m], "{type: harmonic, frequencies: " + list + "}");
    ASSERT_EQ(w.size(), 3u);
    for (int k = 0; k < 3; ++k) {
      const double exact = exact_centre(2 * pi * ratios[k] * f1);
      error[k][m] = std::abs(w[k] / exact - 1.0);
      std::printf("strip %2d x 2, f = %.1f f1: w = %+.8e %+.2e i, exact %+.8e, error %.3e\n",
                  meshes[m], ratios[k], w[k].real(), w[k].imag(), exact, error[k][m]);
      EXPECT_LT(std::abs(w[k].imag()), 1e-12 * std::abs(w[k].real()));  // undamped: real
    }
  }
  for (int k = 0; k < 3; ++k) {
    const double p =
        test_support::fitted_order({4.0, 2.0, 1.0}, {error[k][0], error[k][1], error[k][2]});
    std::printf("f = %.1f f1: observed order %.2f\n", ratios[k], p);
    EXPECT_GE(p, 1.8) << ratios[k];
    EXPECT_LT(error[k][2], 2e-3) << ratios[k];
  }
  // In phase below the first resonance, in antiphase above it.
  EXPECT_GT(exact_centre(2 * pi * 0.5 * f1) / q, 0);
  EXPECT_LT(exact_centre(2 * pi * 1.5 * f1) / q, 0);
}

TEST(HarmonicResponse, QuasiStaticLimitIsTheStaticSolution) {
  const double f1 = std::sqrt(stiffness(1) / (rho * h)) / (2 * pi);
  AnalysisStats stats;
  const auto w = centre_response(
      40,
      fmt::format("{{type: harmonic, sweep: {{from: {} Hz, to: {} Hz, points: 3}}}}", 1e-6 * f1,
                  2e-6 * f1),
      &stats);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(stats.harmonic.factorizations, 1);
  EXPECT_EQ(stats.harmonic.refactorizations, 2);
  EXPECT_NEAR(stats.harmonic.frequencies[1], std::sqrt(2.0) * 1e-6 * f1, 1e-12 * f1);
  const CaseFile cf = CaseFile::parse(strip(40, "{type: static}"), "strip.yaml");
  std::unique_ptr<StructuralModel> model = build_structure(cf.root(), "", AnalysisType::Static);
  const StaticSolution s = solve_static(model->structure(), model->ramp_end_time());
  const std::vector<Probe> probes = read_probes(cf.root().child("probes"), model->structure_mesh());
  const double static_w = model->probe_values(probes, 0.0, s.y)[0][0];
  std::printf("quasi-static limit: w = %.10e, static %.10e\n", w[0].real(), static_w);
  EXPECT_NEAR(w[0].real() / static_w, 1.0, 1e-9);
}

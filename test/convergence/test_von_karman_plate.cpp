// The von Karman plate (physics/plate/von_karman_plate.hpp) against closed forms, with observed
// orders over three meshes, and its Newton iteration.
//
// 1. Cylindrical bending of a long strip with immovable edges (Timoshenko & Woinowsky-Krieger,
//    Theory of Plates and Shells, ch. 1): span l, uniform pressure q, the edges clamped or
//    simply supported and held in-plane (u = 0). The strip bends into a cylinder and its
//    mid-surface stretches under a constant axial force S per unit width; with x measured from
//    the middle of the span,
//      D w'''' - S w'' = q,
//    w = A + B cosh(k x) - q x^2/(2 S), k = sqrt(S/D), u = k l/2 (Timoshenko's tension
//    parameter), and the end conditions give
//      clamped  (w = w' = 0):  w' = (q/S) [(l/2) sinh(k x)/sinh(u) - x],
//                              w(0) = (q/S) [l^2/8 - (l/(2k)) (cosh u - 1)/sinh u]
//      simply supported (w = w'' = 0):
//                              w' = (q/S) [sinh(k x)/(k cosh u) - x],
//                              w(0) = (q/S) [l^2/8 - (1 - 1/cosh u)/k^2]
//    (the latter is Timoshenko's w0 = 5 q l^4/(384 D) f0(u)). The edges do not move, so the
//    stretching of the span is that of its slope alone:
//      S l / C = 1/2 int w'^2 dx,   C = E h/(1 - nu^2)
//    a scalar equation for S, solved here by bisection (the integral by Simpson's rule on 4000
//    intervals). nu = 0, so that the plate's free long sides (M n = 0, N n = 0) leave the strip
//    in the plane strain of an infinitely long one (no anticlastic curvature, eps_yy = 0); l/h =
//    1000, so that the shear deflection of the Mindlin plate, ~10 (h/l)^2 of the bending one,
//    stays below the discretisation error. Loads for a centre deflection of 0.5, 1.5 and 3
//    thicknesses; 20, 40, 80 x 2 cells.
// 2. Modes about the deflected state: the clamped strip of 1. at w_c = 1.5 h, built from a case
//    (model.geometric_nonlinearity: true, a modal analysis), linearised about its static state.
//    The perturbation phi of an antisymmetric mode changes the stretching by
//    dS = (C/l) int w' phi' dx = 0 (w' odd, phi' even), so the mode is that of the clamped beam
//    under the constant tension S of the deflected state: D phi'''' - S phi'' = rho h omega^2 phi,
//    phi = phi' = 0 at the ends, its frequency the second zero of the end conditions'
//    determinant. The in-plane displacements and the rotations quasi-static (modal mass zero);
//    40, 80, 160 x 2 cells.
// 3. Newton's iteration: quadratic (the residual norms of a plain Newton iteration with the
//    analytic Jacobian, from rest), KINSOL's iteration counts for the strip, and the linear plate
//    (geometric nonlinearity off) still one step.
#include <fmt/format.h>
// 4. The input contract: the continuum's follower loads and segregated method, shear creep in
//    a creep run, an in-plane release without geometric nonlinearity.
// 5. The default switch as plate and as plane-stress beam: the same rise of its pull-in voltage.
// 6. A strip with an end released in-plane (in_plane: free) does not stretch.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>

#include "../support/convergence_order.hpp"
#include "core/error.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/switch_scene.hpp"
#include "io/case_file.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/creep/creep_case.hpp"
#include "physics/plate/plate_scene.hpp"
#include "physics/plate/von_karman_plate.hpp"
#include "physics/structure/modal_analysis.hpp"
#include "physics/structure/structure_from_case.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using Kind = PlateBoundary::Kind;

namespace {

constexpr double E = 200e9, l = 1.0, h = 1e-3;

// Bisection of a function with f(lo) > 0 > f(hi) (or the reverse), on a log scale.
double log_bisect(const std::function<double(double)>& f, double lo, double hi) {
  const double f_lo = f(lo);
  for (int i = 0; i < 60; ++i) {
    const double mid = std::sqrt(lo * hi);
    ((f(mid) > 0) == (f_lo > 0) ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

// The strip at tension parameter u (1.): the pressure q that makes the stretching condition
// hold (w' is proportional to q) and the centre deflection.
struct StripState {
  double q, w0;
};
StripState strip_at(bool clamped, double u, double D, double C) {
  const double k = 2 * u / l, S = D * k * k;
  auto slope = [&](double x) {  // w' / q
    return clamped ? (l / 2 * std::sinh(k * x) / std::sinh(u) - x) / S
                   : (std::sinh(k * x) / (k * std::cosh(u)) - x) / S;
  };
  const int n = 4000;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const double x = -l / 2 + l * i / n, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    sum += w * slope(x) * slope(x);
  }
  const double integral = sum * l / (3 * n);  // int (w'/q)^2 dx
  const double q = std::sqrt(S * l / C / (0.5 * integral));
  const double w0 = clamped ? q / S * (l * l / 8 - l / (2 * k) * (std::cosh(u) - 1) / std::sinh(u))
                            : q / S * (l * l / 8 - (1 - 1 / std::cosh(u)) / (k * k));
  return {q, w0};
}

// int_0^1 g(s) ds by Simpson's rule on 2000 intervals.
double simpson_01(const std::function<double(double)>& g) {
  const int n = 2000;
  double sum = 0;
  for (int i = 0; i <= n; ++i) sum += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * g(double(i) / n);
  return sum / (3 * n);
}

struct Strip {
  Mesh mesh;
  PlateSection section{E, 0.0, 7854, h};
  std::unique_ptr<PlateOperator> plate;
  std::unique_ptr<VonKarmanPlate> op;
  Strip(int nx, bool clamped, double q) : mesh(make_mesh(nx)) {
    std::vector<PlateBoundary> bcs(mesh.patches().size());
    for (std::size_t p = 0; p < bcs.size(); ++p) {
      const std::string& name = mesh.patches()[p].name;
      bcs[p].kind = name == "left" || name == "right"
                        ? (clamped ? Kind::Clamped : Kind::SimplySupportedHard)
                        : Kind::Free;
    }
    plate =
        std::make_unique<PlateOperator>(mesh, section, bcs, [q](const Vec3&, double) { return q; });
    op = std::make_unique<VonKarmanPlate>(*plate);
  }
  static Mesh make_mesh(int nx) {
    BoxSpec spec;
    spec.upper = Vec3(l, l / 10, 0);
    spec.n[0] = nx;
    spec.n[1] = 2;
    return make_structured_mesh(spec);
  }
  // The mean of the four centre cells' reconstructions at the centre.
  double centre(std::span<const double> y) const {
    const Vec3 c(l / 2, l / 20, 0);
    double w = 0;
    int count = 0;
    for (Index k = 0; k < mesh.n_cells(); ++k)
      if (std::abs(mesh.cell_centroid(k).x() - c.x()) < l / (mesh.n_cells() / 2)) {
        w += plate->deflection_at(k, c, 0.0, y);
        ++count;
      }
    EXPECT_EQ(count, 4);
    return w / count;
  }
};

}  // namespace

TEST(VonKarmanPlate, CylindricalBendingOfAStripWithImmovableEdges) {
  const PlateSection section{E, 0.0, 7854, h};
  const double D = section.bending_stiffness(), C = E * h;
  for (bool clamped : {true, false}) {
    for (double target : {0.5, 1.5, 3.0}) {
      const double u = log_bisect(
          [&](double u) { return strip_at(clamped, u, D, C).w0 - target * h; }, 1e-2, 1e2);
      const auto [q, exact] = strip_at(clamped, u, D, C);
      double error[3];
      const int meshes[3] = {40, 80, 160};
      for (int m = 0; m < 3; ++m) {
        Strip strip(meshes[m], clamped, q);
        const StaticSolution sol = solve_static(*strip.op, 0.0);
        const double w = strip.centre(sol.y);
        error[m] = std::abs(w / exact - 1);
        std::printf(
            "%s strip, u = %.4f, q l^4/(E h^4) = %8.3f, %2d x 2: w_c/h = %.6f, closed form "
            "%.6f, error %.2e, Newton iterations %ld\n",
            clamped ? "clamped" : "simply supported", u, q * std::pow(l / h, 4) / E, meshes[m],
            w / h, exact / h, error[m], sol.stats.newton_iters);
      }
      const double p = test_support::fitted_order({4.0, 2.0, 1.0}, {error[0], error[1], error[2]});
      std::printf("  observed order %.2f\n", p);
      EXPECT_GE(p, 1.8);
      EXPECT_LT(error[2], 5e-4);
    }
  }
}

// The k-th natural frequency [rad/s] of the clamped-clamped beam D w'''' - S w'' = m omega^2 w
// on [0, L] per unit width: the k-th sign change of the end conditions' determinant.
double clamped_beam_in_tension(double D, double S, double m, double L, int k) {
  auto det = [&](double omega) {
    const double disc = std::sqrt(S * S / (4 * D * D) + m * omega * omega / D);
    const double a = std::sqrt(S / (2 * D) + disc), b = std::sqrt(disc - S / (2 * D));
    Eigen::Matrix4d A;
    A << 1, 0, 1, 0,  //
        0, a, 0, b,   //
        std::cosh(a * L), std::sinh(a * L), std::cos(b * L), std::sin(b * L), a * std::sinh(a * L),
        a * std::cosh(a * L), -b * std::sin(b * L), b * std::cos(b * L);
    return A.determinant() / std::cosh(a * L);
  };
  // From below the first root (the pinned string's and the stress-free beam's are below it).
  double lo = 0.5 * std::min(M_PI / L * std::sqrt(S / m), std::pow(4.73 / L, 2) * std::sqrt(D / m));
  if (S == 0) lo = 0.5 * std::pow(4.73 / L, 2) * std::sqrt(D / m);
  double hi = lo * 1.001;
  for (int found = 0;; lo = hi, hi *= 1.001) {
    if (det(lo) * det(hi) > 0) continue;
    if (++found == k) break;
  }
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (det(lo) * det(mid) <= 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(VonKarmanPlate, AntisymmetricModeAboutTheDeflectedStateIsTheBeamInTension) {
  const double rho = 7854;
  const PlateSection section{E, 0.0, rho, h};
  const double D = section.bending_stiffness(), C = E * h;
  const double u =
      log_bisect([&](double u) { return strip_at(true, u, D, C).w0 - 1.5 * h; }, 1e-2, 1e2);
  const double q = strip_at(true, u, D, C).q, S = D * std::pow(2 * u / l, 2);
  const double exact = clamped_beam_in_tension(D, S, rho * h, l, 2) / (2 * M_PI);
  const double free_beam = clamped_beam_in_tension(D, 0.0, rho * h, l, 2) / (2 * M_PI);
  double error[3];
  const int meshes[3] = {40, 80, 160};
  for (int m = 0; m < 3; ++m) {
    const std::string text = fmt::format(
        "mesh: {{type: rectangle, lower: [0 m, 0 m], size: [{} m, {} m], cells: [{}, 2]}}\n"
        "material: {{E: {} Pa, nu: 0, density: {} kg/m^3}}\n"
        "model: {{structure: plate, thickness: {} m, geometric_nonlinearity: true}}\n"
        "boundaries: {{left: {{type: clamped}}, right: {{type: clamped}}, bottom: {{type: free}}, "
        "top: {{type: free}}}}\n"
        "pressure: {{value: {} Pa}}\n",
        l, l / 10, meshes[m], E, rho, h, q);
    const CaseFile cf = CaseFile::parse(text, "strip.yaml");
    std::unique_ptr<StructuralModel> model = build_structure(cf.root(), "", AnalysisType::Modal);
    const StructuralModes modes = structural_modes(*model, 4, 0.0);
    EXPECT_GT(modes.stats.newton.newton_iters, 1);  // the deflected state, by Newton
    // The first mode whose w is antisymmetric about the middle of the span.
    const Mesh& mesh = model->structure_mesh();
    double f = 0;
    for (std::size_t k = 0; k < modes.shapes.size() && f == 0; ++k) {
      double odd = 0, even = 0;
      for (Index c = 0; c < mesh.n_cells(); ++c) {
        const Vec3 x = mesh.cell_centroid(c);
        for (Index d = 0; d < mesh.n_cells(); ++d) {
          const Vec3 y = mesh.cell_centroid(d);
          if (std::abs(x.x() + y.x() - l) < 1e-9 && std::abs(x.y() - y.y()) < 1e-9) {
            odd += std::abs(modes.shapes[k][3 * c] + modes.shapes[k][3 * d]);
            even += std::abs(modes.shapes[k][3 * c] - modes.shapes[k][3 * d]);
          }
        }
      }
      if (odd < 1e-6 * even) f = modes.stats.modes[k].frequency;
    }
    ASSERT_GT(f, 0.0) << "no antisymmetric mode among the first four";
    error[m] = std::abs(f / exact - 1);
    std::printf(
        "clamped strip at w_c = 1.5 h (S l^2/D = %.2f), %3d x 2: antisymmetric mode %.6f Hz, beam "
        "in tension %.6f Hz (stress-free %.6f Hz), error %.2e\n",
        S * l * l / D, meshes[m], f, exact, free_beam, error[m]);
  }
  const double p = test_support::fitted_order({4.0, 2.0, 1.0}, {error[0], error[1], error[2]});
  std::printf("  observed order %.2f\n", p);
  EXPECT_GE(p, 1.8);
  EXPECT_LT(error[2], 1e-3);
}

TEST(VonKarmanPlate, NewtonConvergesQuadratically) {
  // The clamped strip at w_c = 3 h (q l^4/(E h^4) = 718.6), 80 x 2 cells, from rest.
  Strip strip(80, true, 718.601 * E * std::pow(h / l, 4));
  VonKarmanPlate& op = *strip.op;
  const Index n = op.size();
  std::vector<double> y(n, 0.0), r(n), values(op.stiffness_pattern().nnz());
  const CsrPattern& pattern = op.stiffness_pattern();
  std::vector<double> norms;
  for (int it = 0; it < 30; ++it) {
    op.internal_residual(0.0, y, r);
    norms.push_back(Eigen::Map<Eigen::VectorXd>(r.data(), n).lpNorm<Eigen::Infinity>());
    std::printf("Newton iteration %2d: ||R||_inf = %.3e\n", it, norms.back());
    // Stop at the round-off floor (the residual no longer halves).
    if (norms.size() > 2 && norms.back() > 0.5 * norms[norms.size() - 2] &&
        norms.back() < 1e-6 * *std::max_element(norms.begin(), norms.end()))
      break;
    op.stiffness(0.0, y, values);
    std::vector<Eigen::Triplet<double>> triplets;
    for (Index i = 0; i < n; ++i)
      for (Index k = pattern.row_ptr[i]; k < pattern.row_ptr[i + 1]; ++k)
        triplets.emplace_back(i, pattern.col_idx[k], values[k]);
    Eigen::SparseMatrix<double> K(n, n);
    K.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(K);
    ASSERT_EQ(lu.info(), Eigen::Success);
    const Eigen::VectorXd dy = lu.solve(Eigen::Map<Eigen::VectorXd>(r.data(), n));
    for (Index i = 0; i < n; ++i) y[i] -= dy[i];
  }
  const std::size_t m = norms.size() - 2;  // the first iterate at the floor
  ASSERT_LT(norms[m], 1e-8 * *std::max_element(norms.begin(), norms.end())) << "not converged";
  // The last two reductions above round-off: log(r_k+1 / r_k) / log(r_k / r_k-1) -> 2.
  const double order =
      std::log(norms[m - 1] / norms[m - 2]) / std::log(norms[m - 2] / norms[m - 3]);
  std::printf("Newton: %zu iterations, order of the last reductions %.2f\n", m, order);
  EXPECT_GT(order, 1.8);
  EXPECT_LE(m, 15u);

  // KINSOL's iteration on the same plate, and the linear plate's one step.
  const StaticSolution nonlinear = solve_static(op, 0.0);
  std::printf("KINSOL: von Karman plate %ld Newton iterations, w_c/h = %.5f\n",
              nonlinear.stats.newton_iters, strip.centre(nonlinear.y) / h);
  EXPECT_GT(nonlinear.stats.newton_iters, 3);
  EXPECT_LE(nonlinear.stats.newton_iters, 15);
  EXPECT_NEAR(strip.centre(nonlinear.y) / h, strip.centre(y) / h, 1e-6);
  const StaticSolution linear = solve_static(*strip.plate, 0.0);
  std::printf("KINSOL: linear plate %ld Newton iteration, w_c/h = %.3f\n",
              linear.stats.newton_iters, strip.centre(linear.y) / h);
  EXPECT_EQ(linear.stats.newton_iters, 1);
}

// The input contract: a pressure boundary (a follower load) or the segregated method with the
// large-deformation continuum, and transverse shear creep with the key in a creep run, are bad
// input naming the file, the key and its value.
TEST(VonKarmanPlate, UnsupportedCombinationsAreInputErrors) {
  auto message = [](const std::function<void()>& build) {
    try {
      build();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  const std::string plane =
      "mesh: {type: rectangle, lower: [0 um, 0 um], size: [400 um, 10 um], cells: [8, 2]}\n"
      "material: {E: 200 GPa, nu: 0.3}\n"
      "model: {structure: plane, geometric_nonlinearity: true}\n"
      "boundaries: {left: {type: fixed}, right: {type: free}, bottom: {type: free}, top: {type: "
      "pressure, value: 1 kPa}}\n";
  const std::string pressure = message(
      [&] { build_structure(CaseFile::parse(plane, "c.yaml").root(), "", AnalysisType::Static); });
  EXPECT_NE(pressure.find("c.yaml: key 'boundaries.top.type' = 'pressure': a pressure follows"),
            std::string::npos)
      << pressure;
  const std::string segregated = message([&] {
    const CaseFile cf =
        CaseFile::parse(plane, "c.yaml", {"model.stress=segregated", "boundaries.top.type=free"});
    build_structure(cf.root(), "", AnalysisType::Static);
  });
  EXPECT_NE(segregated.find("c.yaml: key 'model.stress' = 'segregated'"), std::string::npos)
      << segregated;
  const std::string released = message([] {
    const CaseFile cf = CaseFile::parse(
        "mesh: {type: rectangle, lower: [0 um, 0 um], size: [400 um, 40 um], cells: [8, 2]}\n"
        "material: {E: 200 GPa, nu: 0.3}\n"
        "model: {structure: plate, thickness: 2 um}\n"
        "boundaries: {left: {type: clamped, in_plane: free}, right: {type: clamped}, bottom: "
        "{type: free}, top: {type: free}}\n",
        "p.yaml");
    build_structure(cf.root(), "", AnalysisType::Static);
  });
  EXPECT_NE(released.find("p.yaml: key 'boundaries.left.in_plane' = 'free': is for the von Karman"),
            std::string::npos)
      << released;
  const std::string creep = message([] {
    const std::string path = std::string(RFMEMS_SOURCE_DIR) + "/cases/creep_switch_hold/case.yaml";
    const CaseFile cf =
        CaseFile::load(path, {"model.geometric_nonlinearity=true", "creep.shear_creep=true"});
    read_creep_case(cf.root(), std::filesystem::path(path).parent_path().string());
  });
  EXPECT_NE(creep.find("case.yaml: key 'creep.shear_creep' = 'true': not with "
                       "model.geometric_nonlinearity"),
            std::string::npos)
      << creep;
}

// The default switch (cases/switch_plate, no gas) as the plate and as the plane-stress beam of
// cases/switch_plane_laplace with the parallel-plate field: two independent large-deflection
// models (von Karman plate; total Lagrangian continuum) raise the quasi-static pull-in voltage
// by the same factor (measured 1.05378 and 1.05404; the linear voltages differ by 0.5 %).
TEST(VonKarmanPlate, PlateAndPlaneSwitchesStiffenAlike) {
  double rise[2];
  const char* names[2] = {"switch_plate", "switch_plane_laplace"};
  for (int k = 0; k < 2; ++k) {
    double voltage[2];
    for (int nonlinear = 0; nonlinear < 2; ++nonlinear) {
      const std::string path = std::string(RFMEMS_SOURCE_DIR) + "/cases/" + names[k] + "/case.yaml";
      std::vector<std::string> overrides = {
          "actuation.electrostatics=parallel_plate",
          std::string("model.geometric_nonlinearity=") + (nonlinear ? "true" : "false")};
      if (k == 0) overrides.push_back("gas.model=none");
      const CaseFile cf = CaseFile::load(path, overrides);
      SwitchScene scene =
          build_switch_scene(cf.root(), std::filesystem::path(path).parent_path().string());
      QuasiStaticOptions o;
      o.voltage_tolerance = 1e-4;
      voltage[nonlinear] = trace_pull_in(*scene.actuation, scene.control, o).pull_in_voltage;
    }
    rise[k] = voltage[1] / voltage[0];
    std::printf("%s: V_PI %.4f V linear, %.4f V with stretching (x %.5f)\n", names[k], voltage[0],
                voltage[1], rise[k]);
  }
  EXPECT_GT(rise[0], 1.04);
  EXPECT_NEAR(rise[0], rise[1], 1e-3);
}

// The clamped strip of 1. with its right end released in-plane (boundaries.right.in_plane: free,
// from a case): nothing holds the span's length, so no membrane force builds up (N = 0), the
// deflection is the linear plate's, and the end slides in by the shortening of the deflected
// span, u(x) = -1/2 int_0^x w'^2, with w' = q x (l - x)(l - 2x)/(12 D) of the clamped beam.
TEST(VonKarmanPlate, AStripWithASlidingEndDoesNotStretch) {
  const double D = PlateSection{E, 0.0, 7854, h}.bending_stiffness();
  const double q = 718.601 * E * std::pow(h / l, 4);  // w_c = 3 h immovable, 22.5 h linear
  const int nx = 80;
  double w[2];
  std::vector<double> y;
  std::unique_ptr<StructuralModel> model;
  for (int nonlinear = 0; nonlinear < 2; ++nonlinear) {
    const std::string text = fmt::format(
        "mesh: {{type: rectangle, lower: [0 m, 0 m], size: [{} m, {} m], cells: [{}, 2]}}\n"
        "material: {{E: {} Pa, nu: 0}}\n"
        "model: {{structure: plate, thickness: {} m, geometric_nonlinearity: {}}}\n"
        "boundaries: {{left: {{type: clamped}}, right: {{type: clamped{}}}, bottom: {{type: "
        "free}}, top: {{type: free}}}}\n"
        "pressure: {{value: {} Pa}}\n",
        l, l / 10, nx, E, h, nonlinear ? "true" : "false", nonlinear ? ", in_plane: free" : "", q);
    const CaseFile cf = CaseFile::parse(text, "strip.yaml");
    model = build_structure(cf.root(), "", AnalysisType::Static);
    const StaticSolution sol = solve_static(model->structure(), 0.0);
    const auto& plate = *dynamic_cast<PlateScene&>(*model).op;
    w[nonlinear] =
        plate.deflection_at(nx / 2, Vec3(l / 2, l / 20, 0), 0.0, sol.y);  // a centre cell
    y = sol.y;
  }
  // The end cells' u against -1/2 int_0^x w'^2 dx at their centroids.
  const auto& vk = *dynamic_cast<PlateScene&>(*model).von_karman;
  const Mesh& mesh = model->structure_mesh();
  double worst = 0, end_u = 0, end_exact = 0;
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    const double x = mesh.cell_centroid(c).x();
    const double exact = -0.5 * x * simpson_01([&](double s) {
      const double xi = s * x;
      return std::pow(q * xi * (l - xi) * (l - 2 * xi) / (12 * D), 2);
    });
    const double u = y[vk.in_plane_index(c, 0)];
    worst = std::max(worst, std::abs(u - exact));
    if (x > l - l / nx) end_u = u, end_exact = exact;
  }
  std::printf(
      "sliding strip: w_c %.6e m (linear plate %.6e), end u %.6e m (-1/2 int w'^2: %.6e), worst "
      "|u - exact| / |u_end| = %.2e\n",
      w[1], w[0], end_u, end_exact, worst / std::abs(end_exact));
  EXPECT_NEAR(w[1] / w[0], 1.0, 1e-4);
  EXPECT_LT(worst, 5e-3 * std::abs(end_exact));
}

// Residual stress (material.residual_stress, physics/structure/residual_stress.hpp): the
// geometric stiffness of an initial stress in the plate and the plane continuum, against closed
// forms, with observed orders over three meshes.
//
// 1. Simply supported square plate (hard support, side a = 1 m, a/h = 100, nu = 0.3) under a
//    uniform pressure q and an isotropic membrane force N = h sigma0. Navier's series for the
//    Mindlin plate: each mode sin(m pi x/a) sin(n pi y/a) of the load, q_mn = 16 q/(pi^2 m n)
//    (m, n odd), deflects by
//      W_mn = q_mn / (K_mn + N k^2),   1/K_mn = 1/(D k^4) + 1/(kappa G h k^2),
//    k^2 = (m^2 + n^2) pi^2/a^2 (from div Q + N lap w + q = 0, div div M = div Q, with the
//    moment and shear relations; N = 0 gives the series of test_plate_simply_supported). The
//    centre deflection summed to m, n <= 399. Tension parameters N/(D k_11^2) = 1 and 10, and a
//    compression of half the buckling load N_cr = -D k_11^2 (which doubles the deflection).
//    20 x 20, 40 x 40, 80 x 80 cells; one Newton step each. Measured: errors 1.2e-4, 1.3e-4,
//    6.5e-5 on 80 x 80, orders 1.96, 1.87, 2.01 from 40 x 40.
// 2. Simply supported strip in tension (plate, nu = 0, free long sides, uniaxial sigma_xx, the
//    stress a released bridge keeps): w = sin(k x), k = n pi/L, rotations quasi-static,
//      rho h omega_n^2 = D k^4 / (1 + D k^2/(kappa G h)) + N k^2.
//    Modes 1-3, tension N L^2/(pi^2 D) = 1.2 and 12, 20/40/80 x 2 cells. Measured: errors
//    6.4e-5 to 5.7e-4 on 80 x 2, orders 1.90-2.00.
// 3. Clamped-clamped beam in tension (plate strip, L/h = 1000): D w'''' - N w'' = rho h omega^2
//    w, w = w' = 0 at both ends; w = A cosh(a x) + B sinh(a x) + C cos(b x) + E sin(b x) with
//    a^2, -b^2 the roots of D s^2 - N s - rho h omega^2 = 0, and omega_1 the first zero of the
//    4 x 4 determinant of the end conditions (bisection; at N = 0 it is (4.7300407 / L)^2
//    sqrt(D/(rho h)), checked). N L^2/D = 30 and 300 (frequency 1.31 and 2.79 times the
//    stress-free beam's), 40/80/160 x 2 cells. Measured: errors 2.0e-4 and 3.4e-4 on 160 x 2,
//    orders 1.95 and 1.87.
// 4. The plane-stress continuum beam of cases/fixed_fixed_beam (L = 400 um, h = 8 um) in
//    tension sigma_xx = 100 MPa (N L^2/(E I) = 15): the rise of its first frequency over the
//    stress-free beam against Euler-Bernoulli's (3. with E I per unit depth), where the
//    continuum's shear and clamped faces, a few 1e-3 of each frequency, largely cancel.
//    Measured on 160 x 16: rise 1.168811 against 1.168554 (+2.2e-4).
// 5. Pull-in of a tension-dominated membrane: the default switch (cases/switch_plate, no gas,
//    nu = 0, 320 x 4 cells) thinned to h = 1 and 0.5 um under sigma_xx = 100 MPa. The string
//    N w'' = -eps0 V^2/(2 (g - w)^2), w = 0 at both ends, in u = w/g and x/L is
//    u'' = -lambda/(1 - u)^2 with lambda = eps0 V^2 L^2/(2 N g^3); its first integral gives the
//    closed form sqrt(lambda) = sqrt(2 (1 - u_m)) [sqrt(u_m) + (1 - u_m) ln((1 + sqrt(u_m)) /
//    sqrt(1 - u_m))] for the centre deflection u_m, whose maximum is the fold, lambda* = 1.40002
//    at u_m = 0.388 (Pelesko & Bernstein, Modeling MEMS and NEMS, 2003: 1.400). The clamps add
//    a bending layer of width l = sqrt(D/N) at each end, where the slope goes to zero; to first
//    order in eps = l/L the string then spans L - 2 l, so V_PI = V_string/(1 - 2 eps), and the
//    rest is O(eps^2). Measured: 1 + 4.2e-3 (eps = 0.032) and 1 + 9.6e-4 (eps = 0.016).
// 6. cases/switch_prestressed against cases/switch_plate (no gas, both linear: the case's
//    geometric nonlinearity off): the stress raises the quasi-static pull-in voltage and the
//    first frequency by the same factor, both going as the square root of one stiffness
//    (measured 1.22381 and 1.22289).
// 7. The input contract: a stress across a free edge, and a wrong number of components.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>

#include "../support/convergence_order.hpp"
#include "core/error.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/switch_scene.hpp"
#include "io/case_file.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/plate/plate_operator.hpp"
#include "physics/structure/modal_analysis.hpp"
#include "physics/structure/structure_from_case.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using Kind = PlateBoundary::Kind;
using std::numbers::pi;

namespace {

constexpr double E = 200e9, rho = 7854;

double order(const double (&e)[3]) {
  return test_support::fitted_order({4.0, 2.0, 1.0}, {e[0], e[1], e[2]});
}

// Centre deflection of the simply supported Mindlin plate (1.), side a, load q.
double navier_centre(const PlateSection& s, double a, double q, double N) {
  const double D = s.bending_stiffness(), S = s.shear_stiffness();
  double w = 0;
  for (int m = 1; m < 400; m += 2)
    for (int n = 1; n < 400; n += 2) {
      const double sign = ((m + n) / 2 - 1) % 2 == 0 ? 1.0 : -1.0;
      const double k2 = (double(m) * m + double(n) * n) * pi * pi / (a * a);
      const double K = 1 / (1 / (D * k2 * k2) + 1 / (S * k2));
      w += sign * 16 * q / (pi * pi * m * n) / (K + N * k2);
    }
  return w;
}

// The plate's centre deflection, the mean of the four cells' reconstructions at the centre.
double plate_centre(const PlateSection& s, double a, double q, int n) {
  BoxSpec spec;
  spec.upper = Vec3(a, a, 0);
  spec.n[0] = n;
  spec.n[1] = n;
  Mesh mesh = make_structured_mesh(spec);
  std::vector<PlateBoundary> bcs(mesh.patches().size(),
                                 PlateBoundary{Kind::SimplySupportedHard, {}});
  PlateOperator op(mesh, s, bcs, [q](const Vec3&, double) { return q; });
  StaticSolution sol = solve_static(op, 0.0);
  EXPECT_EQ(sol.stats.newton_iters, 1);
  const Vec3 centre(a / 2, a / 2, 0);
  double w = 0;
  int count = 0;
  for (Index c = 0; c < mesh.n_cells(); ++c)
    if ((mesh.cell_centroid(c) - centre).cwiseAbs().maxCoeff() < a / n) {
      w += op.deflection_at(c, centre, 0.0, sol.y);
      ++count;
    }
  EXPECT_EQ(count, 4);
  return w / count;
}

StructuralModes modes_of(const std::string& text, Index n_modes) {
  const CaseFile cf = CaseFile::parse(text, "prestressed.yaml");
  std::unique_ptr<StructuralModel> model = build_structure(cf.root(), "", AnalysisType::Modal);
  return structural_modes(*model, n_modes, 0.0);
}

std::string plate_strip(double L, double h, int nx, const std::string& ends, double sigma) {
  return fmt::format(
      "mesh: {{type: rectangle, lower: [0 m, 0 m], size: [{} m, {} m], cells: [{}, 2]}}\n"
      "material: {{E: 200 GPa, nu: 0, density: 7854 kg/m^3, residual_stress: [{} Pa, 0 Pa, 0 "
      "Pa]}}\n"
      "model: {{structure: plate, thickness: {} m}}\n"
      "boundaries: {{left: {{type: {}}}, right: {{type: {}}}, bottom: {{type: free}}, top: "
      "{{type: free}}}}\n",
      L, L / 10, nx, sigma, h, ends, ends);
}

// The first natural frequency of the clamped-clamped beam D w'''' - N w'' = m omega^2 w on
// [0, L] (3.), per unit width: the first sign change of the end-condition determinant, found
// by scanning up and bisecting.
double clamped_clamped_tension(double D, double N, double m, double L) {
  auto det = [&](double omega) {
    const double disc = std::sqrt(N * N / (4 * D * D) + m * omega * omega / D);
    const double a = std::sqrt(N / (2 * D) + disc), b = std::sqrt(disc - N / (2 * D));
    Eigen::Matrix4d A;
    A << 1, 0, 1, 0,  //
        0, a, 0, b,   //
        std::cosh(a * L), std::sinh(a * L), std::cos(b * L), std::sin(b * L), a * std::sinh(a * L),
        a * std::cosh(a * L), -b * std::sin(b * L), b * std::cos(b * L);
    return A.determinant() / std::cosh(a * L);
  };
  // Tension and clamping only add stiffness: omega_1 is above the stress-free beam's and the
  // pinned string's.
  const double start =
      0.99 * std::max(pi / L * std::sqrt(N / m), std::pow(4.73 / L, 2) * std::sqrt(D / m));
  double lo = start, hi = start * 1.01;
  while (det(lo) * det(hi) > 0) lo = hi, hi *= 1.01;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (det(lo) * det(mid) <= 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST(ResidualStress, SimplySupportedPlateUnderTensionAndCompressionMatchesNavier) {
  const double a = 1.0, q = 1e3;
  PlateSection s{E, 0.3, rho, a / 100};
  const double N_cr = s.bending_stiffness() * 2 * pi * pi / (a * a);  // D k_11^2
  for (double ratio : {1.0, 10.0, -0.5}) {
    const double N = ratio * N_cr;
    s.residual_stress = Mat3::Zero();
    s.residual_stress(0, 0) = s.residual_stress(1, 1) = N / s.thickness;
    const double exact = navier_centre(s, a, q, N);
    double error[3];
    const int meshes[3] = {20, 40, 80};
    for (int m = 0; m < 3; ++m) {
      const double w = plate_centre(s, a, q, meshes[m]);
      error[m] = std::abs(w / exact - 1);
      std::printf(
          "SS plate N = %+5.1f N_cr (sigma0 %+.4g MPa), %2d x %2d: w_c = %.8e, Navier "
          "%.8e, error %.3e\n",
          ratio, N / s.thickness * 1e-6, meshes[m], meshes[m], w, exact, error[m]);
    }
    // The order of the two finer meshes: at 10 N_cr the bending layer along the supports,
    // sqrt(D/N) = a/14 wide, spans a cell and a half of the coarsest mesh.
    const double p = test_support::fitted_order({2.0, 1.0}, {error[1], error[2]});
    std::printf("SS plate N = %+5.1f N_cr: observed order %.2f (fitted over three meshes %.2f)\n",
                ratio, p, order(error));
    EXPECT_GE(p, 1.8) << "N/N_cr = " << ratio;
    EXPECT_LT(error[2], 2e-4) << "N/N_cr = " << ratio;
  }
  // The stress-free series, for scale: the tension lowers the deflection as the closed form says.
  s.residual_stress = Mat3::Zero();
  EXPECT_NEAR(navier_centre(s, a, q, 0.0) * s.bending_stiffness() / (q * std::pow(a, 4)),
              0.00406235 + 0.0737 * s.bending_stiffness() / (s.shear_stiffness() * a * a), 2e-6);
}

TEST(ResidualStress, SimplySupportedStripInTensionFrequencies) {
  const double L = 1.0, h = 0.01;
  const PlateSection section{E, 0.0, rho, h};
  const double D = section.bending_stiffness(), S = section.shear_stiffness();
  for (double tension : {1.2, 12.0}) {
    const double N = tension * pi * pi * D / (L * L), sigma = N / h;
    double exact[3], error[3][3];
    for (int n = 1; n <= 3; ++n) {
      const double k = n * pi / L;
      exact[n - 1] = std::sqrt((D * std::pow(k, 4) / (1 + D * k * k / S) + N * k * k) / (rho * h));
    }
    const int meshes[3] = {20, 40, 80};
    for (int m = 0; m < 3; ++m) {
      const StructuralModes r =
          modes_of(plate_strip(L, h, meshes[m], "simply_supported", sigma), 3);
      for (int n = 0; n < 3; ++n) {
        error[n][m] = std::abs(r.stats.modes[n].angular_frequency / exact[n] - 1);
        std::printf(
            "SS strip N L^2/(pi^2 D) = %4.1f, %2d x 2, mode %d: omega %.8e, exact %.8e, "
            "error %.3e\n",
            tension, meshes[m], n + 1, r.stats.modes[n].angular_frequency, exact[n], error[n][m]);
      }
    }
    for (int n = 0; n < 3; ++n) {
      std::printf("SS strip tension %4.1f, mode %d: observed order %.2f\n", tension, n + 1,
                  order(error[n]));
      EXPECT_GE(order(error[n]), 1.8) << "tension " << tension << ", mode " << n + 1;
      EXPECT_LT(error[n][2], 1e-3) << "tension " << tension << ", mode " << n + 1;
    }
  }
}

TEST(ResidualStress, ClampedClampedBeamInTensionMatchesCharacteristicEquation) {
  const double L = 1.0, h = 0.001;
  const PlateSection section{E, 0.0, rho, h};
  const double D = section.bending_stiffness(), m = rho * h;
  EXPECT_NEAR(clamped_clamped_tension(D, 0.0, m, L) / (std::sqrt(D / m) / (L * L)),
              std::pow(4.730040744862704, 2), 1e-7);
  for (double tension : {30.0, 300.0}) {
    const double N = tension * D / (L * L);
    const double exact = clamped_clamped_tension(D, N, m, L);
    double error[3];
    const int meshes[3] = {40, 80, 160};
    for (int k = 0; k < 3; ++k) {
      const StructuralModes r = modes_of(plate_strip(L, h, meshes[k], "clamped", N / h), 1);
      error[k] = std::abs(r.stats.modes[0].angular_frequency / exact - 1);
      std::printf(
          "CC beam N L^2/D = %5.0f, %2d x 2: omega_1 %.8e, exact %.8e (stress-free x "
          "%.4f), error %.3e\n",
          tension, meshes[k], r.stats.modes[0].angular_frequency, exact,
          exact / clamped_clamped_tension(D, 0.0, m, L), error[k]);
    }
    std::printf("CC beam N L^2/D = %5.0f: observed order %.2f\n", tension, order(error));
    EXPECT_GE(order(error), 1.8) << "tension " << tension;
    EXPECT_LT(error[2], 1e-3) << "tension " << tension;
  }
}

TEST(ResidualStress, ContinuumBeamInTensionStiffensAsEulerBernoulli) {
  const double L = 400e-6, h = 8e-6, sigma = 100e6;
  const double D = E * h * h * h / 12, m = rho * h;  // per unit depth
  const double rise =
      clamped_clamped_tension(D, sigma * h, m, L) / clamped_clamped_tension(D, 0.0, m, L);
  auto beam = [&](double s) {
    return fmt::format(
        "mesh: {{type: rectangle, lower: [0 um, -4 um], size: [400 um, 8 um], cells: [160, 16]}}\n"
        "material: {{E: 200 GPa, nu: 0.31, density: 7854 kg/m^3, residual_stress: {} Pa}}\n"
        "model: {{hypothesis: plane_stress}}\n"
        "boundaries: {{left: {{type: fixed}}, right: {{type: fixed}}, top: {{type: free}}, "
        "bottom: {{type: free}}}}\n",
        s);
  };
  const double stressed = modes_of(beam(sigma), 1).stats.modes[0].angular_frequency;
  const double free_beam = modes_of(beam(0.0), 1).stats.modes[0].angular_frequency;
  std::printf(
      "CC continuum 160 x 16: omega_1 %.8e (sigma_xx 100 MPa), %.8e (none): rise %.6f, "
      "Euler-Bernoulli %.6f (%+.3e)\n",
      stressed, free_beam, stressed / free_beam, rise, stressed / free_beam / rise - 1);
  EXPECT_GT(rise, 1.15);
  EXPECT_NEAR(stressed / free_beam / rise, 1.0, 2e-3);
}

// lambda* of the string (5.): the largest sqrt(lambda)(u_m), by golden section.
double string_fold_lambda() {
  auto root_lambda = [](double u) {
    const double a = 1 - u;
    return std::sqrt(2 * a) * (std::sqrt(u) + a * std::log((1 + std::sqrt(u)) / std::sqrt(a)));
  };
  double lo = 0.1, hi = 0.7;
  const double r = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 100; ++i) {
    const double c = hi - r * (hi - lo), d = lo + r * (hi - lo);
    if (root_lambda(c) > root_lambda(d))
      hi = d;
    else
      lo = c;
  }
  return std::pow(root_lambda(0.5 * (lo + hi)), 2);
}

TEST(ResidualStress, TensionDominatedMembranePullsInAsAClampedString) {
  const double lambda = string_fold_lambda();
  EXPECT_NEAR(lambda, 1.40002, 1e-5);
  const double L = 400e-6, g = 3.75e-6, sigma = 100e6, eps0 = 8.8541878128e-12;
  const std::string path = std::string(RFMEMS_SOURCE_DIR) + "/cases/switch_plate/case.yaml";
  double deviation[2];
  const double thickness[2] = {1e-6, 0.5e-6};
  for (int k = 0; k < 2; ++k) {
    const double h = thickness[k], N = sigma * h, D = E * h * h * h / 12;
    const CaseFile cf = CaseFile::load(
        path, {"gas.model=none", "material.nu=0", fmt::format("model.thickness={} m", h),
               "material.residual_stress=[100 MPa, 0 MPa, 0 MPa]", "mesh.cells=[320,4]"});
    SwitchScene scene =
        build_switch_scene(cf.root(), std::filesystem::path(path).parent_path().string());
    QuasiStaticOptions o;
    o.n_points = 40;
    o.max_fraction = 0.9;
    o.voltage_tolerance = 1e-5;
    const double V = trace_pull_in(*scene.actuation, scene.control, o).pull_in_voltage;
    const double string = std::sqrt(2 * N * g * g * g * lambda / (eps0 * L * L));
    const double layer = std::sqrt(D / N) / L;
    deviation[k] = V / (string / (1 - 2 * layer)) - 1;
    std::printf(
        "h = %.2f um: V_PI = %.6f V, string %.6f V, with the clamps' layers (eps = "
        "%.4f) %.6f V: %+.3e\n",
        h * 1e6, V, string, layer, string / (1 - 2 * layer), deviation[k]);
  }
  EXPECT_LT(std::abs(deviation[0]), 6e-3);
  EXPECT_LT(std::abs(deviation[1]), 1.5e-3);
  // O(eps^2): halving eps divides the rest by about 4.
  EXPECT_GT(std::abs(deviation[0] / deviation[1]), 3.0);
}

TEST(ResidualStress, PrestressedSwitchRaisesPullInAndFrequencyAlike) {
  double voltage[2], frequency[2];
  const char* names[2] = {"switch_plate", "switch_prestressed"};
  for (int k = 0; k < 2; ++k) {
    const std::string path = std::string(RFMEMS_SOURCE_DIR) + "/cases/" + names[k] + "/case.yaml";
    const CaseFile cf =
        CaseFile::load(path, {"gas.model=none", "model.geometric_nonlinearity=false"});
    SwitchScene scene =
        build_switch_scene(cf.root(), std::filesystem::path(path).parent_path().string());
    frequency[k] = structural_modes(*scene.structure, 1, 0.0).stats.modes[0].frequency;
    QuasiStaticOptions o;
    o.voltage_tolerance = 1e-4;
    voltage[k] = trace_pull_in(*scene.actuation, scene.control, o).pull_in_voltage;
    std::printf("%s: V_PI %.5f V, f1 %.2f Hz\n", names[k], voltage[k], frequency[k]);
  }
  const double rise = voltage[1] / voltage[0];
  EXPECT_GT(rise, 1.2);
  EXPECT_NEAR(frequency[1] / frequency[0], rise, 3e-3 * rise);
}

TEST(ResidualStress, StressAcrossAFreeEdgeOrAWrongCountIsAnInputError) {
  const std::string plate =
      "mesh: {type: rectangle, lower: [0 um, 0 um], size: [400 um, 100 um], cells: [8, 2]}\n"
      "model: {structure: plate, thickness: 2 um}\n"
      "boundaries: {left: {type: clamped}, right: {type: clamped}, bottom: {type: free}, top: "
      "{type: free}}\n";
  auto build = [&](const std::string& stress) {
    const CaseFile cf = CaseFile::parse(
        plate + "material: {E: 80 GPa, nu: 0.4, residual_stress: " + stress + "}\n", "c.yaml");
    return build_structure(cf.root(), "", AnalysisType::Static);
  };
  auto message = [&](const std::string& stress) {
    try {
      build(stress);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // Biaxial: sigma_yy crosses the free sides.
  const std::string biaxial = message("30 MPa");
  EXPECT_NE(biaxial.find("c.yaml: key 'material.residual_stress' = '30 MPa'"), std::string::npos)
      << biaxial;
  EXPECT_NE(biaxial.find("'bottom'"), std::string::npos) << biaxial;
  EXPECT_NE(message("[0 MPa, 0 MPa, 5 MPa]").find("'bottom'"), std::string::npos);
  EXPECT_NE(message("[1 MPa, 2 MPa]").find("expected one stress or 3"), std::string::npos);
  // Along the span only: in equilibrium with the free sides.
  EXPECT_NO_THROW(build("[18 MPa, 0 MPa, 0 MPa]"));
}

// Natural frequencies of beams from the modal analysis (physics/structure/modal_analysis.hpp),
// against closed forms, with the observed order over three meshes (each refinement halves the
// cell size along the span).
//
// 1. Simply supported plate strip (Mindlin-Reissner plate, nu = 0 so that the strip bends
//    cylindrically and is exactly a Timoshenko beam; free long edges; rotations quasi-static as
//    in the transients): w = sin(k x), k = n pi / L, gives
//      omega_n^2 = D k^4 / (rho h) / (1 + D k^2 / (kappa G h)),   D = E h^3 / 12,
//    the thin-plate D k^4 / (rho h) with the shear correction (1e-3 at n = 3, L/h = 100). Modes
//    n = 1, 2, 3, strip L = 1 m, h = 10 mm, width L/10 (torsion stays above the third bending
//    mode), 20/40/80 x 2 cells. Measured: relative frequency errors 9.2e-4, 2.4e-4, 6.3e-5 (mode
//    1), 3.6e-3 ... 2.5e-4 (2), 7.7e-3 ... 5.6e-4 (3), observed orders 1.83-1.96; against the
//    thin-plate formula the finest mesh is -1.6e-4, -6.4e-4, -1.4e-3 (the shear correction).
//    The shapes match sin(k x) at the cells to 1.7e-4 ... 2.6e-6 (mode 1; order ~3).
//    Asserted: orders >= 1.8, finest error < 1e-3, shape error < 0.01 (20 / nx)^2.
// 2. Clamped-clamped beam, plate model (L/h = 1000, so the shear correction, ~(h/L)^2, is below
//    1e-5): omega_1 = (b L)^2 / L^2 sqrt(D / (rho h)), b L the first root of
//    cos(b L) cosh(b L) = 1, found here by Newton's method (4.7300407...). 20/40/80 x 2 cells:
//    errors 1.03e-2, 2.68e-3, 6.8e-4, orders 1.95, 1.97 (asserted >= 1.8, finest < 1e-3).
// 3. Clamped-clamped beam, plane-stress continuum (cases/fixed_fixed_beam's beam: L = 400 um,
//    h = 8 um, L/h = 50), against the same Euler-Bernoulli value with E I = E h^3 / 12 per unit
//    depth; here the continuum's shear and the clamped faces lower the frequency by a few 1e-3,
//    so the closed form is a check of the converged value, not of the order. 40 x 4, 80 x 8,
//    160 x 16 cells: +1.85e-2, +2.19e-3, -1.03e-3 against Euler-Bernoulli; order 2.34 from the
//    successive differences, Richardson limit -1.8e-3 below Euler-Bernoulli (asserted: order
//    >= 1.8, finest within 0.5 %, limit in (0.995, 1) of Euler-Bernoulli).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "../support/convergence_order.hpp"
#include "io/case_file.hpp"
#include "materials/plate_section.hpp"
#include "physics/structure/modal_analysis.hpp"
#include "physics/structure/structure_from_case.hpp"

using namespace rfmems;

namespace {

constexpr double E = 200e9, rho = 7854;

// The modes, and (if centroids is given) the cell centroids of the model's mesh.
StructuralModes modes_of(const std::string& text, Index n_modes,
                         std::vector<Vec3>* centroids = nullptr) {
  const CaseFile cf = CaseFile::parse(text, "modal.yaml");
  std::unique_ptr<StructuralModel> model = build_structure(cf.root(), "", AnalysisType::Modal);
  if (centroids) {
    const Mesh& mesh = model->structure_mesh();
    for (Index c = 0; c < mesh.n_cells(); ++c) centroids->push_back(mesh.cell_centroid(c));
  }
  return structural_modes(*model, n_modes, 0.0);
}

std::string plate_strip(double L, double h, int nx, const std::string& ends) {
  return "mesh: {type: rectangle, lower: [0 m, 0 m], size: [" + std::to_string(L) + " m, " +
         std::to_string(L / 10) + " m], cells: [" + std::to_string(nx) +
         ", 2]}\n"
         "material: {E: 200 GPa, nu: 0, density: 7854 kg/m^3}\n"
         "model: {structure: plate, thickness: " +
         std::to_string(h) +
         " m}\n"
         "boundaries:\n"
         "  left: {type: " +
         ends + "}\n  right: {type: " + ends +
         "}\n"
         "  bottom: {type: free}\n  top: {type: free}\n";
}

// The observed order between two meshes, the second twice as fine.
double order(double e_coarse, double e_fine) {
  return test_support::fitted_order({2.0, 1.0}, {e_coarse, e_fine});
}

// (20 / nx)^2: the second-order error scale of an nx-cell span, 1 on the coarsest mesh.
double error_scale(int nx) { return std::pow(20.0 / nx, 2); }

// The first root of cos x cosh x = 1 above zero, by Newton from 4.7.
double clamped_clamped_root() {
  double x = 4.7;
  for (int i = 0; i < 50; ++i) {
    const double f = std::cos(x) * std::cosh(x) - 1;
    const double df = -std::sin(x) * std::cosh(x) + std::cos(x) * std::sinh(x);
    x -= f / df;
  }
  return x;
}

}  // namespace

TEST(ModalBeams, SimplySupportedPlateStripConvergesToMindlinStrip) {
  const double L = 1.0, h = 0.01;
  const PlateSection section{E, 0.0, rho, h};
  const double D = section.bending_stiffness(), S = section.shear_stiffness();
  double exact[3], thin[3];
  for (int n = 1; n <= 3; ++n) {
    const double k = n * std::numbers::pi / L;
    thin[n - 1] = std::sqrt(D * std::pow(k, 4) / (rho * h));
    exact[n - 1] = thin[n - 1] / std::sqrt(1 + D * k * k / S);
  }
  double error[3][3];
  const int meshes[3] = {20, 40, 80};
  for (int m = 0; m < 3; ++m) {
    std::vector<Vec3> x;
    const StructuralModes r = modes_of(plate_strip(L, h, meshes[m], "simply_supported"), 3, &x);
    for (int n = 0; n < 3; ++n) {
      // The shape: w = sin(k x) scaled so that its largest cell value is +1 (the plate's
      // unknowns are w, beta_x, beta_y per cell); the sign from the cell of that value.
      const double k = (n + 1) * std::numbers::pi / L;
      std::size_t top = 0;
      for (std::size_t c = 0; c < x.size(); ++c)
        if (std::abs(std::sin(k * x[c].x())) > std::abs(std::sin(k * x[top].x()))) top = c;
      const double scale = std::sin(k * x[top].x()) * (r.shapes[n][3 * top] > 0 ? 1 : -1);
      double shape_error = 0, largest_w = 0;
      for (std::size_t c = 0; c < x.size(); ++c) {
        const double w = r.shapes[n][3 * c];
        shape_error = std::max(shape_error, std::abs(w - std::sin(k * x[c].x()) / scale));
        largest_w = std::max(largest_w, w);
      }
      std::printf("SS strip %3d x 2, mode %d: shape error %.3e\n", meshes[m], n + 1, shape_error);
      EXPECT_DOUBLE_EQ(largest_w, 1.0);
      EXPECT_LT(shape_error, 0.01 * error_scale(meshes[m])) << "mode " << n + 1;
      const StructuralMode& mode = r.stats.modes[n];
      EXPECT_FALSE(mode.complex);
      EXPECT_EQ(mode.damping_ratio, 0.0);
      error[m][n] = std::abs(mode.angular_frequency / exact[n] - 1);
      std::printf(
          "SS strip %3d x 2, mode %d: omega = %.8e rad/s, Mindlin strip %.8e (error "
          "%.3e), thin plate %.8e (%+.3e)\n",
          meshes[m], n + 1, mode.angular_frequency, exact[n], error[m][n], thin[n],
          mode.angular_frequency / thin[n] - 1);
    }
  }
  for (int n = 0; n < 3; ++n) {
    const double p1 = order(error[0][n], error[1][n]), p2 = order(error[1][n], error[2][n]);
    std::printf("SS strip mode %d: observed orders %.2f, %.2f\n", n + 1, p1, p2);
    EXPECT_GE(p1, 1.8) << "mode " << n + 1;
    EXPECT_GE(p2, 1.8) << "mode " << n + 1;
    EXPECT_LT(error[2][n], 1e-3) << "mode " << n + 1;  // measured 6.3e-5, 2.5e-4, 5.6e-4
  }
}

TEST(ModalBeams, ClampedClampedPlateConvergesToCharacteristicRoot) {
  const double L = 1.0, h = 0.001;
  const PlateSection section{E, 0.0, rho, h};
  const double bL = clamped_clamped_root();
  EXPECT_NEAR(bL, 4.730040744862704, 1e-12);
  const double exact = bL * bL / (L * L) * std::sqrt(section.bending_stiffness() / (rho * h));
  double error[3];
  const int meshes[3] = {20, 40, 80};
  for (int m = 0; m < 3; ++m) {
    const StructuralModes r = modes_of(plate_strip(L, h, meshes[m], "clamped"), 1);
    error[m] = std::abs(r.stats.modes[0].angular_frequency / exact - 1);
    std::printf("CC plate %3d x 2: omega_1 = %.8e rad/s, exact %.8e, error %.3e\n", meshes[m],
                r.stats.modes[0].angular_frequency, exact, error[m]);
  }
  std::printf("CC plate: observed orders %.2f, %.2f\n", order(error[0], error[1]),
              order(error[1], error[2]));
  EXPECT_GE(order(error[0], error[1]), 1.8);
  EXPECT_GE(order(error[1], error[2]), 1.8);
  EXPECT_LT(error[2], 1e-3);  // measured 6.8e-4 on 80 x 2
}

TEST(ModalBeams, ClampedClampedContinuumBeam) {
  const double L = 400e-6, h = 8e-6;
  const double exact = std::pow(clamped_clamped_root() / L, 2) * h * std::sqrt(E / (12 * rho));
  const int meshes[3] = {40, 80, 160};
  double error[3], omega[3];
  for (int m = 0; m < 3; ++m) {
    const std::string text =
        "mesh: {type: rectangle, lower: [0 um, -4 um], size: [400 um, 8 um], cells: [" +
        std::to_string(meshes[m]) + ", " + std::to_string(meshes[m] / 10) +
        "]}\n"
        "material: {E: 200 GPa, nu: 0.31, density: 7854 kg/m^3}\n"
        "model: {hypothesis: plane_stress}\n"
        "boundaries: {left: {type: fixed}, right: {type: fixed}, top: {type: free}, bottom: "
        "{type: free}}\n";
    const StructuralModes r = modes_of(text, 1);
    omega[m] = r.stats.modes[0].angular_frequency;
    error[m] = omega[m] / exact - 1;
    std::printf(
        "CC continuum %3d x %d: omega_1 = %.8e rad/s, Euler-Bernoulli %.8e (%+.3e), "
        "damping ratio %.3e\n",
        meshes[m], meshes[m] / 10, r.stats.modes[0].angular_frequency, exact, error[m],
        r.stats.modes[0].damping_ratio);
  }
  // The order from the successive differences (the limit is not the Euler-Bernoulli value),
  // and the Richardson limit, which shear and the clamped faces put just below it.
  const double p = order(std::abs(omega[0] - omega[1]), std::abs(omega[1] - omega[2]));
  const double limit = omega[2] + (omega[2] - omega[1]) / (std::pow(2.0, p) - 1);
  std::printf(
      "CC continuum: observed order %.2f, Richardson limit %.8e (%+.3e vs "
      "Euler-Bernoulli)\n",
      p, limit, limit / exact - 1);
  EXPECT_GE(p, 1.8);
  EXPECT_LT(std::abs(error[2]), 5e-3);
  EXPECT_LT(limit, exact);
  EXPECT_GT(limit, 0.995 * exact);
}

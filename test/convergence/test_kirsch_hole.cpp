// Plate with a circular hole under uniaxial tension (Kirsch problem; thesis Fig. 2.9 and
// Tables 2.2-2.3), plane strain, E = 1e7 Pa, nu = 0.3, remote tension T = 1e4 Pa along x,
// hole radius a = 0.5 m.
//
// Model: the quarter plate [0, 2] x [0, 2] minus the hole, meshed with unstructured triangles
// from cases/kirsch_hole/plate_with_hole.geo at run time. Symmetry on x = 0 and y = 0, the
// hole free, and on the outer edges (x = 2, y = 2) the exact traction sigma n of the
// infinite-plate solution, so that the finite plate reproduces the Kirsch field exactly and
// the discretisation error is all that remains (the standard benchmark set-up).
//
// Reference: Kirsch (1898); closed forms (stress, and the displacement in Kolosov's kappa
// form) in test/support/analytic_elasticity.hpp, as in e.g. Barber, Elasticity, the circular
// hole in a uniaxial stress field.
//
// Asserted:
//  - the reference itself: Hooke's law (plane strain) applied to finite differences of the
//    reference displacement gives the reference stress; the displacement satisfies the symmetry
//    conditions; the stress is traction-free on the hole and tends to (T, 0, 0) far away;
//  - the FV solution: one Newton step (linear problem), and volume-weighted RMS errors of
//    sigma_xx and of |u| at cell centroids that fall at an observed order >= 1.8 (least-squares
//    fit over the meshes; the thesis reports 2.0), plus loose absolute bounds on the finest
//    mesh so that a solution converging to the wrong answer cannot pass.
// Printed: cells, mean cell size, both errors, pairwise orders, timing, and the stress error of
// the exact centroid displacements put through the same reconstruction (what the gradient
// reconstruction alone costs).
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "../support/analytic_elasticity.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/gmsh_runner.hpp"
#include "physics/elasticity/elasticity_operator.hpp"
#include "solvers/static_solve.hpp"

using namespace rfmems;
using test_support::KirschHole;

namespace {

namespace fs = std::filesystem;

constexpr double kE = 1e7, kNu = 0.3, kT = 1e4, kA = 0.5;
const KirschHole kirsch{kA, kT, kE, kNu};
const std::string kHoleGeo =
    std::string(RFMEMS_SOURCE_DIR) + "/cases/kirsch_hole/plate_with_hole.geo";

// Plane-strain Hooke's law written out here (not taken from lib/) so that the reference check
// does not depend on the code under test. Returns sigma_xx, sigma_yy, sigma_xy.
Vec3 plane_strain_stress(double exx, double eyy, double gxy) {
  const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  return Vec3(lambda * (exx + eyy) + 2 * mu * exx, lambda * (exx + eyy) + 2 * mu * eyy, mu * gxy);
}

struct Result {
  Index cells;
  double h;              // sqrt(mean cell area)
  double rms_sxx;        // [Pa]
  double rms_u;          // [m]
  double rms_sxx_exact;  // [Pa] cell stress reconstructed from the exact centroid displacements
  long newton;
  double seconds;
};

// A linear problem: Newton must converge in one step; a few more are allowed only so that a
// wrong Jacobian fails quickly instead of grinding through KINSOL's default 50 iterations.
KinsolOptions linear_solve_options() {
  KinsolOptions options;
  options.max_iterations = 3;
  return options;
}

Result solve(double h, const fs::path& dir) {
  const auto start = std::chrono::steady_clock::now();
  char name[64];
  std::snprintf(name, sizeof name, "plate_h%.4f.msh", h);
  Mesh mesh = read_gmsh_mesh(generate_gmsh_mesh(kHoleGeo, {{"h", h}}, (dir / name).string(), 2));

  // Boundary conditions by patch name; an unexpected patch is an error in the .geo, not free.
  std::vector<ElasticityBoundary> bcs(mesh.patches().size());
  for (std::size_t p = 0; p < bcs.size(); ++p) {
    const std::string& patch = mesh.patches()[p].name;
    if (patch == "symmetry_x" || patch == "symmetry_y")
      bcs[p] = {ElasticityBoundary::Kind::Symmetry, {}};
    else if (patch == "right")
      bcs[p] = {ElasticityBoundary::Kind::Traction,
                [](const Vec3& x, double) { return kirsch.traction(x, Vec3(1, 0, 0)); }};
    else if (patch == "top")
      bcs[p] = {ElasticityBoundary::Kind::Traction,
                [](const Vec3& x, double) { return kirsch.traction(x, Vec3(0, 1, 0)); }};
    else if (patch == "hole")
      bcs[p] = {ElasticityBoundary::Kind::Traction, {}};
    else
      ADD_FAILURE() << "unexpected patch '" << patch << "' in " << kHoleGeo;
  }
  const LinearElastic material{kE, kNu, 1000, Hypothesis::PlaneStrain};
  // Quadratic reconstruction: on these unstructured meshes with a curved free boundary the
  // cubic one keeps sigma_xx at order 2.2 but lets the displacement order sag to 1.73 (one-sided
  // cubic fits on the hole and symmetry cells; measured), while the quadratic gives 2.2 / 2.3.
  ElasticityOperator op(mesh, material, bcs, {}, 2);
  StaticSolution s = solve_static(op, 0.0, linear_solve_options());

  // The exact field sampled at the centroids, put through the same gradient reconstruction:
  // separates the reconstruction's own error from the discretisation error of the solution
  // (printed only, as a diagnostic).
  std::vector<double> u_exact(op.size());
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    const Vec3 u = kirsch.displacement(mesh.cell_centroid(c));
    u_exact[2 * c] = u.x();
    u_exact[2 * c + 1] = u.y();
  }
  const std::vector<Mat3> grad = op.cell_gradients(0.0, s.y),
                          grad_exact = op.cell_gradients(0.0, u_exact);
  double sum_s = 0, sum_u = 0, sum_e = 0, area = 0;
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    const Vec3& xc = mesh.cell_centroid(c);
    const double v = mesh.cell_volume(c), sxx = kirsch.stress(xc)[0];
    const double ds = material.stress(grad[c])(0, 0) - sxx,
                 de = material.stress(grad_exact[c])(0, 0) - sxx;
    const Vec3 du = Vec3(s.y[2 * c], s.y[2 * c + 1], 0) - kirsch.displacement(xc);
    sum_s += ds * ds * v;
    sum_e += de * de * v;
    sum_u += du.squaredNorm() * v;
    area += v;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {mesh.n_cells(),
          std::sqrt(area / mesh.n_cells()),
          std::sqrt(sum_s / area),
          std::sqrt(sum_u / area),
          std::sqrt(sum_e / area),
          s.stats.newton_iters,
          seconds};
}

// Slope of the least-squares line through (log h_i, log e_i).
double fitted_order(const std::vector<Result>& r, double Result::*error) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(r.size());
  for (const Result& x : r) {
    const double lx = std::log(x.h), ly = std::log(x.*error);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

TEST(KirschReference, HookesLawOfDisplacementGivesStress) {
  // Central differences with step 1e-5 m: truncation ~1e-10 relative, round-off ~1e-11 Pa.
  const double d = 1e-5, tol = 1e-6 * kT;
  for (Vec3 x : {Vec3(0.6, 0.1, 0), Vec3(0.9, 1.3, 0), Vec3(0.2, 1.7, 0)}) {
    const Vec3 dx(d, 0, 0), dy(0, d, 0);
    const Vec3 ux = (kirsch.displacement(x + dx) - kirsch.displacement(x - dx)) / (2 * d);
    const Vec3 uy = (kirsch.displacement(x + dy) - kirsch.displacement(x - dy)) / (2 * d);
    const Vec3 hooke = plane_strain_stress(ux.x(), uy.y(), ux.y() + uy.x());
    const Vec3 exact = kirsch.stress(x);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(hooke[i], exact[i], tol)
          << "component " << i << " at (" << x.x() << ", " << x.y() << ")";
  }
}

TEST(KirschReference, SatisfiesSymmetryAndHoleConditions) {
  // Magnitude of the displacement near the hole, for the tolerances: u ~ T a / mu.
  const double u_scale = kT * kA / kirsch.mu();
  for (double s : {0.5, 0.8, 1.4, 2.0}) {
    EXPECT_NEAR(kirsch.displacement(Vec3(0, s, 0)).x(), 0.0, 1e-12 * u_scale)
        << "u_x on x = 0, y = " << s;
    EXPECT_NEAR(kirsch.displacement(Vec3(s, 0, 0)).y(), 0.0, 1e-12 * u_scale)
        << "u_y on y = 0, x = " << s;
    // The symmetry faces carry no shear: sigma_xy = 0 on both axes.
    EXPECT_NEAR(kirsch.stress(Vec3(0, s, 0))[2], 0.0, 1e-12 * kT);
    EXPECT_NEAR(kirsch.stress(Vec3(s, 0, 0))[2], 0.0, 1e-12 * kT);
  }
  // The hole is traction-free, with the classic concentration factor 3 at its top.
  for (double th : {0.0, 0.4, 0.9, 1.3, std::numbers::pi / 2}) {
    const Vec3 n(std::cos(th), std::sin(th), 0);
    EXPECT_NEAR(kirsch.traction(kA * n, -n).norm(), 0.0, 1e-12 * kT) << "theta = " << th;
  }
  EXPECT_NEAR(kirsch.stress(Vec3(0, kA, 0))[0], 3 * kT, 1e-12 * kT);
  // Far away the field is the uniform tension.
  const Vec3 far = kirsch.stress(Vec3(300, 400, 0));
  EXPECT_NEAR(far[0], kT, 1e-4 * kT);
  EXPECT_NEAR(far[1], 0.0, 1e-4 * kT);
  EXPECT_NEAR(far[2], 0.0, 1e-4 * kT);
}

TEST(KirschHole, StressAndDisplacementConvergeAtSecondOrder) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() /
                       ("rfmems_kirsch_" + std::to_string(getpid()) + "_" + info->name());
  fs::create_directories(dir);

  // Rows are printed as each mesh finishes (the finest takes most of the time).
  std::printf("%8s %9s %13s %13s %7s %7s %15s %8s\n", "cells", "h_mean", "rms sxx [Pa]",
              "rms |u| [m]", "p(sxx)", "p(u)", "sxx(exact u)", "time [s]");
  std::vector<Result> r;
  for (double h : {0.2, 0.1, 0.05, 0.025}) {
    r.push_back(solve(h, dir));
    const Result& x = r.back();
    EXPECT_EQ(x.newton, 1) << "a linear static problem needs one Newton step (h = " << h << ")";
    // Pairwise orders against the actual mesh-size ratio (Gmsh does not halve exactly).
    double p_si = NAN, p_ui = NAN;
    if (r.size() > 1) {
      const Result& prev = r[r.size() - 2];
      p_si = test_support::observed_order(prev.rms_sxx, x.rms_sxx, prev.h / x.h);
      p_ui = test_support::observed_order(prev.rms_u, x.rms_u, prev.h / x.h);
    }
    std::printf("%8ld %9.5f %13.5e %13.5e %7.3f %7.3f %15.5e %8.2f\n", static_cast<long>(x.cells),
                x.h, x.rms_sxx, x.rms_u, p_si, p_ui, x.rms_sxx_exact, x.seconds);
    std::fflush(stdout);
  }
  fs::remove_all(dir);

  const double p_s = fitted_order(r, &Result::rms_sxx), p_u = fitted_order(r, &Result::rms_u);
  std::printf("least-squares order: sigma_xx %.3f, |u| %.3f\n", p_s, p_u);
  EXPECT_GE(p_s, 1.8);
  EXPECT_GE(p_u, 1.8);

  // Errors relative to the load scales on the finest mesh (about 40x and 7x below these bounds
  // with the cubic reconstruction): a solution that converges to something else (a wrong
  // traction or symmetry condition gives O(1) errors) cannot pass on its order alone.
  const double u_scale = kT * kA / kirsch.mu();
  EXPECT_LT(r.back().rms_sxx, 1e-3 * kT);
  EXPECT_LT(r.back().rms_u, 1e-4 * u_scale);
}

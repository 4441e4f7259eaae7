// Study: stability of the semi-discrete plate dynamics. The FV stiffness K is not symmetric
// near boundaries (one-sided reconstructions; the divergence-consistent moment source of the
// shear), so M^{-1} K may have complex eigenvalues lambda, i.e. modes growing like
// exp(Re sqrt(-lambda) t). Computed densely (M^{-1/2} K M^{-1/2}, balanced) for small meshes:
//  - full mass (FirstOrderSystem): rotary inertia puts ~2N thickness-shear modes near
//    sqrt(12 k G / rho)/h; the asymmetry splits them into complex pairs (growth ~1e7 /s for
//    the 2 um strip with cubic reconstruction, none with linear);
//  - quasi-static rotations (ReducedInertiaSystem): the Schur complement on w.
// Prints the largest growth rate per case; asserts the cases the regression tests rely on:
// the clamped-free strip and the clamped square with quasi-static rotations have a real
// spectrum, and the linear reconstruction has a real spectrum with the full mass.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <cstdio>

#include "mesh/structured_mesh.hpp"
#include "physics/plate/plate_operator.hpp"

using namespace rfmems;
using Kind = PlateBoundary::Kind;

namespace {

struct Growth {
  double full_mass, quasi_static;  // max Re sqrt(-lambda) [1/s]
  double first_frequency;          // lowest quasi-static frequency [Hz]
};

double max_growth(const Eigen::VectorXcd& lambda) {
  double g = 0;
  for (Eigen::Index i = 0; i < lambda.size(); ++i)
    g = std::max(g, std::abs(std::sqrt(-lambda[i]).real()));
  return g;
}

// edges: 0 clamped x-ends and free sides, 1 all clamped, 2 all soft simple supports.
Growth spectrum(int degree, int nx, int ny, double nu, int edges) {
  const double L = 400e-6, h = 2e-6;
  BoxSpec spec;
  spec.upper = Vec3(L, L * ny / nx, 0);
  spec.n[0] = nx;
  spec.n[1] = ny;
  Mesh mesh = make_structured_mesh(spec);
  std::vector<PlateBoundary> bcs(mesh.patches().size());
  for (std::size_t p = 0; p < bcs.size(); ++p) {
    const std::string& name = mesh.patches()[p].name;
    const bool end = name == "left" || name == "right";
    bcs[p].kind =
        edges == 2 ? Kind::SimplySupportedSoft : (end || edges == 1 ? Kind::Clamped : Kind::Free);
  }
  PlateOperator op(mesh, {200e9, nu, 7854, h}, bcs, {}, degree);
  const Index n = op.size();
  std::vector<double> values(op.stiffness_pattern().nnz()), y(n, 0.0);
  op.stiffness(0.0, y, values);
  const CsrPattern& pattern = op.stiffness_pattern();
  const auto m = op.mass_diagonal();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (Index i = 0; i < n; ++i)
    for (Index k = pattern.row_ptr[i]; k < pattern.row_ptr[i + 1]; ++k)
      K(i, pattern.col_idx[k]) = values[k];
  Eigen::MatrixXd A(n, n);
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j) A(i, j) = K(i, j) / std::sqrt(m[i] * m[j]);
  Growth g;
  g.full_mass = max_growth(Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues());
  // Quasi-static rotations: S = K_ww - K_wb K_bb^{-1} K_bw, frequencies of M_w^{-1} S.
  std::vector<Index> w, b;
  for (Index i = 0; i < n; ++i) (i % 3 == 0 ? w : b).push_back(i);
  auto block = [&](const std::vector<Index>& r, const std::vector<Index>& c) {
    Eigen::MatrixXd B(r.size(), c.size());
    for (std::size_t i = 0; i < r.size(); ++i)
      for (std::size_t j = 0; j < c.size(); ++j) B(i, j) = K(r[i], c[j]);
    return B;
  };
  Eigen::MatrixXd S = block(w, w) - block(w, b) * block(b, b).partialPivLu().solve(block(b, w));
  for (std::size_t i = 0; i < w.size(); ++i) S.row(i) /= m[w[i]];
  const Eigen::VectorXcd lambda = Eigen::EigenSolver<Eigen::MatrixXd>(S, false).eigenvalues();
  g.quasi_static = max_growth(lambda);
  double lowest = 1e300;
  for (Eigen::Index i = 0; i < lambda.size(); ++i) lowest = std::min(lowest, std::abs(lambda[i]));
  g.first_frequency = std::sqrt(lowest) / (2 * M_PI);
  std::printf(
      "degree %d  %2dx%-2d  nu %.1f  %-22s growth: full mass %.3e /s, quasi-static rotations %.3e "
      "/s; "
      "f1 = %.1f Hz\n",
      degree, nx, ny, nu,
      edges == 0   ? "clamped ends, free"
      : edges == 1 ? "clamped"
                   : "soft simple support",
      g.full_mass, g.quasi_static, g.first_frequency);
  return g;
}

}  // namespace

TEST(PlateSpectrum, GrowthRates) {
  for (int degree : {3, 1}) {
    const Growth strip = spectrum(degree, 40, 4, 0.0, 0);
    const Growth clamped = spectrum(degree, 12, 12, 0.3, 1);
    const Growth free_sides = spectrum(degree, 12, 12, 0.3, 0);
    const Growth soft = spectrum(degree, 12, 12, 0.3, 2);
    // Real spectra: growth below 1e-6 of the first angular frequency.
    EXPECT_LT(strip.quasi_static, 1e-6 * 2 * M_PI * strip.first_frequency);
    EXPECT_LT(clamped.quasi_static, 1e-6 * 2 * M_PI * clamped.first_frequency);
    if (degree == 1) {
      EXPECT_LT(strip.full_mass, 1e-6 * 2 * M_PI * strip.first_frequency);
      EXPECT_LT(free_sides.full_mass, 1e-6 * 2 * M_PI * free_sides.first_frequency);
      EXPECT_LT(soft.quasi_static, 1e-6 * 2 * M_PI * soft.first_frequency);
    }
  }
}

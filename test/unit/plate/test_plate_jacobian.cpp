// The analytic Jacobian of the FV Mindlin-Reissner plate operator against central finite
// differences of its residual, on irregular non-orthogonal meshes (smooth distortion plus
// random jitter, graded), with every boundary kind on some patch, cubic and linear
// reconstructions, in the static form (dR/dy) and the first-order transient form
// (dF/dY + c_j dF/dY'). Thick and thin sections, so both the bending and the shear parts are
// checked at their own scale.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "../../support/distorted_plate.hpp"
#include "../../support/jacobian_check.hpp"
#include "core/reduced_inertia_system.hpp"
#include "core/structural_systems.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/plate/plate_operator.hpp"

using namespace rfmems;
using Kind = PlateBoundary::Kind;
using rfmems::test::distorted_mesh;
using rfmems::test_support::random_state;

namespace {

// left, right, bottom, top get the four kinds named; values depend on x and t.
std::vector<PlateBoundary> boundaries(const Mesh& mesh, Kind left, Kind right, Kind bottom,
                                      Kind top) {
  auto value = [](const Vec3& x, double t) {
    return Vec3(1e-4 * (1 + x.y()) * (1 + t), 2e-4 * x.x() - 1e-4, 3e-4 * (1 - t) * x.y());
  };
  auto load = [](const Vec3& x, double t) {
    return Vec3(-50.0 * (1 + x.x() * t), 3.0 * x.y(), -2.0);
  };
  std::vector<PlateBoundary> bcs(mesh.patches().size());
  for (std::size_t p = 0; p < bcs.size(); ++p) {
    const std::string& name = mesh.patches()[p].name;
    Kind kind = name == "left" ? left : name == "right" ? right : name == "bottom" ? bottom : top;
    bcs[p].kind = kind;
    if (kind == Kind::Load)
      bcs[p].value = load;
    else if (kind != Kind::Clamped && kind != Kind::Free)
      bcs[p].value = value;
  }
  return bcs;
}

// Central-difference check per class of entry (row component, column component) of
// (w, beta_x, beta_y): the shear entries are (L/h)^2 larger than the bending ones, so a check
// against the largest entry alone would let a wrong bending block through. Returns the worst
// of max |J_fd - J| / max |J| over the nine classes (entries outside the pattern included).
double worst_class_difference(SystemOperator& op, double t, double c_j,
                              const std::vector<double>& y, const std::vector<double>& yp,
                              double step) {
  double diff[3][3] = {}, scale[3][3] = {};
  const std::vector<double> values = test_support::analytic_jacobian(op, t, c_j, y, yp);
  test_support::for_each_jacobian_entry(op, t, c_j, y, yp, std::vector<double>(y.size(), step),
                                        values, [&](Index i, Index j, double fd, double analytic) {
                                          double& d = diff[i % 3][j % 3];
                                          double& s = scale[i % 3][j % 3];
                                          d = std::max(d, std::abs(fd - analytic));
                                          s = std::max(s, std::abs(analytic));
                                        });
  double worst = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      EXPECT_GT(scale[a][b], 0.0) << "class " << a << b << " is empty";
      worst = std::max(worst, diff[a][b] / scale[a][b]);
    }
  return worst;
}

const ScalarField pressure = [](const Vec3& x, double t) { return -1e3 * (1 + x.x() * x.y() + t); };

}  // namespace

struct JacobianCase {
  Kind left, right, bottom, top;
  double thickness;
  int degree;
};

class PlateJacobian : public ::testing::TestWithParam<JacobianCase> {};

TEST_P(PlateJacobian, StaticMatchesFiniteDifferences) {
  const JacobianCase c = GetParam();
  Mesh mesh = distorted_mesh(6, 5, 3);
  PlateSection section{200e9, 0.3, 7854, c.thickness};
  PlateOperator op(mesh, section, boundaries(mesh, c.left, c.right, c.bottom, c.top), pressure,
                   c.degree);
  StaticSystem system(op);
  auto y = random_state(system.size(), 1, 1e-3);
  std::vector<double> yp(system.size(), 0.0);
  auto check = test_support::check_jacobian(system, 0.4, 0.0, y, yp, 1e-6);
  EXPECT_LT(check.relative(), 1e-6)
      << "max |J_fd - J| = " << check.max_abs_difference << " of max |J| = " << check.max_abs_entry;
  EXPECT_LT(worst_class_difference(system, 0.4, 0.0, y, yp, 1e-6), 1e-6);
}

std::string kind_name(Kind k) {
  switch (k) {
    case Kind::Clamped:
      return "Clamped";
    case Kind::Displacement:
      return "Displacement";
    case Kind::SimplySupportedHard:
      return "SSHard";
    case Kind::SimplySupportedSoft:
      return "SSSoft";
    case Kind::Free:
      return "Free";
    case Kind::Load:
      return "Load";
  }
  return "?";
}

INSTANTIATE_TEST_SUITE_P(
    EveryBoundaryKind, PlateJacobian,
    ::testing::Values(
        JacobianCase{Kind::Clamped, Kind::Load, Kind::SimplySupportedHard, Kind::Free, 0.1, 3},
        JacobianCase{Kind::Displacement, Kind::SimplySupportedSoft, Kind::Load,
                     Kind::SimplySupportedHard, 0.1, 3},
        JacobianCase{Kind::SimplySupportedSoft, Kind::Free, Kind::Clamped, Kind::Displacement, 0.01,
                     3},
        JacobianCase{Kind::Clamped, Kind::Load, Kind::SimplySupportedHard, Kind::Free, 0.1, 1},
        JacobianCase{Kind::SimplySupportedHard, Kind::Displacement, Kind::Free,
                     Kind::SimplySupportedSoft, 0.05, 2}),
    [](const ::testing::TestParamInfo<JacobianCase>& info) {
      const JacobianCase& c = info.param;
      return kind_name(c.left) + "_" + kind_name(c.right) + "_" + kind_name(c.bottom) + "_" +
             kind_name(c.top) + "_h" + std::to_string(static_cast<int>(1000 * c.thickness)) +
             "mm_degree" + std::to_string(c.degree);
    });

// The membrane force of a residual stress (a full in-plane tensor, large enough that the
// membrane entries dominate the w-w class) on every kind of edge, cubic and linear.
TEST(PlateJacobianPrestressed, StaticMatchesFiniteDifferences) {
  Mesh mesh = distorted_mesh(6, 5, 17);
  PlateSection section{200e9, 0.3, 7854, 0.1};
  section.residual_stress << 8e10, 3e10, 0, 3e10, 5e10, 0, 0, 0, 0;
  for (int degree : {3, 1}) {
    for (auto [left, right] : {std::pair{Kind::Clamped, Kind::Displacement},
                               std::pair{Kind::SimplySupportedHard, Kind::SimplySupportedSoft}}) {
      PlateOperator op(mesh, section, boundaries(mesh, left, right, Kind::Load, Kind::Free),
                       pressure, degree);
      StaticSystem system(op);
      auto y = random_state(system.size(), 5, 1e-3);
      std::vector<double> yp(system.size(), 0.0);
      EXPECT_LT(worst_class_difference(system, 0.4, 0.0, y, yp, 1e-6), 1e-6)
          << "degree " << degree << ", left " << kind_name(left);
    }
  }
}

TEST(PlateJacobianTransient, FirstOrderFormMatchesFiniteDifferences) {
  Mesh mesh = distorted_mesh(5, 5, 9);
  PlateSection section{200e9, 0.25, 7854, 0.05};
  PlateOperator op(
      mesh, section,
      boundaries(mesh, Kind::Clamped, Kind::Load, Kind::SimplySupportedHard, Kind::Free), pressure);
  FirstOrderSystem system(op);
  auto y = random_state(system.size(), 2, 1e-3);
  auto yp = random_state(system.size(), 3, 1e-3);
  auto check = test_support::check_jacobian(system, 0.2, 3.7e4, y, yp, 1e-6);
  EXPECT_LT(check.relative(), 1e-6) << "max |J_fd - J| = " << check.max_abs_difference;
  EXPECT_LT(worst_class_difference(system, 0.2, 3.7e4, y, yp, 1e-6), 1e-6);
}

TEST(PlateJacobianTransient, ReducedInertiaFormMatchesFiniteDifferences) {
  Mesh mesh = distorted_mesh(5, 4, 13);
  PlateSection section{200e9, 0.3, 7854, 0.05};
  PlateOperator op(
      mesh, section,
      boundaries(mesh, Kind::SimplySupportedSoft, Kind::Clamped, Kind::Load, Kind::Free), pressure);
  ReducedInertiaSystem system(op, op.rotation_components());
  ASSERT_EQ(system.size(), op.size() + mesh.n_cells());
  auto id = system.differential_components();
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    EXPECT_EQ(id[3 * c], 1.0);
    EXPECT_EQ(id[3 * c + 1], 0.0);
    EXPECT_EQ(system.velocity_index(3 * c + 2), -1);
  }
  auto y = random_state(system.size(), 6, 1e-3);
  auto yp = random_state(system.size(), 7, 1e-3);
  auto check = test_support::check_jacobian(system, 0.2, 3.7e4, y, yp, 1e-6);
  EXPECT_LT(check.relative(), 1e-6) << "max |J_fd - J| = " << check.max_abs_difference;
  EXPECT_LT(worst_class_difference(system, 0.2, 3.7e4, y, yp, 1e-6), 1e-6);
  // The consistent derivative makes the residual vanish at a state whose rotations are in
  // quasi-static equilibrium; check its inertial rows on any state.
  auto yp0 = system.consistent_derivative(0.2, y);
  std::vector<double> r(system.size());
  system.residual(0.2, y, yp0, r);
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    EXPECT_NEAR(r[3 * c], 0.0, 1e-15);
    EXPECT_NEAR(r[system.velocity_index(3 * c)], 0.0,
                1e-9 * std::abs(yp0[system.velocity_index(3 * c)]) + 1e-12);
  }
}

// The residual is affine in y, so the FD check at one state could miss a Jacobian that is
// right only there; this checks R(y) - R(0) = K y at a second, large random state.
TEST(PlateJacobianTransient, ResidualIsAffineWithTheAssembledStiffness) {
  Mesh mesh = distorted_mesh(5, 4, 5);
  PlateOperator op(mesh, {70e9, 0.33, 2700, 0.02},
                   boundaries(mesh, Kind::SimplySupportedSoft, Kind::Clamped, Kind::Load,
                              Kind::SimplySupportedHard),
                   pressure);
  const Index n = op.size();
  auto y = random_state(n, 4, 1.0);
  std::vector<double> r(n), r0(n), zero(n, 0.0), K(op.stiffness_pattern().nnz());
  op.internal_residual(0.3, y, r);
  op.internal_residual(0.3, zero, r0);
  op.stiffness(0.3, y, K);
  const CsrPattern& pat = op.stiffness_pattern();
  double max_diff = 0, max_r = 0;
  for (Index i = 0; i < n; ++i) {
    double ky = 0;
    for (Index k = pat.row_ptr[i]; k < pat.row_ptr[i + 1]; ++k) ky += K[k] * y[pat.col_idx[k]];
    max_diff = std::max(max_diff, std::abs(r[i] - r0[i] - ky));
    max_r = std::max(max_r, std::abs(ky));
  }
  EXPECT_LT(max_diff, 1e-10 * max_r);
}

// With homogeneous data (no pressure, clamped and free edges) the operator can evaluate its
// residual as K y with the assembled stiffness; it must equal the face-by-face evaluation from
// the reconstructions, which a zero pressure field selects, cubic and linear, on a distorted
// mesh whose thin section weighs the shear against the bending (L/h)^2 = 1e4.
TEST(PlateResidual, HomogeneousDataGivesTheFaceByFaceResidual) {
  Mesh mesh = distorted_mesh(6, 5, 21);
  PlateSection section{200e9, 0.3, 7854, 0.01};
  const ScalarField zero = [](const Vec3&, double) { return 0.0; };
  for (int degree : {3, 1}) {
    const auto bcs = boundaries(mesh, Kind::Clamped, Kind::Free, Kind::Clamped, Kind::Free);
    PlateOperator product(mesh, section, bcs, {}, degree), faces(mesh, section, bcs, zero, degree);
    product.set_residual_by_stiffness(true);
    faces.set_residual_by_stiffness(true);  // ignored: its pressure field is data
    const auto y = random_state(product.size(), 8, 1e-3);
    std::vector<double> r_product(product.size()), r_faces(product.size());
    product.internal_residual(0.3, y, r_product);
    faces.internal_residual(0.3, y, r_faces);
    // Per kind of row (w, beta_x, beta_y): the shear rows are (L/h)^2 larger than the bending.
    for (int k = 0; k < 3; ++k) {
      double difference = 0, scale = 0;
      for (Index c = 0; c < mesh.n_cells(); ++c) {
        difference = std::max(difference, std::abs(r_product[3 * c + k] - r_faces[3 * c + k]));
        scale = std::max(scale, std::abs(r_faces[3 * c + k]));
      }
      EXPECT_GT(scale, 0.0);
      EXPECT_LT(difference, 1e-10 * scale) << "degree " << degree << ", row kind " << k;
    }
  }
}

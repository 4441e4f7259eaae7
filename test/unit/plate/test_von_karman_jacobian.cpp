// The analytic Jacobian of the von Karman plate (physics/plate/von_karman_plate.hpp) against
// central finite differences of its residual, on irregular non-orthogonal meshes (smooth
// distortion, random jitter, grading), at random states whose slopes make the membrane strains
// of the deflection comparable to those of the in-plane displacements, with held, free and
// released edges (u = 0; N n = 0; w held but N n = 0), a residual stress, cubic and linear
// reconstructions, in the static and the reduced-inertia transient forms. Entries are compared per
// class (row and column kinds w, beta, u), each on its own scale; a Jacobian with a planted 1 %
// error in the membrane-bending coupling dF_u/dw must fail the same check.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "../../support/distorted_plate.hpp"
#include "../../support/jacobian_check.hpp"
#include "core/reduced_inertia_system.hpp"
#include "core/structural_systems.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/plate/von_karman_plate.hpp"

using namespace rfmems;
using Kind = PlateBoundary::Kind;
using rfmems::test::distorted_mesh;
using rfmems::test_support::random_state;

namespace {

std::vector<PlateBoundary> boundaries(const Mesh& mesh, Kind left, Kind right, Kind bottom,
                                      Kind top) {
  auto value = [](const Vec3& x, double t) {
    return Vec3(1e-3 * (1 + x.y()) * (1 + t), 2e-4 * x.x() - 1e-4, 3e-4 * (1 - t) * x.y());
  };
  std::vector<PlateBoundary> bcs(mesh.patches().size());
  for (std::size_t p = 0; p < bcs.size(); ++p) {
    const std::string& name = mesh.patches()[p].name;
    bcs[p].kind = name == "left" ? left : name == "right" ? right : name == "bottom" ? bottom : top;
    if (bcs[p].kind == Kind::Load)
      bcs[p].value = [](const Vec3& x, double) { return Vec3(-50.0 * (1 + x.x()), 3.0, -2.0); };
    else if (bcs[p].kind != Kind::Clamped && bcs[p].kind != Kind::Free)
      bcs[p].value = value;
  }
  return bcs;
}

const ScalarField pressure = [](const Vec3& x, double t) { return -1e3 * (1 + x.x() * x.y() + t); };

// Class of unknown i: 0 w, 1 beta, 2 in-plane (the plate's 3 n unknowns, then the 2 n in-plane
// ones, then in a reduced-inertia system the velocities of w, counted as w).
int kind_of(Index i, Index n_plate) {
  if (i >= n_plate / 3 * 5) return 0;
  return i >= n_plate ? 2 : (i % 3 == 0 ? 0 : 1);
}

// The worst over the classes of max |J_fd - J| / max |J| (entries outside the pattern
// included); every class must be non-empty.
double worst_class_difference(SystemOperator& op, Index n_plate, double t, double c_j,
                              const std::vector<double>& y, const std::vector<double>& yp,
                              const std::vector<double>& values) {
  double diff[3][3] = {}, scale[3][3] = {};
  std::vector<double> steps(y.size(), 1e-7);
  test_support::for_each_jacobian_entry(
      op, t, c_j, y, yp, steps, values, [&](Index i, Index j, double fd, double analytic) {
        const int a = kind_of(i, n_plate), b = kind_of(j, n_plate);
        diff[a][b] = std::max(diff[a][b], std::abs(fd - analytic));
        scale[a][b] = std::max(scale[a][b], std::abs(analytic));
      });
  double worst = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      if ((a == 1) != (b == 1) && (a == 2 || b == 2)) continue;  // beta-u: none
      if (scale[a][b] == 0 && (a == 1 || b == 1)) continue;      // the membrane part: no beta
      EXPECT_GT(scale[a][b], 0.0) << "class " << a << b << " is empty";
      worst = std::max(worst, diff[a][b] / scale[a][b]);
      std::printf("class %d%d: max |J_fd - J| / max |J| = %.2e\n", a, b, diff[a][b] / scale[a][b]);
    }
  return worst;
}

struct Setup {
  Mesh mesh;
  PlateSection section;
  std::unique_ptr<PlateOperator> plate;
  std::unique_ptr<VonKarmanPlate> op;
};

std::unique_ptr<Setup> setup(Kind left, Kind right, Kind bottom, Kind top, int degree,
                             bool prestressed, bool release_right = false) {
  auto s =
      std::make_unique<Setup>(Setup{distorted_mesh(6, 5, 3), {200e9, 0.3, 7854, 0.05}, {}, {}});
  if (prestressed) s->section.residual_stress << 8e7, 3e7, 0, 3e7, 5e7, 0, 0, 0, 0;
  std::vector<PlateBoundary> bcs = boundaries(s->mesh, left, right, bottom, top);
  for (std::size_t p = 0; p < bcs.size(); ++p)
    bcs[p].in_plane_free = release_right && s->mesh.patches()[p].name == "right";
  s->plate = std::make_unique<PlateOperator>(s->mesh, s->section, bcs, pressure, degree);
  s->op = std::make_unique<VonKarmanPlate>(*s->plate);
  return s;
}

// The state: w and beta of 1e-2 (slopes ~ 1e-2, membrane strains ~ 1e-4), u of 1e-4.
std::vector<double> state(const VonKarmanPlate& op, unsigned seed) {
  std::vector<double> y = random_state(op.size(), seed, 1e-2);
  for (Index i = 3 * op.plate().mesh().n_cells(); i < op.size(); ++i) y[i] *= 1e-2;
  return y;
}

}  // namespace

// The membrane part alone, von Karman minus the (linear) plate: its w-w entries, (N grad w) .S
// differentiated, are ~1e-5 of the plate's shear entries, so they are checked here on their
// own scale.
class MembranePart : public SecondOrderOperator {
 public:
  explicit MembranePart(VonKarmanPlate& op)
      : op_(op), plate_(const_cast<PlateOperator&>(op.plate())) {}
  Index size() const override { return op_.size(); }
  void internal_residual(Real t, std::span<const Real> y, std::span<Real> r) override {
    op_.internal_residual(t, y, r);
    std::vector<Real> rp(plate_.size());
    plate_.internal_residual(t, y.first(plate_.size()), rp);
    for (Index i = 0; i < plate_.size(); ++i) r[i] -= rp[i];
  }
  const CsrPattern& stiffness_pattern() const override { return op_.stiffness_pattern(); }
  void stiffness(Real t, std::span<const Real> y, std::span<Real> values) override {
    op_.stiffness(t, y, values);
    const CsrPattern& pp = plate_.stiffness_pattern();
    std::vector<Real> vp(pp.nnz());
    plate_.stiffness(t, y.first(plate_.size()), vp);
    for (Index i = 0; i < pp.n_rows(); ++i)
      for (Index k = pp.row_ptr[i]; k < pp.row_ptr[i + 1]; ++k)
        values[op_.stiffness_pattern().find(i, pp.col_idx[k])] -= vp[k];
  }
  std::vector<Real> mass_diagonal() const override { return op_.mass_diagonal(); }

 private:
  VonKarmanPlate& op_;
  PlateOperator& plate_;
};

struct VonKarmanCase {
  Kind left, right, bottom, top;
  int degree;
  bool prestressed;
};

class VonKarmanJacobian : public ::testing::TestWithParam<VonKarmanCase> {};

namespace {

// The static Jacobian at a random state (seed) against finite differences: the whole operator,
// then its membrane part on its own scale.
void expect_static_jacobian_matches(const Setup& s, unsigned seed) {
  StaticSystem system(*s.op);
  const auto y = state(*s.op, seed);
  const std::vector<double> yp(system.size(), 0.0);
  const auto values = test_support::analytic_jacobian(system, 0.4, 0.0, y, yp);
  EXPECT_LT(worst_class_difference(system, s.plate->size(), 0.4, 0.0, y, yp, values), 1e-6);
  MembranePart membrane(*s.op);
  StaticSystem membrane_system(membrane);
  const auto membrane_values = test_support::analytic_jacobian(membrane_system, 0.4, 0.0, y, yp);
  EXPECT_LT(
      worst_class_difference(membrane_system, s.plate->size(), 0.4, 0.0, y, yp, membrane_values),
      1e-6);
}

}  // namespace

TEST_P(VonKarmanJacobian, StaticMatchesFiniteDifferences) {
  const VonKarmanCase c = GetParam();
  auto s = setup(c.left, c.right, c.bottom, c.top, c.degree, c.prestressed);
  expect_static_jacobian_matches(*s, 1);
}

INSTANTIATE_TEST_SUITE_P(
    HeldAndFreeEdges, VonKarmanJacobian,
    ::testing::Values(VonKarmanCase{Kind::Clamped, Kind::Load, Kind::SimplySupportedHard,
                                    Kind::Free, 3, false},
                      VonKarmanCase{Kind::Displacement, Kind::SimplySupportedSoft, Kind::Clamped,
                                    Kind::SimplySupportedHard, 3, true},
                      VonKarmanCase{Kind::SimplySupportedHard, Kind::Free, Kind::Displacement,
                                    Kind::Load, 1, true}));

// An edge that holds w but is released in-plane (N n = 0 there): separate reconstructions of w
// and u.
TEST(VonKarmanJacobian, EdgeReleasedInPlaneMatchesFiniteDifferences) {
  auto s = setup(Kind::Clamped, Kind::SimplySupportedHard, Kind::Displacement, Kind::Free, 3, false,
                 true);
  expect_static_jacobian_matches(*s, 3);
}

// A 1 % error planted in the membrane-bending coupling (rows u, v; columns w), or in the w-w
// entries of the membrane part, is caught.
TEST(VonKarmanJacobianCheck, CatchesAPlantedOnePercentError) {
  auto s = setup(Kind::Clamped, Kind::Load, Kind::SimplySupportedHard, Kind::Free, 3, false);
  MembranePart membrane(*s->op);
  StaticSystem system(membrane);
  const auto y = state(*s->op, 2);
  const std::vector<double> yp(system.size(), 0.0);
  auto values = test_support::analytic_jacobian(system, 0.4, 0.0, y, yp);
  const Index n_plate = s->plate->size();
  EXPECT_LT(worst_class_difference(system, n_plate, 0.4, 0.0, y, yp, values), 1e-6);
  const CsrPattern& pattern = system.jacobian_pattern();
  for (Index i = n_plate; i < pattern.n_rows(); ++i)
    for (Index k = pattern.row_ptr[i]; k < pattern.row_ptr[i + 1]; ++k)
      if (pattern.col_idx[k] < n_plate) values[k] *= 1.01;
  EXPECT_GT(worst_class_difference(system, n_plate, 0.4, 0.0, y, yp, values), 5e-3);
  values = test_support::analytic_jacobian(system, 0.4, 0.0, y, yp);
  for (Index i = 0; i < n_plate; i += 3)
    for (Index k = pattern.row_ptr[i]; k < pattern.row_ptr[i + 1]; ++k)
      if (pattern.col_idx[k] < n_plate && pattern.col_idx[k] % 3 == 0) values[k] *= 1.01;
  EXPECT_GT(worst_class_difference(system, n_plate, 0.4, 0.0, y, yp, values), 5e-3);
}

TEST(VonKarmanJacobianTransient, ReducedInertiaFormMatchesFiniteDifferences) {
  auto s = setup(Kind::SimplySupportedSoft, Kind::Clamped, Kind::Load, Kind::Free, 3, true);
  ReducedInertiaSystem system(*s->op, s->op->quasi_static_components());
  auto y = random_state(system.size(), 6, 1e-2);
  auto yp = random_state(system.size(), 7, 1e-2);
  for (Index i = s->op->size() / 5 * 3; i < s->op->size(); ++i) y[i] *= 1e-2;
  const auto values = test_support::analytic_jacobian(system, 0.2, 3.7e4, y, yp);
  EXPECT_LT(worst_class_difference(system, s->plate->size(), 0.2, 3.7e4, y, yp, values), 1e-6);
}

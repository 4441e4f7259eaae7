// The analytic Jacobian of the total Lagrangian (St Venant-Kirchhoff) elasticity operator
// (ElasticityOperator::set_geometric_nonlinearity) against central finite differences of its
// residual, at states whose displacement gradients are of order 0.1-1 (rotations of tens of
// degrees), on irregular non-orthogonal meshes in plane stress, plane strain and 3D, with every
// boundary kind, a residual stress, and the first-order transient form. The same check must
// fail for the small-strain Jacobian at those states and for a Jacobian with a planted 1 %
// error in its x-y coupling.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../../support/distorted_box.hpp"
#include "../../support/jacobian_check.hpp"
#include "core/structural_systems.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/elasticity/elasticity_operator.hpp"

using namespace rfmems;
using rfmems::test::distortion;

namespace {

std::vector<ElasticityBoundary> mixed_boundaries(const Mesh& mesh) {
  std::vector<ElasticityBoundary> bcs(mesh.patches().size());
  for (std::size_t p = 0; p < bcs.size(); ++p) {
    const std::string& name = mesh.patches()[p].name;
    if (name == "left")
      bcs[p] = {ElasticityBoundary::Kind::Fixed,
                [](const Vec3& x, double t) { return Vec3(0.05 * x.y() * (1 + t), 0.02, 0.0); }};
    else if (name == "bottom")
      bcs[p] = {ElasticityBoundary::Kind::Symmetry, {}};
    else
      bcs[p] = {ElasticityBoundary::Kind::Traction,
                [](const Vec3&, double) { return Vec3(1e9, -2e9, 3e8); }};
  }
  return bcs;
}

Mesh box(int dim, unsigned seed) {
  BoxSpec spec;
  spec.dim = dim;
  spec.upper = Vec3(1.5, 1.0, 1.0);
  spec.n[0] = 5;
  spec.n[1] = 4;
  spec.n[2] = dim == 3 ? 3 : 1;
  spec.grading[0] = 1.5;
  return make_structured_mesh(spec, distortion(0.03, seed));
}

// Displacements of +-0.1 on cells ~0.3 apart: gradients up to ~0.7.
std::vector<double> large_state(Index n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-0.1, 0.1);
  std::vector<double> y(n);
  for (double& v : y) v = value(rng);
  return y;
}

double fd_difference(SystemOperator& system, const std::vector<double>& y,
                     const std::vector<double>& yp, double c_j, const std::vector<double>& values) {
  double diff = 0, scale = 0;
  test_support::for_each_jacobian_entry(system, 0.3, c_j, y, yp,
                                        std::vector<double>(y.size(), 1e-6), values,
                                        [&](Index, Index, double fd, double analytic) {
                                          diff = std::max(diff, std::abs(fd - analytic));
                                          scale = std::max(scale, std::abs(analytic));
                                        });
  return diff / scale;
}

}  // namespace

TEST(LargeDeformationJacobian, MatchesFiniteDifferencesInEveryHypothesis) {
  for (Hypothesis hyp : {Hypothesis::PlaneStress, Hypothesis::PlaneStrain, Hypothesis::ThreeD}) {
    const int dim = hyp == Hypothesis::ThreeD ? 3 : 2;
    Mesh mesh = box(dim, 7 + dim);
    for (bool prestressed : {false, true}) {
      LinearElastic steel{200e9, 0.3, 7854, hyp};
      if (prestressed) {
        steel.residual_stress << 9e9, 4e9, -2e9, 4e9, -6e9, 3e9, -2e9, 3e9, 7e9;
        if (dim == 2)
          steel.residual_stress.col(2).setZero(), steel.residual_stress.row(2).setZero();
      }
      ElasticityOperator op(mesh, steel, mixed_boundaries(mesh),
                            [](const Vec3&, double) { return Vec3(0, -1e9, 2e8); });
      op.set_geometric_nonlinearity(true);
      StaticSystem system(op);
      const auto y = large_state(system.size(), 3);
      const std::vector<double> yp(system.size(), 0.0);
      const auto values = test_support::analytic_jacobian(system, 0.3, 0.0, y, yp);
      const double d = fd_difference(system, y, yp, 0.0, values);
      std::printf("%s%s: max |J_fd - J| / max |J| = %.2e\n",
                  hyp == Hypothesis::PlaneStress   ? "plane stress"
                  : hyp == Hypothesis::PlaneStrain ? "plane strain"
                                                   : "3D",
                  prestressed ? ", prestressed" : "", d);
      EXPECT_LT(d, 1e-6);
    }
  }
}

TEST(LargeDeformationJacobian, TransientFormMatchesFiniteDifferences) {
  Mesh mesh = box(2, 21);
  ElasticityOperator op(mesh, LinearElastic{210e9, 0.25, 7800, Hypothesis::PlaneStress},
                        mixed_boundaries(mesh));
  op.set_geometric_nonlinearity(true);
  FirstOrderSystem system(op);
  const auto y = large_state(system.size(), 4), yp = large_state(system.size(), 5);
  const auto values = test_support::analytic_jacobian(system, 0.3, 2.5e4, y, yp);
  EXPECT_LT(fd_difference(system, y, yp, 2.5e4, values), 1e-6);
}

TEST(LargeDeformationJacobian, TheCheckCatchesTheSmallStrainJacobianAndAPlantedError) {
  Mesh mesh = box(2, 23);
  const LinearElastic steel{200e9, 0.3, 7854, Hypothesis::PlaneStress};
  ElasticityOperator op(mesh, steel, mixed_boundaries(mesh));
  op.set_geometric_nonlinearity(true);
  StaticSystem system(op);
  const auto y = large_state(system.size(), 6);
  const std::vector<double> yp(system.size(), 0.0);
  auto values = test_support::analytic_jacobian(system, 0.3, 0.0, y, yp);
  // 1 % on every dF_x/du_y entry.
  const CsrPattern& pattern = system.jacobian_pattern();
  for (Index i = 0; i < pattern.n_rows(); i += 2)
    for (Index k = pattern.row_ptr[i]; k < pattern.row_ptr[i + 1]; ++k)
      if (pattern.col_idx[k] % 2 == 1) values[k] *= 1.01;
  const double planted = fd_difference(system, y, yp, 0.0, values);
  std::printf("planted 1 %% error: %.2e\n", planted);
  EXPECT_GT(planted, 1e-3);
  // The small-strain operator's Jacobian at the same state.
  ElasticityOperator linear(mesh, steel, mixed_boundaries(mesh));
  StaticSystem linear_system(linear);
  const auto small_strain = test_support::analytic_jacobian(linear_system, 0.3, 0.0, y, yp);
  const double wrong = fd_difference(system, y, yp, 0.0, small_strain);
  std::printf("small-strain Jacobian: %.2e\n", wrong);
  EXPECT_GT(wrong, 1e-2);
}

// The analytic Jacobian of the fully linearised FV elasticity operator against central finite
// differences of its residual, on irregular non-orthogonal meshes in 2D and 3D, with every
// boundary kind (fixed, traction, symmetry) and the first-order transient form.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../../support/distorted_box.hpp"
#include "../../support/jacobian_check.hpp"
#include "core/reduced_inertia_system.hpp"
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
                [](const Vec3& x, double t) { return Vec3(1e-3 * x.y() * (1 + t), 2e-3, 0.0); }};
    else if (name == "bottom")
      bcs[p] = {ElasticityBoundary::Kind::Symmetry, {}};
    else
      bcs[p] = {ElasticityBoundary::Kind::Traction,
                [](const Vec3&, double) { return Vec3(1e5, -2e5, 3e4); }};
  }
  return bcs;
}

// A unit square of nx x ny cells, distorted as above.
Mesh distorted_square(int nx, int ny, double amplitude, unsigned seed) {
  BoxSpec spec;
  spec.dim = 2;
  spec.n[0] = nx;
  spec.n[1] = ny;
  return make_structured_mesh(spec, distortion(amplitude, seed));
}

std::vector<double> random_state(Index n, unsigned seed) {
  return test_support::random_state(n, seed, 1e-3);
}

// The box [0, 1.5] x [0, 1] (x [0, 1]) on 4 x 3 (x 3) cells, its nodes moved by distortion(0.03,
// seed): the prestressed and stiffness-product tests' body in 2D and 3D.
Mesh skewed_box(int dim, unsigned seed) {
  BoxSpec spec;
  spec.dim = dim;
  spec.upper = Vec3(1.5, 1.0, 1.0);
  spec.n[0] = 4;
  spec.n[1] = 3;
  spec.n[2] = dim == 3 ? 3 : 1;
  return make_structured_mesh(spec, distortion(0.03, seed));
}

}  // namespace

TEST(ElasticityJacobian, MatchesFiniteDifferences2DPlaneStrainSkewed) {
  BoxSpec spec;
  spec.dim = 2;
  spec.upper = Vec3(2.0, 1.0, 0);
  spec.n[0] = 6;
  spec.n[1] = 4;
  spec.grading[0] = 2.0;
  Mesh mesh = make_structured_mesh(spec, distortion(0.04, 7));
  LinearElastic steel{200e9, 0.31, 7854, Hypothesis::PlaneStrain};
  ElasticityOperator op(mesh, steel, mixed_boundaries(mesh),
                        [](const Vec3&, double) { return Vec3(0, -1e4, 0); });
  StaticSystem system(op);
  auto y = random_state(system.size(), 1);
  std::vector<double> yp(system.size(), 0.0);
  auto check = test_support::check_jacobian(system, 0.3, 0.0, y, yp, 1e-6);
  EXPECT_LT(check.relative(), 1e-6) << "max |J_fd - J| = " << check.max_abs_difference;
  EXPECT_GT(check.max_abs_entry, 1e9);
}

TEST(ElasticityJacobian, MatchesFiniteDifferences2DPlaneStressTransient) {
  Mesh mesh = distorted_square(5, 5, 0.05, 11);
  LinearElastic steel{210e9, 0.25, 7800, Hypothesis::PlaneStress};
  ElasticityOperator op(mesh, steel, mixed_boundaries(mesh));
  FirstOrderSystem system(op);
  auto y = random_state(system.size(), 2);
  auto yp = random_state(system.size(), 3);
  auto check = test_support::check_jacobian(system, 0.1, 2.5e4, y, yp, 1e-6);
  EXPECT_LT(check.relative(), 1e-6) << "max |J_fd - J| = " << check.max_abs_difference;
}

TEST(ElasticityJacobian, MatchesFiniteDifferences3DSkewedBox) {
  BoxSpec spec;
  spec.dim = 3;
  spec.upper = Vec3(1.5, 1.0, 1.0);
  spec.n[0] = 4;
  spec.n[1] = 3;
  spec.n[2] = 3;
  spec.grading[2] = 1.5;
  Mesh mesh = make_structured_mesh(spec, distortion(0.03, 5));
  LinearElastic steel{200e9, 0.3, 7854, Hypothesis::ThreeD};
  ElasticityOperator op(mesh, steel, mixed_boundaries(mesh));
  StaticSystem system(op);
  auto y = random_state(system.size(), 4);
  std::vector<double> yp(system.size(), 0.0);
  auto check = test_support::check_jacobian(system, 0.0, 0.0, y, yp, 1e-6);
  EXPECT_LT(check.relative(), 1e-6) << "max |J_fd - J| = " << check.max_abs_difference;
}

// The geometric stiffness of a residual stress: a full stress tensor, of the order of the
// moduli so that its terms are not hidden in the elastic ones, in 2D and 3D.
TEST(ElasticityJacobian, PrestressedMatchesFiniteDifferences) {
  for (int dim : {2, 3}) {
    Mesh mesh = skewed_box(dim, 19);
    LinearElastic steel{200e9, 0.3, 7854, dim == 3 ? Hypothesis::ThreeD : Hypothesis::PlaneStress};
    steel.residual_stress << 9e10, 4e10, -2e10, 4e10, -6e10, 3e10, -2e10, 3e10, 7e10;
    if (dim == 2) steel.residual_stress.col(2).setZero(), steel.residual_stress.row(2).setZero();
    ElasticityOperator op(mesh, steel, mixed_boundaries(mesh));
    StaticSystem system(op);
    auto y = random_state(system.size(), 8);
    std::vector<double> yp(system.size(), 0.0);
    auto check = test_support::check_jacobian(system, 0.2, 0.0, y, yp, 1e-6);
    EXPECT_LT(check.relative(), 1e-6) << dim << "D: max |J_fd - J| = " << check.max_abs_difference;
    // The prestress changes the stiffness by a fraction of the elastic part, not by round-off.
    ElasticityOperator plain(mesh, LinearElastic{200e9, 0.3, 7854, steel.hypothesis},
                             mixed_boundaries(mesh));
    std::vector<double> a(op.stiffness_pattern().nnz()), b(a.size());
    op.stiffness(0.2, y, a);
    plain.stiffness(0.2, y, b);
    double change = 0, largest = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      change = std::max(change, std::abs(a[i] - b[i])), largest = std::max(largest, std::abs(b[i]));
    EXPECT_GT(change, 0.05 * largest) << dim << "D";
  }
}

// Kelvin-Voigt damping C = beta K in both first-order forms (FirstOrderSystem,
// ReducedInertiaSystem): the v rows' Jacobian c_j M + beta K, by finite differences. beta is
// chosen so that beta K is comparable with c_j M (an error in either is visible).
TEST(ElasticityJacobian, DampedTransientFormsMatchFiniteDifferences) {
  Mesh mesh = distorted_square(5, 4, 0.05, 13);
  LinearElastic steel{210e9, 0.25, 7800, Hypothesis::PlaneStress};
  ElasticityOperator op(mesh, steel, mixed_boundaries(mesh),
                        [](const Vec3&, double) { return Vec3(0, -1e4, 0); });
  op.set_damping_time(1e-4);
  FirstOrderSystem first_order(op);
  ReducedInertiaSystem reduced(op, {});
  for (SystemOperator* system : std::initializer_list<SystemOperator*>{&first_order, &reduced}) {
    auto y = random_state(system->size(), 4);
    auto yp = random_state(system->size(), 5);
    auto check = test_support::check_jacobian(*system, 0.1, 2.5e4, y, yp, 1e-6);
    EXPECT_LT(check.relative(), 1e-6) << "max |J_fd - J| = " << check.max_abs_difference;
  }
}

// The damping force is beta K v with K the stiffness at homogeneous data: R(t, v) - R(t, 0)
// for an operator with prescribed displacements, tractions and a body force (all of which the
// damping must leave out).
TEST(ElasticityJacobian, DampingForceIsBetaTimesTheStiffnessTimesTheVelocity) {
  Mesh mesh = distorted_square(6, 3, 0.04, 17);
  LinearElastic steel{200e9, 0.3, 7854, Hypothesis::PlaneStress};
  ElasticityOperator op(mesh, steel, mixed_boundaries(mesh),
                        [](const Vec3&, double) { return Vec3(3e4, -1e4, 0); });
  const Real beta = 2.5e-9;
  op.set_damping_time(beta);
  const Index n = op.size();
  auto v = random_state(n, 6);
  std::vector<double> zero(n, 0.0), r_v(n), r_0(n), damping(n, 0.0);
  op.internal_residual(0.7, v, r_v);
  op.internal_residual(0.7, zero, r_0);
  op.add_damping_force(0.7, v, damping);
  double difference = 0, scale = 0;
  for (Index i = 0; i < n; ++i) {
    difference = std::max(difference, std::abs(damping[i] - beta * (r_v[i] - r_0[i])));
    scale = std::max(scale, std::abs(damping[i]));
  }
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(difference, 1e-9 * scale);
}

// The matrix-free product of the multigrid path (physics/structure/distributed_analysis.cpp):
// K v from the operator without the matrix equals the assembled stiffness times v, on a
// skewed 3D box and a 2D square with a residual stress and boundary data (which K v leaves
// out), and is not offered with large deformations (where K depends on u).
TEST(ElasticityJacobian, StiffnessProductEqualsTheAssembledStiffness) {
  for (const int dim : {2, 3}) {
    const Mesh mesh = skewed_box(dim, 21);
    LinearElastic steel{200e9, 0.3, 7854, dim == 3 ? Hypothesis::ThreeD : Hypothesis::PlaneStress};
    steel.residual_stress << 9e8, 4e8, -2e8, 4e8, -6e8, 3e8, -2e8, 3e8, 7e8;
    if (dim == 2) steel.residual_stress.col(2).setZero(), steel.residual_stress.row(2).setZero();
    ElasticityOperator op(mesh, steel, mixed_boundaries(mesh));
    ASSERT_TRUE(op.has_stiffness_product());
    const Index n = op.size();
    const auto u = random_state(n, 22), v = random_state(n, 23);
    std::vector<double> k(op.stiffness_pattern().nnz()), kv(n), product(n, 0.0);
    op.stiffness(0.4, u, k);
    op.stiffness_product(0.4, u, v, kv);
    const CsrPattern& p = op.stiffness_pattern();
    double difference = 0, scale = 0;
    for (Index i = 0; i < n; ++i) {
      for (Index e = p.row_ptr[i]; e < p.row_ptr[i + 1]; ++e) product[i] += k[e] * v[p.col_idx[e]];
      difference = std::max(difference, std::abs(kv[i] - product[i]));
      scale = std::max(scale, std::abs(product[i]));
    }
    EXPECT_GT(scale, 0.0);
    EXPECT_LT(difference, 1e-12 * scale) << dim << "D";
    op.set_geometric_nonlinearity(true);
    EXPECT_FALSE(op.has_stiffness_product()) << dim << "D";
  }
}

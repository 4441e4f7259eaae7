// The analytic Jacobian of the continuum creep system (physics/creep/continuum_creep_system.hpp)
// against central differences of its residual, at a random state (displacements, plastic
// strains, effective strains) on non-orthogonal distorted meshes with fixed (non-zero value),
// symmetry and loaded / free faces, for plane stress, plane strain and 3D; initial_state is
// consistent (F(t0, y0, y0') = 0); and a uniform volume-preserving plastic strain on a body held
// only by symmetry planes is stress-free at u = eps_p x (the source on interior, symmetry and
// traction faces is consistent with the elastic fluxes).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "../../support/creep_continuum_fixture.hpp"
#include "../../support/jacobian_check.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/creep/continuum_creep_system.hpp"

using namespace rfmems;
using Kind = ElasticityBoundary::Kind;

namespace {

LinearElastic steel(Hypothesis h) { return {200e9, 0.3, 7854, h}; }

void check_jacobian_of(int dim, Hypothesis h, bool bending_only = false) {
  const Mesh mesh =
      dim == 2 ? test::creep_test_mesh(2, 6, 4, 1, 4) : test::creep_test_mesh(3, 4, 3, 2, 5);
  ElasticityOperator op(mesh, steel(h), test::creep_test_boundaries(mesh));
  // Moderate hardening so that every term of the rate Jacobian is visible at this state.
  ContinuumCreepSystem system(op, CreepLaw{1e-3, 3e3, 2.5, 1.5, 1e9});
  if (bending_only) system.set_creep_stress_mask({true, false, true, false, false, false});
  const int nq = system.n_components();
  ASSERT_EQ(nq, h == Hypothesis::PlaneStress ? 4 : h == Hypothesis::PlaneStrain ? 5 : 7);
  ASSERT_EQ(system.size(), (dim + nq) * mesh.n_cells());

  const Index ns = system.structural_size();
  const auto [y, yp, steps, scales] = test::random_continuum_creep_state(system, 7);
  for (Real c_j : {0.0, 2.5e2}) {
    const auto check = test_support::check_jacobian(system, 0.3, c_j, y, yp, steps, scales);
    // Round-off of the central differences bounds both measures: a wrong term is O(1) off.
    EXPECT_LT(check.max_entry_relative, 1e-3)
        << "c_j " << c_j << " row " << check.worst_entry_row << " col " << check.worst_entry_col;
    EXPECT_LT(check.max_row_relative, 1e-6) << "c_j " << c_j << " row " << check.worst_row;
    std::printf("dim %d, hypothesis %d, c_j %g: row-relative %.2e, entry-relative %.2e\n", dim,
                static_cast<int>(h), c_j, check.max_row_relative, check.max_entry_relative);
  }

  // initial_state: F(t0, y0, y0') = 0.
  std::vector<Real> state, state_dot, r(system.size());
  system.initial_state(0.0, state, state_dot);
  system.residual(0.0, state, state_dot, r);
  Real worst = 0, rate = 0;
  for (Index k = 0; k < ns; ++k) worst = std::max(worst, std::abs(r[k]));
  for (Index k = ns; k < system.size(); ++k) rate = std::max(rate, std::abs(state_dot[k]));
  EXPECT_LT(worst, 1e-9 * 5e7 * 2.0);  // force scale: the load times a face area
  for (Index k = ns; k < system.size(); ++k) EXPECT_LE(std::abs(r[k]), 1e-12 * rate);
}

}  // namespace

TEST(ContinuumCreepSystem, PlaneStressJacobianMatchesFiniteDifferences) {
  check_jacobian_of(2, Hypothesis::PlaneStress);
}
TEST(ContinuumCreepSystem, PlaneStrainJacobianMatchesFiniteDifferences) {
  check_jacobian_of(2, Hypothesis::PlaneStrain);
}
// The diagnostic that lets the creep law see only sigma_xx (and sigma_zz).
TEST(ContinuumCreepSystem, BendingOnlyCreepJacobianMatchesFiniteDifferences) {
  check_jacobian_of(2, Hypothesis::PlaneStress, true);
}
TEST(ContinuumCreepSystem, ThreeDJacobianMatchesFiniteDifferences) {
  check_jacobian_of(3, Hypothesis::ThreeD);
}

// A body held only by symmetry planes (left, bottom, and back in 3D) and free elsewhere, with a
// uniform volume-preserving plastic strain: the exact solution is u = eps_p x with zero stress
// (plane strain: eps_p,zz = 0, since eps_zz = 0 would otherwise be stressed). The cubic (2D) and
// quadratic (3D) reconstructions are exact for it, so the discrete solution is too, to round-off.
TEST(ContinuumCreepSystem, UniformPlasticStrainOnAFreeBodyIsStressFree) {
  for (Hypothesis h : {Hypothesis::PlaneStress, Hypothesis::PlaneStrain, Hypothesis::ThreeD}) {
    const int dim = h == Hypothesis::ThreeD ? 3 : 2;
    // Symmetry planes must be the planes x = 0, y = 0, z = 0: a graded, undistorted box.
    BoxSpec spec;
    spec.dim = dim;
    spec.upper = Vec3(2.0, 1.2, dim == 3 ? 0.8 : 0.0);
    spec.n[0] = 6;
    spec.n[1] = 4;
    spec.n[2] = 3;
    spec.grading[0] = 1.6;
    spec.grading[1] = 0.7;
    const Mesh box = make_structured_mesh(spec);
    std::vector<ElasticityBoundary> bcs(box.patches().size());
    for (std::size_t p = 0; p < bcs.size(); ++p) {
      const std::string& name = box.patches()[p].name;
      if (name == "left" || name == "bottom" || name == "back") bcs[p].kind = Kind::Symmetry;
    }
    ElasticityOperator op(box, steel(h), bcs);
    ContinuumCreepSystem system(op, CreepLaw{1e-3, 3e3, 2.0, 2.0, 1e9});
    const Mat3 eps_p = h == Hypothesis::PlaneStrain ? Vec3(2e-4, -2e-4, 0).asDiagonal()
                                                    : Vec3(2e-4, -0.5e-4, -1.5e-4).asDiagonal();
    std::vector<Real> state(system.size(), 0.0);
    for (Index c = 0; c < box.n_cells(); ++c)
      for (int k = 0; k < system.n_plastic_components(); ++k) {
        const auto [i, j] = system.component(k);
        state[system.creep_index(c, k)] = eps_p(i, j);
      }
    system.equilibrate(0.0, state);
    Real u_error = 0, stress = 0;
    for (Index c = 0; c < box.n_cells(); ++c) {
      const Vec3 exact = eps_p * box.cell_centroid(c);
      for (int a = 0; a < dim; ++a)
        u_error = std::max(u_error, std::abs(state[dim * c + a] - exact[a]));
    }
    for (const Mat3& s : system.cell_stresses(0.0, state)) stress = std::max(stress, s.norm());
    const Real stress_scale = 2 * op.material().mu() * 2e-4;
    std::printf("hypothesis %d: max |u - eps_p x| = %.2e m, max |sigma| = %.2e Pa\n",
                static_cast<int>(h), u_error, stress);
    EXPECT_LT(u_error, 1e-10 * 2e-4 * 2.0);
    EXPECT_LT(stress, 1e-8 * stress_scale);
    // The plastic strain reported is volume preserving (plane stress: zz derived).
    for (Index c = 0; c < box.n_cells(); ++c)
      EXPECT_NEAR(system.plastic_strain(state, c).trace(), 0.0, 1e-15 * 2e-4);
  }
}

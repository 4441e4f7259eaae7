// The continuum creep system's Krylov preconditioner
// (physics/creep/continuum_creep_preconditioner.hpp) and the creep runs it serves:
// - P^-1 is the exact inverse of the Jacobian whose structural tangent T is raised by
//   B D^-1 E (the Schur complement it drops), on distorted 2D and 3D meshes with every kind of
//   boundary, with and without a relaxing prestress: the block algebra is right;
// - its error on the true Jacobian, the creep's share B D^-1 E of the step's tangent, falls as
//   1 / c_j (observed order 1): the smaller the step, the better it is;
// - IDA with GMRES and this preconditioner gives the creep deflection of IDA with the sparse LU
//   of the full Jacobian on the plane-stress strip of the creep benchmark, with about one GMRES
//   iteration a Newton step.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <random>

#include "../../support/creep_continuum_fixture.hpp"
#include "physics/creep/continuum_creep_system.hpp"
#include "physics/creep/continuum_plate_comparison.hpp"

using namespace rfmems;

namespace {

using Solver = ContinuumCreepSystem::LinearSolver;

LinearElastic steel(Hypothesis h, int dim, bool prestressed) {
  LinearElastic m{200e9, 0.3, 7854, h};
  if (prestressed && dim == 3) m.residual_stress << 8e7, 2e7, -1e7, 2e7, 5e7, 3e7, -1e7, 3e7, 4e7;
  if (prestressed && dim == 2) m.residual_stress << 8e7, 2e7, 0, 2e7, 5e7, 0, 0, 0, 0;
  return m;
}

struct Blocks {
  Eigen::MatrixXd J, T, B, E, D;
};

Blocks dense_jacobian(ContinuumCreepSystem& system, Real c_j, const std::vector<Real>& y,
                      const std::vector<Real>& yp) {
  const CsrPattern& pattern = system.jacobian_pattern();
  std::vector<Real> values(pattern.nnz());
  system.jacobian(0.3, c_j, y, yp, values);
  const Index n = system.size(), ns = system.structural_size();
  Blocks b;
  b.J = Eigen::MatrixXd::Zero(n, n);
  for (Index i = 0; i < n; ++i)
    for (Index k = pattern.row_ptr[i]; k < pattern.row_ptr[i + 1]; ++k)
      b.J(i, pattern.col_idx[k]) += values[k];
  b.T = b.J.topLeftCorner(ns, ns);
  b.B = b.J.topRightCorner(ns, n - ns);
  b.E = b.J.bottomLeftCorner(n - ns, ns);
  b.D = b.J.bottomRightCorner(n - ns, n - ns);
  return b;
}

// Largest |a - b| over each part (u, q), relative to the part's largest |b|.
std::pair<Real, Real> part_errors(const Eigen::VectorXd& a, const Eigen::VectorXd& b, Index ns) {
  const Index nq = b.size() - ns;
  return {(a.head(ns) - b.head(ns)).cwiseAbs().maxCoeff() / b.head(ns).cwiseAbs().maxCoeff(),
          (a.tail(nq) - b.tail(nq)).cwiseAbs().maxCoeff() / b.tail(nq).cwiseAbs().maxCoeff()};
}

Eigen::VectorXd random_vector(const ContinuumCreepSystem& system, unsigned seed) {
  const auto s = test::random_continuum_creep_state(system, seed);
  return Eigen::Map<const Eigen::VectorXd>(s.y.data(), static_cast<Index>(s.y.size()));
}

Eigen::VectorXd apply_preconditioner(ContinuumCreepSystem& system, const Eigen::VectorXd& r) {
  Eigen::VectorXd z(r.size());
  system.preconditioner_solve(std::span<const Real>(r.data(), r.size()),
                              std::span<Real>(z.data(), z.size()));
  return z;
}

void check_exact_inverse(int dim, Hypothesis h, bool prestressed) {
  const Mesh mesh =
      dim == 2 ? test::creep_test_mesh(2, 6, 4, 1, 4) : test::creep_test_mesh(3, 4, 3, 2, 5);
  ElasticityOperator op(mesh, steel(h, dim, prestressed), test::creep_test_boundaries(mesh));
  ContinuumCreepSystem system(op, CreepLaw{1e-3, 3e3, 2.5, 1.5, 1e9});
  system.set_linear_solver(Solver::Krylov);
  ASSERT_TRUE(system.has_preconditioner());
  const auto [y, yp, steps, scales] = test::random_continuum_creep_state(system, 7);
  const Real c_j = 250;
  system.preconditioner_setup(0.3, c_j, y, yp);
  Blocks b = dense_jacobian(system, c_j, y, yp);
  Eigen::MatrixXd modified = b.J;
  const Index ns = system.structural_size();
  modified.topLeftCorner(ns, ns) += b.B * b.D.partialPivLu().solve(b.E);
  const Eigen::VectorXd v = random_vector(system, 11);
  const Eigen::VectorXd z = apply_preconditioner(system, modified * v);
  const auto [eu, eq] = part_errors(z, v, ns);
  std::printf("dim %d, prestressed %d: P^-1 (J + [B D^-1 E 0; 0 0]) v - v: u %.2e, q %.2e\n", dim,
              prestressed, eu, eq);
  EXPECT_LT(eu, 1e-9);
  EXPECT_LT(eq, 1e-9);
}

TEST(ContinuumCreepPreconditioner, IsTheExactInverseWithTheDroppedSchurTermRestored) {
  check_exact_inverse(2, Hypothesis::PlaneStress, false);
  check_exact_inverse(2, Hypothesis::PlaneStrain, true);
  check_exact_inverse(3, Hypothesis::ThreeD, false);
  check_exact_inverse(3, Hypothesis::ThreeD, true);
}

TEST(ContinuumCreepPreconditioner, ItsErrorFallsAsOneOverCj) {
  const Mesh mesh = test::creep_test_mesh(2, 6, 4, 1, 4);
  ElasticityOperator op(mesh, steel(Hypothesis::PlaneStress, 2, false),
                        test::creep_test_boundaries(mesh));
  ContinuumCreepSystem system(op, CreepLaw{1e-3, 3e3, 2.5, 1.5, 1e9});
  system.set_linear_solver(Solver::Krylov);
  const auto [y, yp, steps, scales] = test::random_continuum_creep_state(system, 7);
  const Eigen::VectorXd v = random_vector(system, 11);
  std::vector<Real> errors;
  for (Real c_j : {1e3, 1e4, 1e5}) {
    system.preconditioner_setup(0.3, c_j, y, yp);
    const Blocks b = dense_jacobian(system, c_j, y, yp);
    const auto [eu, eq] =
        part_errors(apply_preconditioner(system, b.J * v), v, system.structural_size());
    errors.push_back(std::max(eu, eq));
    std::printf("c_j %.0e: |P^-1 J v - v| / |v| = %.3e\n", c_j, errors.back());
  }
  for (std::size_t k = 1; k < errors.size(); ++k) {
    const Real order = std::log10(errors[k - 1] / errors[k]);
    EXPECT_NEAR(order, 1.0, 0.1) << "c_j decade " << k;
  }
  EXPECT_GT(errors.front(), 1e-12);  // the dropped term is there to be measured
}

// The benchmark's strip (L/h = 60, Table 4.1 law, 500 h), plane stress, 81 x 4 cells.
CreepRunResult strip_run(Solver solver) {
  FixedFixedCreepProblem problem;
  problem.continuum_linear_solver = solver;
  const Real h = problem.thickness();
  const Real w_scale = problem.load * std::pow(problem.length, 4) / (32 * problem.E * h * h * h);
  IdaOptions options;
  options.rtol = 1e-6;
  options.atol = 1e-2 * options.rtol * w_scale;
  return run_continuum_creep(problem, 81, 4, options, 500 * 3600.0);
}

TEST(ContinuumCreepPreconditioner, KrylovRunGivesTheDirectRunsCreep) {
  const CreepRunResult direct = strip_run(Solver::Direct);
  const CreepRunResult r = strip_run(Solver::Krylov);
  const Real d_elastic = std::abs(r.w_elastic / direct.w_elastic - 1);
  const Real d_plastic = std::abs(r.w_plastic / direct.w_plastic - 1);
  const Real per_newton = static_cast<Real>(r.stats.linear_iters) / r.stats.newton_iters;
  std::printf(
      "krylov: w_el %.8e (direct %.8e, %.1e), w_p %.8e (direct %.8e, %.1e); steps %ld (direct "
      "%ld), Newton %ld, GMRES %ld (%.2f a Newton step), setups %ld (direct %ld)\n",
      r.w_elastic, direct.w_elastic, d_elastic, r.w_plastic, direct.w_plastic, d_plastic,
      r.stats.steps, direct.stats.steps, r.stats.newton_iters, r.stats.linear_iters, per_newton,
      r.stats.linear_setups, direct.stats.linear_setups);
  EXPECT_LT(d_elastic, 1e-10);
  // IDA's own tolerance (rtol 1e-6 on w, so ~1e-3 of the creep part 1e-3 w_el) allows more;
  // the two linear solvers agree far better.
  EXPECT_LT(d_plastic, 1e-5);
  EXPECT_LT(per_newton, 2.0);
}

}  // namespace

// BoomerAMG with the rigid-body rotations in its interpolation (AmgOptions::rigid_body_points)
// on a thin 3D strip (L/h = 60, clamped at one end, a symmetry plane at the other, loaded on
// top: the creep benchmark's half span), as GMRES's preconditioner for the operator's own
// stiffness: both hierarchies give the sparse LU's answer, and the one that can represent the
// strip's bending (rotations) needs far fewer iterations than the unknown-based one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "parallel/communicator.hpp"
#include "physics/creep/continuum_plate_comparison.hpp"
#include "solvers/boomer_amg.hpp"
#include "solvers/sparse_lu.hpp"
#include "solvers/split_preconditioned_gmres.hpp"

using namespace rfmems;

TEST(AmgRigidBodyModes, ThinStripConvergesInAFractionOfTheIterations) {
  static MpiSession mpi(nullptr, nullptr);  // hypre needs MPI (one rank)
  FixedFixedCreepProblem problem;           // L/h = 60
  problem.width = 0.01 * problem.length;
  problem.continuum_half_length = true;
  const ContinuumStrip strip = make_continuum_strip(problem, 60, 8, 3);
  const ContinuumStripStatics statics(strip);
  const Index n = statics.op.size();
  std::vector<Real> reference = statics.load;
  SparseLu(statics.op.stiffness_pattern(), statics.stiffness).solve_refined(reference);
  Real largest = 0;
  for (Real x : reference) largest = std::max(largest, std::abs(x));

  long iterations[2] = {0, 0};
  for (const bool rotations : {false, true}) {
    AmgOptions options;
    options.unknowns_per_cell = 3;
    if (rotations) {
      const std::span<const Vec3> centroids = strip.mesh.cell_centroids();
      options.rigid_body_points.assign(centroids.begin(), centroids.end());
    }
    BoomerAmg amg(statics.compact.stiffness_pattern(), options);
    amg.setup(statics.compact_stiffness);
    std::vector<Real> u(n, 0.0);
    SplitGmresOptions gmres;
    gmres.relative_tolerance = 1e-8;
    gmres.krylov_dimension = 100;
    gmres.max_restarts = 20;
    const SplitGmresResult r = split_preconditioned_gmres(
        statics.op.stiffness_pattern(), statics.stiffness,
        [&amg](std::span<Real> z) { amg.apply(z, z); }, statics.load, u, gmres);
    Real error = 0;
    for (Index i = 0; i < n; ++i) error = std::max(error, std::abs(u[i] - reference[i]));
    std::printf("%s: %ld GMRES iterations, |u - u_LU| / |u_LU| = %.1e, complexity %.2f\n",
                rotations ? "rotations" : "unknown-based", r.iterations, error / largest,
                amg.stats().operator_complexity);
    EXPECT_TRUE(r.converged);
    EXPECT_LT(error / largest, 1e-6);
    iterations[rotations] = r.iterations;
  }
  // Measured 596 against 105.
  EXPECT_LT(iterations[1], 0.3 * iterations[0]);
}

// Tests of COMET's entry for the rfmems-gas solver registry (comet/comet_kinetic_solver.hpp).
//
// Asserted: read_comet_options takes every documented key (and leaves none unused for the
// case's unknown-key check) and keeps the defaults when absent; bad values (unknown coupling,
// zero sweeps, a non-integer) raise InputError; solve_comet on a 6 x 6 cavity at Kn = 0.1
// (8^3 velocities) converges to ||r||/||r_0|| <= 1e-6 and reports the same result fields as
// the sequential solver's (iterations = cycles, ratio = final / initial, a history per cycle,
// the last entry equal to the ratio).
#include <gtest/gtest.h>

#include "comet_cases.hpp"
#include "core/error.hpp"
#include "physics/gas/comet/comet_kinetic_solver.hpp"

namespace rfmems {
namespace {

TEST(CometKineticSolver, ReadsEveryKey) {
  const CaseFile file = CaseFile::parse(
      "solver: {type: comet, coupling: velocity, multigrid: false, pre_sweeps: 2, post_sweeps: 3,\n"
      "         coarsest_sweeps: 7, symmetric: false, min_coarse_cells: 16,\n"
      "         cell_newton_iterations: 2, sequential_above_knudsen: 0.5, cycle: F,\n"
      "         f_cycle_below_knudsen: 0.03, coarse_symmetric: false}\n",
      "test.yaml");
  const CaseNode solver = file.root().child("solver");
  solver.get_string("type");
  const CometOptions o = read_comet_options(solver);
  EXPECT_EQ(o.coupling, CometCoupling::Velocity);
  EXPECT_FALSE(o.multigrid);
  EXPECT_EQ(o.pre_sweeps, 2);
  EXPECT_EQ(o.post_sweeps, 3);
  EXPECT_EQ(o.coarsest_sweeps, 7);
  EXPECT_FALSE(o.symmetric);
  EXPECT_EQ(o.min_coarse_cells, 16);
  EXPECT_EQ(o.cell_newton_iterations, 2);
  EXPECT_EQ(o.sequential_above_knudsen, 0.5);
  EXPECT_EQ(o.cycle_shape, CometCycle::F);
  EXPECT_EQ(o.f_cycle_below_knudsen, 0.03);
  EXPECT_FALSE(o.coarse_symmetric);
  EXPECT_NO_THROW(file.check_all_used());

  const CaseFile empty = CaseFile::parse("solver: {type: comet}\n", "test.yaml");
  const CometOptions d = read_comet_options(empty.root().child("solver"));
  EXPECT_EQ(d.coupling, CometCoupling::Conserved);
  EXPECT_TRUE(d.multigrid);
  EXPECT_EQ(d.pre_sweeps, 1);
  EXPECT_EQ(d.post_sweeps, 1);
  EXPECT_TRUE(d.symmetric);
  EXPECT_EQ(d.sequential_above_knudsen, 0.2);
  EXPECT_EQ(d.cycle_shape, CometCycle::Auto);  // the cycle by regime (comet_solver.hpp)
  EXPECT_EQ(d.f_cycle_below_knudsen, 0.02);
  EXPECT_TRUE(d.coarse_symmetric);
}

TEST(CometKineticSolver, RejectsBadValues) {
  for (const char* text :
       {"solver: {coupling: full}\n", "solver: {pre_sweeps: 0, post_sweeps: 0}\n",
        "solver: {coarsest_sweeps: two}\n", "solver: {min_coarse_cells: 0}\n"}) {
    const CaseFile file = CaseFile::parse(text, "test.yaml");
    EXPECT_THROW(read_comet_options(file.root().child("solver")), InputError) << text;
  }
}

TEST(CometKineticSolver, SolvesAndReports) {
  auto p = comet_test::make_problem(comet_test::Case::Cavity, 0.1, 6, 8);
  int calls = 0;
  const KineticSolveResult r =
      solve_comet(*p->op, p->f, CometOptions{}, 1e-6, 100, [&](int, Real) { return ++calls > 0; });
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.residual_ratio, 1e-6);
  EXPECT_GT(r.iterations, 0);
  EXPECT_EQ(static_cast<int>(r.history.size()), r.iterations);
  EXPECT_EQ(r.history.back(), r.residual_ratio);
  EXPECT_NEAR(r.final_residual, r.residual_ratio * r.initial_residual, 1e-15 * r.initial_residual);
  EXPECT_EQ(calls, r.iterations - 1);  // not called after the converged cycle
}

}  // namespace
}  // namespace rfmems

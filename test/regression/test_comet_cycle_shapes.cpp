// COMET's cycle shapes (CometOptions::cycle_shape: V, W, F) on the heat-transfer square
// (argon ESBGK, 20 x 20 cells, 8^3 velocities, 6 levels), the goal "cycle count nearly flat
// in Kn" (docs/kinetic.md, "COMET cycle shapes").
//
// Asserted:
//  - W and F converge (||r||/||r_0|| <= 1e-6) at Kn = 0.01 to the V-cycle's steady state: the
//    same fixed point of the same FAS hierarchy, so the temperature fields agree to 1e-4 of
//    the wall temperature difference (both are within the tolerance of it);
//  - the F-cycle's count at Kn = 0.01 is within 2x its count at Kn = 1 (the goal) and
//    below the V-cycle's count at Kn = 0.01;
//  - the default cycle (Auto, by regime): F-cycles with one-pass coarse sweeps below a domain
//    Kn of 0.02, V-cycles (symmetric sweeps) above; at Kn = 0.01 it reaches the V-cycle's
//    steady state (1e-4) in fewer cycles and fewer fine-sweep equivalents (work) than V, and
//    within 2x the cycles it takes at Kn = 1 (the goal, docs/kinetic.md, "COMET cycle by
//    regime");
//  - mass held to round-off (1e-12 relative), no damped step;
//  - a cycle name other than V, W, F is an InputError.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../unit/comet/comet_cases.hpp"
#include "core/error.hpp"
#include "physics/gas/comet/comet_solver.hpp"

namespace rfmems {
namespace {

using namespace comet_test;

struct CycleRun {
  CometResult result;
  std::vector<Real> temperature;  // per cell
};

CycleRun solve_case(Real kn, CometCycle shape) {
  auto p = make_problem(Case::HeatTransfer, kn, 20, 8);
  CometOptions o;
  o.cycle_shape = shape;
  o.sequential_above_knudsen = 0;  // COMET at every Kn
  o.max_cycles = 200;
  CometSolver solver(*p->op, o);
  const Real mass0 = p->op->total_mass(p->f);
  CycleRun r;
  r.result = solver.solve(p->f);
  EXPECT_NEAR(p->op->total_mass(p->f), mass0, 1e-12 * mass0);
  EXPECT_EQ(r.result.damped_steps, 0);
  const Index n = p->op->n_ordinates();
  for (Index c = 0; c < p->op->n_owned_cells(); ++c)
    r.temperature.push_back(
        moments(std::span<const Real>(p->f).subspan(c * n, n), p->op->grid(), p->op->gas()).T);
  std::printf(
      "Kn %.2g, cycle %s (ran %s%s): %d cycles, ratio %.1e, %d levels, %.1f fine-sweep "
      "equivalents, %.2f s\n",
      kn, comet_cycle_name(shape), comet_cycle_name(r.result.cycle_shape),
      r.result.coarse_symmetric ? "" : ", one-pass coarse sweeps", r.result.cycles,
      r.result.residual_ratio, r.result.levels, r.result.fine_sweep_equivalents,
      r.result.wall_seconds);
  return r;
}

Real max_temperature_difference(const CycleRun& a, const CycleRun& b) {
  Real d = 0;
  for (std::size_t c = 0; c < a.temperature.size(); ++c)
    d = std::max(d, std::abs(a.temperature[c] - b.temperature[c]));
  return d / (kTHot - kT0);
}

TEST(CometCycleShapes, WAndFReachTheVCycleSteadyState) {
  const CycleRun v = solve_case(0.01, CometCycle::V);
  const CycleRun w = solve_case(0.01, CometCycle::W);
  const CycleRun f = solve_case(0.01, CometCycle::F);
  ASSERT_TRUE(v.result.converged);
  ASSERT_TRUE(w.result.converged);
  ASSERT_TRUE(f.result.converged);
  EXPECT_LT(max_temperature_difference(v, w), 1e-4);
  EXPECT_LT(max_temperature_difference(v, f), 1e-4);
  EXPECT_LT(w.result.cycles, v.result.cycles);
}

TEST(CometCycleShapes, FCycleCountNearlyFlatInKnudsen) {
  const CycleRun dense = solve_case(0.01, CometCycle::F);
  const CycleRun rare = solve_case(1.0, CometCycle::F);
  const CycleRun v_dense = solve_case(0.01, CometCycle::V);
  ASSERT_TRUE(dense.result.converged);
  ASSERT_TRUE(rare.result.converged);
  ASSERT_TRUE(v_dense.result.converged);
  EXPECT_LE(dense.result.cycles, 2 * rare.result.cycles);
  EXPECT_LT(dense.result.cycles, v_dense.result.cycles);
}

TEST(CometCycleShapes, DefaultCycleByRegime) {
  EXPECT_EQ(CometOptions{}.cycle_shape, CometCycle::Auto);
  const CycleRun dense = solve_case(0.01, CometCycle::Auto);
  const CycleRun rare = solve_case(1.0, CometCycle::Auto);
  const CycleRun v_dense = solve_case(0.01, CometCycle::V);
  ASSERT_TRUE(dense.result.converged);
  ASSERT_TRUE(rare.result.converged);
  ASSERT_TRUE(v_dense.result.converged);
  EXPECT_EQ(dense.result.cycle_shape, CometCycle::F);
  EXPECT_FALSE(dense.result.coarse_symmetric);
  EXPECT_EQ(rare.result.cycle_shape, CometCycle::V);
  EXPECT_TRUE(rare.result.coarse_symmetric);
  EXPECT_LT(max_temperature_difference(v_dense, dense), 1e-4);
  EXPECT_LE(dense.result.cycles, 2 * rare.result.cycles);
  EXPECT_LT(dense.result.cycles, v_dense.result.cycles);
  EXPECT_LT(dense.result.fine_sweep_equivalents, v_dense.result.fine_sweep_equivalents);
}

TEST(CometCycleShapes, UnknownCycleNameIsAnInputError) {
  EXPECT_EQ(comet_cycle_from_name("auto"), CometCycle::Auto);
  EXPECT_EQ(comet_cycle_from_name("F"), CometCycle::F);
  EXPECT_THROW(comet_cycle_from_name("X"), InputError);
}

}  // namespace
}  // namespace rfmems

// Coupling schemes on the same scene: the plate switch of cases/switch_plate (plate +
// parallel-plate + Reynolds film at 1 atm) under a 180 V step. The centre deflection at 5 us
// (before touch-down near 6.2 us) from the monolithic system (one IDA system, exact coupled
// Jacobian; reference at rtol 1e-6) against the partitioned schemes, the film split from the
// plate in the field-coupled structure's loop (coupling/field_coupled_structure.hpp), at fixed
// steps h (so that the splitting error is seen apart from the step control):
//  - strongly coupled (Aitken, the film inside every iterate): converges to the monolithic
//    step, its distance from the monolithic run at the same h only the film's own integration;
//  - staggered (the film's force held over the next step): first order in h.
// Asserts the orders (from h and h/2) and the strongly coupled distance; prints the cost
// (residual evaluations) of each, the figures of docs/coupling.md.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "coupling/coupling_manager.hpp"
#include "coupling/switch_scene.hpp"
#include "coupling/switch_system.hpp"
#include "io/case_file.hpp"

using namespace rfmems;

namespace {

const char* kCase =
    "mesh: {type: rectangle, size: [400 um, 40 um], cells: [40, 4]}\n"
    "material: {E: 200 GPa, nu: 0.31, density: 7854}\n"
    "model: {structure: plate, thickness: 4 um}\n"
    "boundaries: {left: {type: clamped}, right: {type: clamped}, top: {type: free}, "
    "bottom: {type: free}}\n"
    "actuation: {gap: 3.75 um, control: [205 um, 5 um]}\n"
    "gas: {model: reynolds, pressure: 1 atm}\n"
    "pull_in: {mode: transient, transient: {voltage: 180 V, end_time: 1 us}}\n";

struct Result {
  double value, seconds;  // value: the deflection of the control point at 5 us
  long residual_evals, iterations;
};

DynamicOptions options(double rtol, double step = 0) {
  DynamicOptions o;
  o.end_time = 5e-6;
  o.output_interval = 5e-6;  // one sample, at the end
  o.contact_gap = 0.02 * 3.75e-6;
  o.stop_at_turning = false;
  o.ida.rtol = rtol;
  o.ida.atol = rtol * 1e-4 * 3.75e-6;
  o.ida.max_order = 2;
  o.ida.max_steps = 10000000;
  o.ida.fixed_step = step;
  o.ida.fixed_step_min = 1e-4 * step;
  o.coupling.tolerance = 1e-8;
  o.coupling.max_iterations = 50;
  return o;
}

Result run(CouplingScheme scheme, double rtol, double step = 0) {
  const CaseFile cf = CaseFile::parse(kCase, "c.yaml");
  SwitchScene scene = build_switch_scene(cf.root(), "");
  std::unique_ptr<CouplingManager> manager = make_coupling_manager(scene);
  DynamicOptions o = options(rtol, step);
  o.coupling.scheme = scheme;
  const auto t0 = std::chrono::steady_clock::now();
  const DynamicRun r = manager->run(VoltageWaveform{}, 180.0, o);
  EXPECT_FALSE(r.pulled_in);
  const Json c = manager->counters();
  return {r.history.back().control,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
          r.stats.residual_evals, c.value("coupling_iterations", 0L)};
}

}  // namespace

TEST(CouplingSchemes, PartitionedConvergesToMonolithic) {
  const Result ref = run(CouplingScheme::Monolithic, 1e-6);
  std::printf("monolithic rtol 1e-6: w(5 us) = %.6f um (%ld residuals, %.2f s)\n", ref.value * 1e6,
              ref.residual_evals, ref.seconds);
  double split_prev = 0;
  for (const double h : {20e-9, 10e-9, 5e-9}) {
    const Result mono = run(CouplingScheme::Monolithic, 1e-5, h);
    const Result staggered = run(CouplingScheme::Staggered, 1e-5, h);
    const Result strong = run(CouplingScheme::StronglyCoupled, 1e-5, h);
    const double split = std::abs(staggered.value / mono.value - 1);
    const double strong_split = std::abs(strong.value / mono.value - 1);
    std::printf(
        "h = %.0f ns: monolithic error %.2e (%ld residuals, %.2f s); staggered %.2e from it "
        "(%ld residuals, %.2f s); strongly coupled %.2e from it (%ld iterations, %ld residuals, "
        "%.2f s)\n",
        h * 1e9, std::abs(mono.value / ref.value - 1), mono.residual_evals, mono.seconds, split,
        staggered.residual_evals, staggered.seconds, strong_split, strong.iterations,
        strong.residual_evals, strong.seconds);
    EXPECT_LT(strong_split, 1e-4);
    EXPECT_LT(strong_split, 0.1 * split);
    if (split_prev > 0) {
      const double order = std::log(split_prev / split) / std::log(2.0);
      std::printf("  staggered: observed order %.2f\n", order);
      EXPECT_GT(order, 0.7);
      EXPECT_LT(order, 1.5);
    }
    split_prev = split;
  }
}

// Coupling schemes on the same scene: the plate switch of cases/switch_plate (plate +
// parallel-plate + Reynolds film at 1 atm) under a 180 V step. The centre deflection at 5 us
// (before touch-down at 6.2 us: near contact the partitioned schemes fail, the film seeing a gap
// the structure has already overshot) from the monolithic system (one IDA system, exact
// coupled Jacobian; reference at rtol 1e-6) against the partitioned schemes
// (coupling/partitioned_switch.hpp) at several macro steps H:
//  - strongly coupled (Aitken): converges to the monolithic answer, error O(H^2);
//  - staggered (one pass): first order in H (the lagged interface).
// Asserts the orders (from H and H/2) and that the strongly coupled error at the finest H is
// within 0.2 %; prints the cost (residual evaluations) of each, the figures of
// docs/coupling.md ("Coupling schemes on the same scene").
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "coupling/partitioned_switch.hpp"
#include "coupling/squeeze_film_switch_system.hpp"
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

DynamicOptions options(double rtol) {
  DynamicOptions o;
  o.end_time = 5e-6;
  o.output_interval = 5e-6;  // one sample, at the end
  o.contact_gap = 0.02 * 3.75e-6;
  o.stop_at_turning = false;
  o.ida.rtol = rtol;
  o.ida.atol = rtol * 1e-4 * 3.75e-6;
  o.ida.max_order = 2;
  o.ida.max_steps = 10000000;
  return o;
}

Result monolithic(double rtol) {
  const CaseFile cf = CaseFile::parse(kCase, "c.yaml");
  SwitchScene scene = build_switch_scene(cf.root(), "");
  auto system = make_switch_system(scene);
  const auto t0 = std::chrono::steady_clock::now();
  const DynamicRun run = run_dynamic(
      *system, scene.control, [](Real) { return 180.0; }, options(rtol));
  EXPECT_FALSE(run.pulled_in);
  return {run.history.back().control,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
          run.stats.residual_evals, 0};
}

Result partitioned(CouplingScheme scheme, double H) {
  const CaseFile cf = CaseFile::parse(kCase, "c.yaml");
  SwitchScene scene = build_switch_scene(cf.root(), "");
  const std::vector<Index> w_dof = film_unknowns(scene);
  DynamicOptions o = options(1e-5);
  o.coupling.scheme = scheme;
  o.coupling.macro_step = H;
  o.coupling.tolerance = 1e-8;
  o.coupling.max_iterations = 50;
  const auto t0 = std::chrono::steady_clock::now();
  const PartitionedRun r = run_partitioned(
      *scene.actuation, scene.structure->quasi_static_components(), *scene.film, w_dof,
      scene.control, [](Real) { return 180.0; }, o);
  EXPECT_FALSE(r.run.pulled_in);
  return {r.run.history.back().control,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
          r.run.stats.residual_evals, r.coupling_iterations};
}

}  // namespace

TEST(CouplingSchemes, PartitionedConvergesToMonolithic) {
  const Result ref = monolithic(1e-6);
  const Result mono = monolithic(1e-4);
  std::printf(
      "monolithic rtol 1e-6: w(5 us) = %.6f um (%ld residuals, %.2f s); rtol 1e-4: error "
      "%.2e, %ld residuals, %.2f s\n",
      ref.value * 1e6, ref.residual_evals, ref.seconds, std::abs(mono.value / ref.value - 1),
      mono.residual_evals, mono.seconds);
  double error_prev[2] = {0, 0};
  for (const double H : {0.2e-6, 0.1e-6}) {
    int k = 0;
    for (const CouplingScheme scheme :
         {CouplingScheme::Staggered, CouplingScheme::StronglyCoupled}) {
      const Result r = partitioned(scheme, H);
      const double error = std::abs(r.value / ref.value - 1);
      std::printf(
          "%-16s H = %.2f us: w(5 us) = %.6f um, error %.2e, %ld coupling passes, %ld "
          "residuals, %.2f s\n",
          scheme == CouplingScheme::Staggered ? "staggered" : "strongly coupled", H * 1e6,
          r.value * 1e6, error, r.iterations, r.residual_evals, r.seconds);
      if (error_prev[k] > 0)
        std::printf("  observed order %.2f\n", std::log(error_prev[k] / error) / std::log(2.0));
      if (H < 0.15e-6 && scheme == CouplingScheme::StronglyCoupled) {
        EXPECT_LT(error, 2e-3);
      }
      if (H < 0.15e-6 && scheme == CouplingScheme::Staggered) {
        EXPECT_GT(std::log(error_prev[k] / error) / std::log(2.0), 0.7);
      }
      error_prev[k++] = error;
    }
  }
}

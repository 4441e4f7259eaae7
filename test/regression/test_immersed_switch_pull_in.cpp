// Dynamic pull-in of the immersed-boundary cantilever switch by bisection on a coarse
// scene, against the distributed closed form (the full scene's figures: docs/immersed_switch.md,
// "Coupled stepping, dynamic pull-in, gas models"). Scene helper as in
// test/unit/coupling/test_immersed_switch.cpp.
//
// Backgrounds are 151 x 51 / 101 x 31, where the figures below were measured. They were chosen
// because on 150 x 50 / 100 x 30 the beam's top and tip lie on grid lines and slivers gave a
// spurious force; lib/ibm's marking now snaps them (test_immersed_switch_slivers: 150 x 50
// converges at 50 V in 7 iterates), so the thesis sizes would work too. docs/immersed_switch.md.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "../support/cantilever_switch_scene.hpp"
#include "ibm/immersed_boundary_field.hpp"
#include "mesh/structured_mesh.hpp"
#include "physics/electrostatics/permittivity.hpp"

namespace rfmems {
namespace {
using namespace rfmems::test;

// Osterberg & Senturia (1997): the distributed cantilever's quasi-static pull-in, no fringing,
// V = sqrt(0.28 E h^3 g^3 / (eps L^4)) (a fit to 2D FEM within ~1 %): 132.5 V here. The
// lumped closed form (k = 2 E b h^3 / (3 L^3) at the tip, A = b L at the tip gap)
// gives 111 V: it puts the whole area at the tip's gap, so it pulls in too early.
Real distributed_pull_in() {
  return std::sqrt(0.28 * 200e9 * std::pow(kThickness, 3) * std::pow(kGap, 3) /
                   (kVacuumPermittivity * std::pow(kLength, 4)));
}

// Dynamic pull-in by bisection on the coarse scene (46 x 4 beam, 101 x 31 background), within
// a bracket from the distributed closed form: 0.91 x 132.5 V = 120.6 V (the undamped
// dynamic/static ratio of a parallel-plate actuator, 0.92 lumped, 0.91 thesis); the coarse
// beam is stiffer by a few per cent, so +-8 %. Measured: 124.5 V with [112, 132] V to 2.5 V (5
// runs, 47-129 s at load 7-8); here [116, 128] V to 3 V, 4 runs.
TEST(ImmersedBoundaryField, CoarseBisectionWithinTheClosedFormBracket) {
  Cantilever c(46, 4, 101, 31);
  const DynamicOptions o = run_options(4e-6, 5e-5);
  const Real expected = 0.91 * distributed_pull_in();
  const DynamicPullIn pi = find_dynamic_pull_in(
      [&](Real v) { return c.coupled->run(v, o, nullptr); }, 116, 128, 3.0, o.end_time);
  EXPECT_NEAR(pi.voltage / expected, 1.0, 0.08);
  EXPECT_LE(pi.voltage - pi.lower, 3.0);
  EXPECT_GT(pi.pull_in_time, 0.5 * c.scene->first_bending_period());
  RecordProperty("dynamic_pull_in_V", std::to_string(pi.voltage));
  RecordProperty("pull_in_time_s", std::to_string(pi.pull_in_time));
}

}  // namespace
}  // namespace rfmems

// The immersed electrostatics under mpirun -np P gives the serial KLU answer:
// the background partitioned once, each rank assembling its owned FLUID rows (the IB fits'
// columns a few rings away as ghosts), GMRES with restricted additive Schwarz KLU on the
// overlap to ||b - A phi|| <= 1e-13 ||b||, the potential summed to every rank and the IB-face
// charges computed from it on every rank (lib/ibm/immersed_electrostatics.hpp,
// lib/solvers/distributed_linear_solve.hpp).
//
// Every rank also solves serially (KLU) and compares. Asserted:
//  - a cantilever-like beam on a 101 x 41 background bending down in 40 steps of 2-20 nm
//    (re-markings included, the kept-LU test's motion): per step the potential equals the
//    serial one to 1e-10 of V (measured 2.9e-12 on 2 ranks, 4.7e-12 on 3), every IB-face charge to
//    1e-10 of the largest, the total force on the beam to 1e-10 relative; the outputs are the same
//    on every rank (the body charge's spread over the ranks is 0); on more than one rank GMRES ran
//    (iterations > 0), new patterns were analysed on re-markings and the kept ones refactored;
//  - the coupled coarse switch (test/support/cantilever_switch_scene.hpp: 45 x 3 beam,
//    76 x 26 background, 80 V step, 0.4 us, no gas, one re-marking on the way): with the
//    distributed field the IDA steps are the serial run's (times to 1e-9 of the end time)
//    and the tip deflection of every sample equals the serial one to 1e-8 of the final
//    deflection (measured 4.6e-13 on 2 ranks).
// On one rank the distributed path is not taken (the serial code): identical by construction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../support/bending_beam_surface.hpp"
#include "../support/cantilever_switch_scene.hpp"
#include "ibm/cell_marking.hpp"
#include "ibm/ib_interpolation.hpp"
#include "ibm/immersed_electrostatics.hpp"
#include "mesh/structured_mesh.hpp"
#include "parallel/communicator.hpp"

namespace rfmems {
namespace {

constexpr Real um = 1e-6;

std::map<std::string, PotentialBoundary> grounded_bottom() {
  return {{"bottom", PotentialBoundary::potential(0.0)},
          {"top", PotentialBoundary::zero_flux()},
          {"left", PotentialBoundary::zero_flux()},
          {"right", PotentialBoundary::zero_flux()}};
}

Vec3 total(const std::vector<Vec3>& forces) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& f : forces) sum += f;
  return sum;
}

TEST(ImmersedElectrostaticsDistributed, BendingBeamGivesTheSerialPotentialChargesAndForce) {
  const Communicator world = Communicator::world();
  const Real V = 100, L = 30 * um;
  BoxSpec spec;
  spec.upper = Vec3(50 * um, 8 * um, 0);
  spec.n[0] = 101;
  spec.n[1] = 41;
  const Mesh mesh = make_structured_mesh(spec);
  CellMarker marker(mesh);
  const auto rest = ImmersedSurface::rectangle({-0.5 * um, 1.5 * um, 0}, {L, 3.0 * um, 0}, 60, 4);
  ImmersedElectrostatics serial(mesh, grounded_bottom());
  ImmersedElectrostatics parallel(mesh, grounded_bottom());
  parallel.distribute(world);
  Real worst_potential = 0, worst_charge = 0, worst_force = 0, spread = 0;
  for (int step = 0; step < 40; ++step) {
    const ImmersedSurface beam = test::bent_down(rest, test::bending_deflection(step), L);
    const CellMarking m = marker.mark(beam);
    const IbInterpolation ib(mesh, m, beam);
    serial.solve(m, ib, V);
    parallel.solve(m, ib, V);
    for (Index c = 0; c < mesh.n_cells(); ++c) {
      const Real a = parallel.potential()[c], b = serial.potential()[c];
      ASSERT_EQ(std::isnan(a), std::isnan(b));
      if (!std::isnan(a)) worst_potential = std::max(worst_potential, std::abs(a - b) / V);
    }
    Real q_scale = 0;
    for (Real q : serial.ib_face_charge()) q_scale = std::max(q_scale, std::abs(q));
    ASSERT_EQ(parallel.ib_face_charge().size(), serial.ib_face_charge().size());
    for (std::size_t k = 0; k < serial.ib_face_charge().size(); ++k)
      worst_charge =
          std::max(worst_charge,
                   std::abs(parallel.ib_face_charge()[k] - serial.ib_face_charge()[k]) / q_scale);
    const Vec3 f1 = total(serial.ib_face_forces()), fP = total(parallel.ib_face_forces());
    worst_force = std::max(worst_force, (fP - f1).norm() / f1.norm());
    const Real q = parallel.body_charge();
    spread = std::max(spread, world.max(q) - world.min(q));
  }
  if (world.is_root())
    std::printf(
        "%d ranks: %ld analyses, %ld refactorisations, %ld GMRES iterations (last %ld, "
        "relative residual %.1e); max |dphi| / V = %.2e, max |dq| / max q = %.2e, force %.2e\n",
        world.size(), parallel.analyses(), parallel.refactorizations(),
        parallel.krylov_iterations(), parallel.last_krylov().iterations,
        parallel.last_krylov().relative_residual, worst_potential, worst_charge, worst_force);
  EXPECT_LT(worst_potential, 1e-10);
  EXPECT_LT(worst_charge, 1e-10);
  EXPECT_LT(worst_force, 1e-10);
  EXPECT_EQ(spread, 0.0);
  if (!world.is_serial()) {
    EXPECT_TRUE(parallel.distributed());
    EXPECT_GT(parallel.krylov_iterations(), 0);
    EXPECT_GT(parallel.analyses(), 1);          // re-markings: new patterns
    EXPECT_GT(parallel.refactorizations(), 0);  // unchanged ones: the kept analysis
  }
}

TEST(ImmersedElectrostaticsDistributed, CoupledCoarseSwitchGivesTheSerialTipDeflection) {
  using namespace rfmems::test;
  const Communicator world = Communicator::world();
  Cantilever c(45, 3, 76, 26);
  DynamicOptions o = run_options(4e-7, 1e-2);
  o.output_interval = o.end_time / 40;  // the samples compared
  const DynamicRun r1 = c.coupled->run(80.0, o, nullptr);
  c.scene->distribute_electrostatics(world);
  c.scene->reset_times();
  const DynamicRun rP = c.coupled->run(80.0, o, nullptr);
  ASSERT_GT(r1.history.size(), 2u);
  ASSERT_EQ(r1.history.size(), rP.history.size());
  const Real scale = std::abs(r1.history.back().control);
  Real d_tip = 0;
  for (std::size_t i = 0; i < r1.history.size(); ++i) {
    EXPECT_NEAR(r1.history[i].t, rP.history[i].t, 1e-9 * o.end_time);
    d_tip = std::max(d_tip, std::abs(r1.history[i].control - rP.history[i].control));
  }
  if (world.is_root())
    std::printf(
        "%d ranks: %zu samples, %ld loads, %ld analyses, %ld GMRES iterations; tip %.6e m, max "
        "difference %.2e relative\n",
        world.size(), rP.history.size(), c.scene->times().load_evaluations,
        c.scene->times().electrostatic_analyses, c.scene->times().electrostatic_krylov_iterations,
        r1.history.back().control, d_tip / scale);
  EXPECT_LT(r1.history.back().control, 0);
  EXPECT_LE(d_tip, 1e-8 * scale);
  EXPECT_GT(c.scene->times().electrostatic_analyses, 1);  // a re-marking on the way
  if (!world.is_serial()) {
    EXPECT_GT(c.scene->times().electrostatic_krylov_iterations, 0);
  }
}

}  // namespace
}  // namespace rfmems

// The immersed ESBGK gas under mpirun -np P gives the serial answer: the
// background partitioned once, every rank marking and fitting from the same global data, the
// FLUID cells of each rank's part plus the transport ghosts and the IB band, ghost exchanges
// after every sweep (block Jacobi between parts), global norms, masses and IB-face forces
// (lib/ibm/fluid_graph_part.hpp, local_ib_face_values.hpp, immersed_kinetic_gas.hpp).
//
// Every rank also runs the same problem serially and compares (both to the same step
// tolerance). Asserted:
//  - the closed box of test_immersed_kinetic_gas (24 x 24, 6^3 velocities, argon at Kn 0.1,
//    a square body moving along x at 40 m/s, 8 steps, 3 re-markings): per step the
//    segment forces equal the serial ones to 1e-8 of the largest segment force (step
//    residual 1e-12 both), the drag on the body to 1e-8 relative, the FLUID mass change of
//    every gas step <= 1e-10 and the domain's mass M conserved to 1e-10 per step, re-markings
//    included; the re-markings gain and lose the serial cells; after the last step the
//    gathered distribution equals the serial one to 1e-8 of its largest value;
//  - the coupled coarse switch (test/support/cantilever_switch_scene.hpp: 45 x 3 beam,
//    76 x 26 background, 6^3 velocities, air at 1.36e4 Pa, 80 V step, 12 ns, gas step
//    residual 1e-8): the same IDA steps (times to 1e-9 of the end time), and the tip deflection of
//    every sample equal to the serial one to 1e-6 relative (of the final deflection); the net gas
//    force to 1e-7 of p0 times the beam's perimeter (the step tolerance is relative to the whole
//    distribution, i.e. to the ambient pressure, while the net force is ~1e-4 of p0 times the
//    perimeter here: measured 2.4e-9 N/m of 1.29 N/m on 2 ranks, 1.5e-5 of the net force itself).
//  - the same coupled switch with the gas inside the strong iteration (coupling.strong_gas:
//    each iterate restores the gas's checkpoint, on every rank together, and redoes its step):
//    the serial IDA steps, coupling iterations and gas steps, every step converged, the tip
//    to 1e-6 relative and the gas force to 1e-7 of p0 times the perimeter, as above;
//  - a band started at 1 ring is widened until it covers every IB stencil, with the serial
//    segment forces (1e-8);
//  - the closed box with second-order transport (the slopes of ghost cells from their owners,
//    the limiter's length over every rank, the IB faces' reconstructed leaving values): the
//    same figures to the same bounds;
// On one rank the distributed path is not taken (the serial code): identical by construction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../support/cantilever_switch_scene.hpp"
#include "ibm/immersed_esbgk_gas.hpp"
#include "ibm/immersed_kinetic_gas.hpp"
#include "mesh/structured_mesh.hpp"
#include "parallel/communicator.hpp"

namespace rfmems {
namespace {

constexpr Real T0 = 273.15;

std::unique_ptr<ImmersedKineticGas> closed_box(const Mesh& mesh, const KineticGas& gas,
                                               const Communicator& comm, int band_rings = 0,
                                               TransportOrder order = TransportOrder::FirstOrder) {
  const FaceGraph g = face_graph_of(mesh);
  std::vector<KineticBoundary> bcs(g.patch_names.size(), KineticBoundary::diffuse_wall(T0));
  ImmersedGasOptions o;
  o.ib.wall_temperature = T0;
  o.comm = comm;
  o.band_rings = band_rings;
  o.transport.order = order;
  return std::make_unique<ImmersedKineticGas>(
      mesh, bcs, VelocityGrid::uniform(6, 6, 6, 3.5 * gas.thermal_speed(T0)), gas, o);
}

Real max_norm(const std::vector<Vec3>& v) {
  Real m = 0;
  for (const Vec3& x : v) m = std::max(m, x.norm());
  return m;
}

class ClosedBoxDistributed : public ::testing::TestWithParam<TransportOrder> {};

TEST_P(ClosedBoxDistributed, MovingBodyGivesTheSerialForcesAndConservesMass) {
  const Communicator world = Communicator::world();
  BoxSpec spec;
  spec.n[0] = spec.n[1] = 24;
  const Mesh mesh = make_structured_mesh(spec);
  const KineticGas argon = KineticGas::argon();
  const Real rho = argon.density_for_knudsen(0.1, T0, 1.0);
  auto serial = closed_box(mesh, argon, Communicator::serial(), 0, GetParam());
  auto parallel = closed_box(mesh, argon, world, 0, GetParam());

  const Real U = 40, dt = 2e-4;
  ImmersedSurface body = ImmersedSurface::rectangle({0.31, 0.37, 0}, {0.53, 0.61, 0}, 3, 3);
  const std::vector<Vec3> velocity(body.n_segments(), Vec3(U, 0, 0));
  for (ImmersedKineticGas* gas : {serial.get(), parallel.get()}) {
    gas->set_body(body, velocity);
    gas->initialize({rho, Vec3::Zero(), T0});
  }
  int remarks = 0, sweeps_serial = 0, sweeps_parallel = 0;
  Real worst_force = 0, worst_drag = 0, worst_step = 0, worst_m = 0;
  for (int step = 0; step < 8; ++step) {
    body = body.translated(Vec3(U * dt, 0, 0));
    const Real before = parallel->conserved_mass();
    serial->set_body(body, velocity);
    parallel->set_body(body, velocity);
    const RemarkReport& rs = serial->last_remark();
    const RemarkReport& rp = parallel->last_remark();
    ASSERT_EQ(rs.reclassified, rp.reclassified);
    if (rp.reclassified) {
      ++remarks;
      EXPECT_EQ(rp.cells_gained, rs.cells_gained);
      EXPECT_EQ(rp.cells_lost, rs.cells_lost);
      worst_m = std::max(worst_m, std::abs(parallel->conserved_mass() / before - 1));
    }
    const GasStepReport s = serial->advance(dt);
    const GasStepReport p = parallel->advance(dt);
    EXPECT_TRUE(s.converged && p.converged);
    sweeps_serial += s.sweeps;
    sweeps_parallel += p.sweeps;
    worst_step = std::max(worst_step, std::abs(p.mass_after / p.mass_before - 1));
    worst_m = std::max(worst_m, std::abs(parallel->conserved_mass() / before - 1));
    const std::vector<Vec3> fs = serial->segment_forces(), fp = parallel->segment_forces();
    ASSERT_EQ(fs.size(), fp.size());
    Vec3 drag_s = Vec3::Zero(), drag_p = Vec3::Zero();
    Real diff = 0;
    for (std::size_t k = 0; k < fs.size(); ++k) {
      diff = std::max(diff, (fs[k] - fp[k]).norm());
      drag_s += fs[k];
      drag_p += fp[k];
    }
    worst_force = std::max(worst_force, diff / max_norm(fs));
    worst_drag = std::max(worst_drag, std::abs(drag_p.x() / drag_s.x() - 1));
  }
  const std::vector<Real> f1 = serial->global_distribution(), fP = parallel->global_distribution();
  ASSERT_EQ(f1.size(), fP.size());
  Real df = 0, fmax = 0;
  for (std::size_t i = 0; i < f1.size(); ++i) {
    df = std::max(df, std::abs(f1[i] - fP[i]));
    fmax = std::max(fmax, std::abs(f1[i]));
  }
  const GasPartitionReport& part = parallel->partition();
  if (world.is_root())
    std::printf(
        "%s, %d ranks (edge cut %lld, imbalance %.3f, band %d rings; rank 0: %lld owned, %lld "
        "ghost cells): %d re-markings; segment forces to %.2e, drag to %.2e, fields to %.2e; "
        "mass per step %.2e, M %.2e; sweeps %d -> %d\n",
        transport_order_name(GetParam()), world.size(), static_cast<long long>(part.edge_cut),
        part.imbalance, part.band_rings, static_cast<long long>(part.owned_cells),
        static_cast<long long>(part.ghost_cells), remarks, worst_force, worst_drag, df / fmax,
        worst_step, worst_m, sweeps_serial, sweeps_parallel);
  EXPECT_GE(remarks, 2);
  EXPECT_LE(worst_force, 1e-8);
  EXPECT_LE(worst_drag, 1e-8);
  EXPECT_LE(df, 1e-8 * fmax);
  EXPECT_LE(worst_step, 1e-10);
  EXPECT_LE(worst_m, 1e-10);
}

INSTANTIATE_TEST_SUITE_P(ImmersedGasDistributed, ClosedBoxDistributed,
                         ::testing::Values(TransportOrder::FirstOrder, TransportOrder::SecondOrder),
                         [](const auto& info) {
                           return std::string(transport_order_name(info.param));
                         });

// A band too thin for the fits (1 ring; the surface stencils reach 4 rings from their seeds)
// is widened ring by ring, on every rank together, until every fit reads only band cells;
// the answer is the serial one (3 steps of the closed box, one re-marking at least).
TEST(ImmersedGasDistributed, ThinBandIsWidenedUntilItCoversEveryStencil) {
  const Communicator world = Communicator::world();
  BoxSpec spec;
  spec.n[0] = spec.n[1] = 24;
  const Mesh mesh = make_structured_mesh(spec);
  const KineticGas argon = KineticGas::argon();
  const Real rho = argon.density_for_knudsen(0.1, T0, 1.0);
  auto serial = closed_box(mesh, argon, Communicator::serial());
  auto parallel = closed_box(mesh, argon, world, 1);
  ImmersedSurface body = ImmersedSurface::rectangle({0.31, 0.37, 0}, {0.53, 0.61, 0}, 3, 3);
  const std::vector<Vec3> velocity(body.n_segments(), Vec3(40, 0, 0));
  for (ImmersedKineticGas* gas : {serial.get(), parallel.get()}) {
    gas->set_body(body, velocity);
    gas->initialize({rho, Vec3::Zero(), T0});
  }
  Real worst = 0;
  for (int step = 0; step < 3; ++step) {
    body = body.translated(Vec3(40 * 2e-4, 0, 0));
    for (ImmersedKineticGas* gas : {serial.get(), parallel.get()}) {
      gas->set_body(body, velocity);
      EXPECT_TRUE(gas->advance(2e-4).converged);
    }
    const std::vector<Vec3> fs = serial->segment_forces(), fp = parallel->segment_forces();
    for (std::size_t k = 0; k < fs.size(); ++k)
      worst = std::max(worst, (fs[k] - fp[k]).norm() / max_norm(fs));
  }
  if (world.is_root())
    std::printf("%d ranks: band widened 1 -> %d rings; segment forces to %.2e\n", world.size(),
                parallel->partition().band_rings, worst);
  if (!world.is_serial()) {
    EXPECT_GT(parallel->partition().band_rings, 1);
  }
  EXPECT_LE(worst, 1e-8);
}

ImmersedEsbgkSettings air(const Communicator& comm) {
  ImmersedEsbgkSettings s;
  s.gas.R = 287.05;
  s.gas.mu_ref = 1.712e-5;
  s.gas.T_ref = 273.15;
  s.gas.omega = 0.74;
  s.pressure = 1.36e4;
  s.temperature = 300;
  s.velocities = 6;
  s.options.step_tolerance = 1e-8;
  s.comm = comm;
  return s;
}

class CoupledCoarseSwitch : public ::testing::TestWithParam<bool> {};  // strong_gas

TEST_P(CoupledCoarseSwitch, GivesTheSerialTipDeflection) {
  using namespace rfmems::test;
  const Communicator world = Communicator::world();
  Cantilever c(45, 3, 76, 26);
  DynamicOptions o = run_options(1.2e-8, 1e-2);
  o.output_interval = o.end_time / 24;  // the samples compared
  if (GetParam()) {
    o.coupling.scheme = CouplingScheme::StronglyCoupled;
    o.coupling.strong_gas = true;
  }
  auto serial_gas =
      std::make_unique<ImmersedEsbgkGas>(c.scene->background(), air(Communicator::serial()), 0.0);
  auto parallel_gas = std::make_unique<ImmersedEsbgkGas>(c.scene->background(), air(world), 0.0);
  const ImmersedEsbgkGas& serial = *serial_gas;
  const ImmersedEsbgkGas& parallel = *parallel_gas;
  const std::unique_ptr<StructureGas> serial_surface = c.scene->surface_gas(std::move(serial_gas));
  const std::unique_ptr<StructureGas> parallel_surface =
      c.scene->surface_gas(std::move(parallel_gas));
  c.reset_times();
  const DynamicRun r1 = c.coupled->run(80.0, o, serial_surface.get());
  const CoupledRunTimes t1 = c.coupled->times();
  c.reset_times();
  const DynamicRun rP = c.coupled->run(80.0, o, parallel_surface.get());
  const CoupledRunTimes tP = c.coupled->times();
  if (GetParam()) {
    EXPECT_EQ(tP.coupling_iterations, t1.coupling_iterations);
    EXPECT_EQ(tP.gas_steps, t1.gas_steps);
    EXPECT_GT(tP.gas_steps, tP.structure_steps);  // the gas redone inside the iterations
    EXPECT_EQ(tP.unconverged_steps + t1.unconverged_steps, 0);
    EXPECT_LE(tP.max_coupling_residual, o.coupling.tolerance);
    if (world.is_root())
      std::printf("strong_gas: %ld steps, %ld coupling iterations (at most %d in a step)\n",
                  tP.structure_steps, tP.coupling_iterations, tP.max_coupling_iterations);
  }
  ASSERT_GT(parallel.stats().steps, 1);
  EXPECT_EQ(parallel.stats().steps, serial.stats().steps);
  EXPECT_EQ(parallel.stats().unconverged + serial.stats().unconverged, 0);
  ASSERT_EQ(r1.history.size(), rP.history.size());
  const Real scale = std::abs(r1.history.back().control);
  Real perimeter = 0;
  for (Index k = 0; k < c.scene->rest_surface().n_segments(); ++k)
    perimeter += c.scene->rest_surface().length(k);
  const Real gas_scale = 1.36e4 * perimeter;
  Real d_tip = 0, d_gas = 0;
  for (std::size_t i = 0; i < r1.history.size(); ++i) {
    // IDA's steps: the serial ones up to the round-off the gas force's differences cause.
    EXPECT_NEAR(r1.history[i].t, rP.history[i].t, 1e-9 * o.end_time);
    d_tip = std::max(d_tip, std::abs(r1.history[i].control - rP.history[i].control));
    d_gas = std::max(d_gas, std::abs(r1.history[i].gas_force - rP.history[i].gas_force));
  }
  if (world.is_root())
    std::printf(
        "%d ranks: %ld gas steps, %ld -> %ld sweeps; tip %.6e m, max difference %.2e "
        "relative; gas force %.4e N/m, max difference %.2e of p0 times the perimeter\n",
        world.size(), parallel.stats().steps, serial.stats().sweeps, parallel.stats().sweeps,
        r1.history.back().control, d_tip / scale, r1.history.back().gas_force, d_gas / gas_scale);
  EXPECT_LT(r1.history.back().control, 0);
  EXPECT_LE(d_tip, 1e-6 * scale);
  EXPECT_LE(d_gas, 1e-7 * gas_scale);
}

INSTANTIATE_TEST_SUITE_P(ImmersedGasDistributed, CoupledCoarseSwitch, ::testing::Bool(),
                         [](const auto& info) {
                           return std::string(info.param ? "StrongGas" : "Staggered");
                         });

}  // namespace
}  // namespace rfmems

// COMET on a distributed mesh (thesis sec. 5.4) under mpirun -np P gives the serial
// answer: agglomeration per part, coarse ghosts exchanged, Gauss-Seidel within a part with
// ghost exchanges between passes (block Jacobi between parts), global norms and masses.
//
// Every rank also solves the whole problem serially (a 10 x 10 mesh costs ~1 s) and compares
// its owned cells with the serial cells of the same global number. Both runs stop at
// ||r|| / ||r_0|| <= 1e-8; asserted: max over cells of |T_P - T_1| / (T_hot - T0) (heat
// transfer) or / T0 (cavity), |rho_P - rho_1| / rho0, |u_P - u_1| / u_scale <= 1e-6, and the
// wall forces and heat flows equal to 1e-6 of their scale; the mass held to 1e-12; the cycle
// count on P ranks at most 1.5x the serial count + 2 on METIS parts (block Jacobi between
// parts and coarse levels that stop at the part boundaries cost cycles; printed; measured
// with V-cycles 14 -> 16, 17, 18 on 2, 3, 4 ranks for the heat transfer at Kn = 0.01; with
// the default cycle by regime, F there, 11 -> 13, 14 on 2, 3 ranks; 7 -> 7, 8, 8 for the
// cavity), 3x + 2 on the column partition below (measured 7 -> 15). On one rank the
// distributed path is the serial solver: the same cycles and bit-identical fields.
//
// Cases (test/unit/comet/comet_cases.hpp's problems, argon ESBGK, 8^3 velocities, COMET
// forced at every Kn): heat transfer at Kn = 0.01 (where COMET matters) and the cavity at
// Kn = 0.1 on METIS parts; and the heat transfer at Kn = 0.1 on a hand-made partition that
// leaves the last rank without cells and gives the others disconnected parts (columns dealt
// out in turn), the cases METIS never produces on a square but a user's mesh can.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../unit/comet/comet_cases.hpp"
#include "parallel/distributed_mesh.hpp"
#include "physics/gas/comet/comet_solver.hpp"

namespace rfmems {
namespace {

using namespace comet_test;

constexpr int kCells = 10, kVelocities = 8;
constexpr Real kTolerance = 1e-8;

CometOptions comet_options() {
  CometOptions o;
  o.tolerance = kTolerance;
  o.sequential_above_knudsen = 0;  // COMET itself at every Kn
  o.max_cycles = 400;
  return o;
}

// The serial problem's boundary conditions, by patch name, for a rank's part ("processor"
// faces close the ghost layer: only ghost cells touch them, so any condition will do).
std::vector<KineticBoundary> local_boundaries(const FaceGraph& global, const KineticOperator& op,
                                              const FaceGraph& local) {
  std::vector<KineticBoundary> bcs;
  for (const std::string& name : local.patch_names) {
    const int p = global.find_patch(name);
    bcs.push_back(p >= 0 ? op.boundaries()[p] : KineticBoundary::specular_wall());
  }
  return bcs;
}

struct Comparison {
  Real dT = 0, drho = 0, du = 0, dforce = 0, dheat = 0, dmass = 0;
  int serial_cycles = 0, parallel_cycles = 0, levels_serial = 0, levels_parallel = 0;
  CommunicationCounters sent;
};

// Solves `which` serially on every rank and distributed over the ranks (METIS parts, or the
// given part of each global cell), and compares.
Comparison compare(Case which, Real kn, const std::vector<int>& parts = {}) {
  const Communicator comm = Communicator::world();
  auto serial = make_problem(which, kn, kCells, kVelocities);
  KineticOperator& sop = *serial->op;
  std::vector<Real> fs = serial->f;
  CometSolver serial_solver(sop, comet_options());
  const CometResult rs = serial_solver.solve(fs);
  EXPECT_TRUE(rs.converged);

  BoxSpec spec;
  spec.upper = Vec3(kLength, kLength, 0);
  spec.n[0] = spec.n[1] = kCells;
  const Mesh global = make_structured_mesh(spec);
  DistributedMesh d;
  if (parts.empty() || comm.is_serial()) {
    d = distribute_mesh(global, comm, 1);
  } else {
    d.partition.n_parts = comm.size();
    d.partition.part = parts;
    d.n_global_cells = global.n_cells();
    d.local = extract_local_mesh(global, d.partition, comm.rank(), 1);
    d.exchange = GhostExchange(comm, d.local);
  }
  const FaceGraph graph = face_graph_of(d.local.mesh);
  KineticOperator op(graph, sop.grid(), sop.gas(), local_boundaries(serial->graph, sop, graph));
  if (!comm.is_serial()) op.set_parallel(comm, &d.exchange);
  std::vector<Real> f(op.size());
  const Real rho0 = serial->rho0;
  op.initialize(f, [rho0](const Vec3&) { return GasState{rho0, Vec3::Zero(), kT0}; });
  const Real mass0 = op.total_mass(f);
  CometSolver solver(op, comet_options());
  const CometResult rp = solver.solve(f);
  EXPECT_TRUE(rp.converged);

  Comparison out;
  out.serial_cycles = rs.cycles;
  out.parallel_cycles = rp.cycles;
  out.levels_serial = rs.levels;
  out.levels_parallel = rp.levels;
  out.sent = rp.communication;
  op.update_collision(f);
  sop.update_collision(fs);
  const Real t_scale = which == Case::HeatTransfer ? kTHot - kT0 : kT0;
  const Real u_scale = which == Case::HeatTransfer ? sop.gas().thermal_speed(kT0) : kLidSpeed;
  for (Index c = 0; c < op.n_owned_cells(); ++c) {
    const MacroState& mp = op.macro(c);
    const MacroState& ms = sop.macro(d.local.global_cell[c]);
    out.dT = std::max(out.dT, std::abs(mp.T - ms.T) / t_scale);
    out.drho = std::max(out.drho, std::abs(mp.rho - ms.rho) / rho0);
    out.du = std::max(out.du, (mp.u - ms.u).norm() / u_scale);
  }
  out.dT = comm.max(out.dT);
  out.drho = comm.max(out.drho);
  out.du = comm.max(out.du);
  out.dmass = std::abs(op.total_mass(f) / mass0 - 1);
  // Walls: forces (pressure + shear) against the largest serial wall force; heat flows
  // against the largest serial heat flow (the heat transfer case's; the cavity's is small).
  Real force_scale = 0, heat_scale = 0;
  for (const std::string& name : serial->graph.patch_names) {
    force_scale = std::max(force_scale, sop.wall_force(name, fs).norm());
    heat_scale =
        std::max(heat_scale, std::abs(sop.wall_heat_flow(serial->graph.find_patch(name), fs)));
  }
  for (const std::string& name : serial->graph.patch_names) {
    const Vec3 Fp = op.wall_force(graph.find_patch(name), f);  // -1: no faces here, still a sum
    const Vec3 Fs = sop.wall_force(name, fs);
    out.dforce = std::max(out.dforce, (Fp - Fs).norm() / force_scale);
    const Real qp = op.wall_heat_flow(graph.find_patch(name), f);
    const Real qs = sop.wall_heat_flow(serial->graph.find_patch(name), fs);
    out.dheat = std::max(out.dheat, std::abs(qp - qs) / heat_scale);
  }
  if (comm.is_root())
    std::printf(
        "ranks %d, %s Kn %g: cycles %d (%d levels) serial -> %d (%d levels); max diff T "
        "%.1e rho %.1e u %.1e force %.1e heat %.1e mass %.1e; rank 0 sent %lld messages, "
        "%lld bytes, %lld reductions\n",
        comm.size(), which == Case::HeatTransfer ? "heat transfer" : "cavity", kn,
        out.serial_cycles, out.levels_serial, out.parallel_cycles, out.levels_parallel, out.dT,
        out.drho, out.du, out.dforce, out.dheat, out.dmass,
        static_cast<long long>(out.sent.messages), static_cast<long long>(out.sent.bytes),
        static_cast<long long>(out.sent.reductions));
  return out;
}

// growth: the stated bound on parallel / serial V-cycles.
void expect_serial_answer(const Comparison& c, Real growth = 1.5) {
  EXPECT_LT(c.dT, 1e-6);
  EXPECT_LT(c.drho, 1e-6);
  EXPECT_LT(c.du, 1e-6);
  EXPECT_LT(c.dforce, 1e-6);
  EXPECT_LT(c.dheat, 1e-6);
  EXPECT_LT(c.dmass, 1e-12);
  EXPECT_LE(c.parallel_cycles, growth * c.serial_cycles + 2);
}

// The coarse levels of a distributed mesh (fv/agglomeration.hpp): on every level and rank each
// owned coarse cell is closed (its outward face areas sum to 0, so no face across a part
// boundary is missing), the owned volumes add up to the domain's area, the level count and
// global cell counts are the same as seen from every rank, and every coarse ghost carries the
// volume its owner has, and every fine cell (ghosts too) lies inside its coarse cell (the
// coarse numbers sent to the ghosts name the right cells).
TEST(CometDistributed, CoarseLevelsAreClosedAndConsistentAcrossRanks) {
  const Communicator comm = Communicator::world();
  BoxSpec spec;
  spec.n[0] = spec.n[1] = 16;
  const Mesh global = make_structured_mesh(spec, [](const Vec3& x) {
    return Vec3(x.x() + 0.05 * std::sin(3 * x.y()), x.y() + 0.04 * std::sin(2 * x.x()), 0);
  });
  const DistributedMesh d = distribute_mesh(global, comm, 1);
  const FaceGraph fine = face_graph_of(d.local.mesh);
  const std::vector<Agglomeration> levels =
      agglomeration_hierarchy(fine, 4, 30, comm, comm.is_serial() ? nullptr : &d.exchange);
  const Index n_levels = static_cast<Index>(levels.size());
  EXPECT_EQ(comm.max(n_levels), comm.sum(n_levels) / comm.size());
  EXPECT_GE(n_levels, 3);
  Real area = 0;
  for (Index c = 0; c < global.n_cells(); ++c) area += global.cell_volume(c);
  Index n_fine = global.n_cells();
  const FaceGraph* finer = &fine;
  for (const Agglomeration& a : levels) {
    const FaceGraph& g = a.coarse;
    // Every fine cell, ghosts too, lies inside its coarse cell: a ghost given the wrong coarse
    // number would sit far from that cell's centroid.
    Real misplaced = 0;
    for (Index c = 0; c < finer->n_cells(); ++c) {
      const Index k = a.coarse_of_fine[c];
      const Real reach = 2 * std::sqrt(g.cell_volume[k]);
      misplaced =
          std::max(misplaced, (finer->cell_centroid[c] - g.cell_centroid[k]).norm() / reach);
      EXPECT_LE(finer->cell_volume[c], g.cell_volume[k] * (1 + 1e-12));
    }
    EXPECT_LT(comm.max(misplaced), 1.0);
    finer = &g;
    Real closure = 0, volume = 0;
    for (Index k = 0; k < g.n_owned_cells; ++k) {
      Vec3 sum = Vec3::Zero();
      for (Index i = g.cell_face_offsets[k]; i < g.cell_face_offsets[k + 1]; ++i) {
        const Index f = g.cell_faces[i];
        sum += g.face_owner[f] == k ? Vec3(g.face_area[f]) : Vec3(-g.face_area[f]);
      }
      closure = std::max(closure, sum.norm() / std::sqrt(g.cell_volume[k]));
      volume += g.cell_volume[k];
    }
    EXPECT_LT(comm.max(closure), 1e-12);
    EXPECT_NEAR(comm.sum(volume), area, 1e-12 * area);
    const Index n_coarse = comm.sum(g.n_owned_cells);
    EXPECT_LT(n_coarse, n_fine);
    n_fine = n_coarse;
    if (!comm.is_serial()) {
      std::vector<Real> v(g.cell_volume.begin(), g.cell_volume.end());
      for (Index k = g.n_owned_cells; k < g.n_cells(); ++k) v[k] = -1;
      a.coarse_exchange.exchange(v, 1);
      for (Index k = 0; k < g.n_cells(); ++k) EXPECT_EQ(v[k], g.cell_volume[k]);
    }
  }
}

TEST(CometDistributed, HeatTransferKn001EqualsSerial) {
  const Comparison c = compare(Case::HeatTransfer, 0.01);
  expect_serial_answer(c);
  if (Communicator::world().is_serial()) {
    EXPECT_EQ(c.parallel_cycles, c.serial_cycles);  // one rank is the serial solver
    EXPECT_EQ(c.dT, 0.0);
  }
}

TEST(CometDistributed, CavityKn01EqualsSerial) { expect_serial_answer(compare(Case::Cavity, 0.1)); }

TEST(CometDistributed, EmptyRankAndDisconnectedPartsTakePart) {
  const Communicator comm = Communicator::world();
  // Column i of the mesh (cells are numbered x fastest) to rank i mod (P - 1); rank P - 1
  // gets nothing.
  std::vector<int> parts(kCells * kCells, 0);
  const int used = std::max(1, comm.size() - 1);
  for (Index c = 0; c < kCells * kCells; ++c) parts[c] = static_cast<int>((c % kCells) % used);
  // Every cell of a column borders another rank (the heat flows along the columns, but the
  // point solves see their x neighbours a pass late): measured 7 -> 15 cycles on 3 and 4
  // ranks, so the bound here is 3x.
  expect_serial_answer(compare(Case::HeatTransfer, 0.1, parts), 3.0);
}

}  // namespace
}  // namespace rfmems

// The distributed mesh under mpirun -np P: every global cell owned by exactly one rank, ghost
// values equal to their owners' after an exchange, and a distributed FV residual (the
// elasticity operator, the widest stencil in the library: cubic reconstructions, 4 ghost
// layers) equal on every owned cell to the serial residual of the whole mesh — the property
// "mpirun -np P gives the serial answer" rests on.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/structured_mesh.hpp"
#include "parallel/distributed_mesh.hpp"
#include "physics/elasticity/elasticity_operator.hpp"

using namespace rfmems;

namespace {

Mesh skewed_strip() {
  BoxSpec spec;
  spec.upper = Vec3(3, 1, 0);
  spec.n[0] = 30;
  spec.n[1] = 8;
  return make_structured_mesh(spec, [](const Vec3& x) {
    return Vec3(x.x() + 0.05 * std::sin(2 * x.y()), x.y() + 0.04 * std::sin(3 * x.x()), 0);
  });
}

std::vector<ElasticityBoundary> boundaries(const Mesh& mesh) {
  std::vector<ElasticityBoundary> bcs;
  for (const Patch& p : mesh.patches()) {
    if (p.name == "left")
      bcs.push_back({ElasticityBoundary::Kind::Fixed,
                     [](const Vec3&, double) { return Vec3::Zero().eval(); }});
    else
      bcs.push_back({ElasticityBoundary::Kind::Traction,
                     [](const Vec3&, double) { return Vec3(0, -1e5, 0); }});
  }
  return bcs;
}

// A smooth displacement field, known on every rank by global position.
Vec3 displacement(const Vec3& x) {
  return Vec3(1e-4 * std::sin(x.x()) * x.y(), -2e-4 * x.x() * x.x() + 1e-5 * x.y(), 0);
}

}  // namespace

TEST(DistributedMesh, GhostsReceiveTheirOwnersValues) {
  const Communicator comm = Communicator::world();
  const Mesh global = skewed_strip();
  DistributedMesh d = distribute_mesh(global, comm, 2);
  const Mesh& mesh = d.local.mesh;
  EXPECT_EQ(comm.sum(mesh.n_owned_cells()), global.n_cells());
  if (comm.size() > 1) {
    EXPECT_GT(mesh.n_cells(), mesh.n_owned_cells());
  }

  // Owned cells carry (global id, rank, 7); ghosts start as garbage.
  const int block = 3;
  std::vector<Real> values(mesh.n_cells() * block, -1.0);
  for (Index c = 0; c < mesh.n_owned_cells(); ++c) {
    values[block * c] = static_cast<Real>(d.local.global_cell[c]);
    values[block * c + 1] = comm.rank();
    values[block * c + 2] = 7;
  }
  d.exchange.exchange(values, block);
  for (Index c = mesh.n_owned_cells(); c < mesh.n_cells(); ++c) {
    EXPECT_EQ(values[block * c], static_cast<Real>(d.local.global_cell[c]));
    EXPECT_EQ(values[block * c + 1], d.local.owner_part[c]);
    EXPECT_EQ(values[block * c + 2], 7);
  }
  std::vector<Real> gathered = gather_to_root(comm, d.local, values, block, global.n_cells());
  if (comm.is_root()) {
    ASSERT_EQ(static_cast<Index>(gathered.size()), global.n_cells() * block);
    for (Index g = 0; g < global.n_cells(); ++g)
      EXPECT_EQ(gathered[block * g], static_cast<Real>(g));
  }
}

TEST(DistributedMesh, DistributedResidualEqualsTheSerialOne) {
  const Communicator comm = Communicator::world();
  const Mesh global = skewed_strip();
  const LinearElastic steel{200e9, 0.3, 7800, Hypothesis::PlaneStrain};

  ElasticityOperator serial_op(global, steel, boundaries(global));
  std::vector<Real> u(serial_op.size()), r_serial(serial_op.size());
  for (Index c = 0; c < global.n_cells(); ++c) {
    const Vec3 v = displacement(global.cell_centroid(c));
    u[2 * c] = v.x();
    u[2 * c + 1] = v.y();
  }
  serial_op.internal_residual(0.0, u, r_serial);
  Real scale = 0;
  for (Real x : r_serial) scale = std::max(scale, std::abs(x));

  DistributedMesh d = distribute_mesh(global, comm, 4);  // cubic stencils reach 3 rings
  const Mesh& mesh = d.local.mesh;
  ElasticityOperator op(mesh, steel, boundaries(mesh));
  // Each rank knows only its owned values; the ghosts come through the exchange.
  std::vector<Real> ul(op.size(), 0.0), rl(op.size());
  for (Index c = 0; c < mesh.n_owned_cells(); ++c) {
    const Vec3 v = displacement(mesh.cell_centroid(c));
    ul[2 * c] = v.x();
    ul[2 * c + 1] = v.y();
  }
  d.exchange.exchange(ul, 2);
  op.internal_residual(0.0, ul, rl);

  std::vector<Real> r_gathered = gather_to_root(comm, d.local, rl, 2, global.n_cells());
  if (comm.is_root()) {
    Real diff = 0;
    for (std::size_t i = 0; i < r_serial.size(); ++i)
      diff = std::max(diff, std::abs(r_gathered[i] - r_serial[i]));
    std::printf("ranks %d: max |r_distributed - r_serial| / max |r| = %.2e\n", comm.size(),
                diff / scale);
    EXPECT_LT(diff, 1e-12 * scale);
  }
  // Global reductions agree with the serial norm.
  Real local_sq = 0;
  for (Index i = 0; i < 2 * mesh.n_owned_cells(); ++i) local_sq += rl[i] * rl[i];
  Real serial_sq = 0;
  for (Real x : r_serial) serial_sq += x * x;
  EXPECT_NEAR(comm.sum(local_sq), serial_sq, 1e-12 * serial_sq);
}

TEST(DistributedMesh, MoreRanksThanCellsLeavesRanksEmptyButWorking) {
  const Communicator comm = Communicator::world();
  BoxSpec spec;
  spec.n[0] = 2;
  const Mesh global = make_structured_mesh(spec);  // 2 cells
  DistributedMesh d = distribute_mesh(global, comm, 1);
  const Index n_owned = d.local.mesh.n_owned_cells();
  EXPECT_EQ(comm.sum(n_owned), 2);
  if (comm.rank() >= 2) {
    EXPECT_EQ(n_owned, 0);
  }
  std::vector<Real> values(d.local.mesh.n_cells(), 0.0);
  for (Index c = 0; c < n_owned; ++c) values[c] = 10.0 + static_cast<Real>(d.local.global_cell[c]);
  d.exchange.exchange(values, 1);
  for (Index c = n_owned; c < d.local.mesh.n_cells(); ++c)
    EXPECT_EQ(values[c], 10.0 + static_cast<Real>(d.local.global_cell[c]));
  std::vector<Real> all = gather_to_root(comm, d.local, values, 1, 2);
  if (comm.is_root()) {
    EXPECT_EQ(all, (std::vector<Real>{10.0, 11.0}));
  }
}

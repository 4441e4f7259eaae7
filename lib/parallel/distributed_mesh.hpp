// A mesh distributed over the ranks of a communicator: every rank holds the cells it owns
// (METIS k-way part `rank` of the global cell graph, mesh/partition.hpp) followed by its ghost
// layers, and a GhostExchange that refreshes ghost values from their owners.
//
// Every rank builds (or reads) the global mesh and partitions it with the same deterministic
// METIS call (fixed seed), so no mesh data travels; only ghost values do. That is enough up to
// meshes of a few million cells; a parallel reader can replace the global build later without
// changing this interface.
#pragma once
#include <vector>

#include "mesh/partition.hpp"
#include "parallel/communicator.hpp"
#include "parallel/ghost_exchange.hpp"

namespace rfmems {

struct DistributedMesh {
  LocalMesh local;         // owned cells first, then ghosts (local.global_cell, owner_part)
  Partition partition;     // of the global mesh (edge cut, imbalance)
  GhostExchange exchange;  // refreshes ghost cells' values
  Index n_global_cells = 0;
};

// Partitions `global` into comm.size() parts (weights: empty = 1 per cell) and builds this
// rank's part with `ghost_layers` layers of ghosts.
DistributedMesh distribute_mesh(const Mesh& global, const Communicator& comm, int ghost_layers,
                                std::span<const int> weights = {});

// The owned values of every rank (block values per cell) gathered on the root, in global cell
// order; other ranks get an empty vector. Serial: the owned values themselves.
std::vector<Real> gather_to_root(const Communicator& comm, const LocalMesh& local,
                                 std::span<const Real> values, int block, Index n_global_cells);

}  // namespace rfmems

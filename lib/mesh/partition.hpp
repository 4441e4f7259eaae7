// Domain decomposition: METIS k-way partitions of the cell graph (cells joined by shared
// faces) and the local mesh of one part with its ghost layers.
//
// A local mesh lists the part's own cells first (ascending global number), then ghost cells
// layer by layer; the faces that leave the outermost ghost layer form the patch "processor".
// A residual computed on the owned cells of a local mesh equals the global one when the ghost
// layers cover the operator's stencil depth.
#pragma once
#include <span>
#include <vector>

#include "mesh/mesh.hpp"

namespace rfmems {

struct Partition {
  int n_parts = 1;
  std::vector<int> part;   // per global cell
  Index edge_cut = 0;      // interior faces between parts
  double imbalance = 1.0;  // largest part weight / mean part weight
};

// k-way partition with optional per-cell weights (empty: all 1).
Partition partition_cells(const Mesh& mesh, int n_parts, std::span<const int> weights = {});

struct LocalMesh {
  Mesh mesh;
  std::vector<Index> global_cell;  // local cell -> global cell
  std::vector<int> owner_part;     // local cell -> part that owns it
};

LocalMesh extract_local_mesh(const Mesh& global, const Partition& partition, int part,
                             int ghost_layers);

}  // namespace rfmems

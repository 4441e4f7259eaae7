#include "mesh/partition.hpp"

#include <fmt/format.h>
#include <metis.h>

#include <algorithm>
#include <map>

#include "core/error.hpp"

namespace rfmems {

Partition partition_cells(const Mesh& mesh, int n_parts, std::span<const int> weights) {
  const Index nc = mesh.n_cells();
  Partition result;
  result.n_parts = n_parts;
  result.part.assign(nc, 0);
  if (n_parts < 1) throw InputError(fmt::format("partition: {} parts requested", n_parts));
  if (!weights.empty() && static_cast<Index>(weights.size()) != nc)
    throw InputError("partition: one weight per cell is needed");

  // Dual graph in CSR form (METIS uses 32-bit indices here).
  std::vector<idx_t> xadj{0}, adjncy, vwgt;
  for (Index c = 0; c < nc; ++c) {
    for (Index f : mesh.cell_faces(c)) {
      if (mesh.is_boundary(f)) continue;
      adjncy.push_back(static_cast<idx_t>(mesh.face_owner(f) == c ? mesh.face_neighbour(f)
                                                                  : mesh.face_owner(f)));
    }
    xadj.push_back(static_cast<idx_t>(adjncy.size()));
    vwgt.push_back(weights.empty() ? 1 : weights[c]);
  }
  if (n_parts > 1 && nc >= n_parts) {
    idx_t nvtxs = static_cast<idx_t>(nc), ncon = 1, nparts = n_parts, objval = 0;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_CONTIG] = 1;  // connected parts where the graph allows
    options[METIS_OPTION_SEED] = 1;    // reproducible
    std::vector<idx_t> part(nc);
    int status =
        METIS_PartGraphKway(&nvtxs, &ncon, xadj.data(), adjncy.data(), vwgt.data(), nullptr,
                            nullptr, &nparts, nullptr, nullptr, options, &objval, part.data());
    if (status != METIS_OK) throw SolverError(fmt::format("METIS failed with status {}", status));
    std::copy(part.begin(), part.end(), result.part.begin());
  } else if (n_parts > 1) {
    // Fewer cells than parts: one cell per part, the rest empty.
    for (Index c = 0; c < nc; ++c) result.part[c] = static_cast<int>(c);
  }

  std::vector<double> load(n_parts, 0.0);
  for (Index c = 0; c < nc; ++c) load[result.part[c]] += vwgt[c];
  double mean = 0;
  for (double l : load) mean += l / n_parts;
  result.imbalance = *std::max_element(load.begin(), load.end()) / mean;
  for (Index f = 0; f < mesh.n_interior_faces(); ++f)
    if (result.part[mesh.face_owner(f)] != result.part[mesh.face_neighbour(f)]) ++result.edge_cut;
  return result;
}

LocalMesh extract_local_mesh(const Mesh& global, const Partition& partition, int part,
                             int ghost_layers) {
  LocalMesh local;
  std::vector<Index> cells;
  std::vector<char> taken(global.n_cells(), 0);
  for (Index c = 0; c < global.n_cells(); ++c)
    if (partition.part[c] == part) {
      cells.push_back(c);
      taken[c] = 1;
    }
  const Index n_owned = static_cast<Index>(cells.size());
  if (n_owned == 0) {  // METIS may leave a part empty (more parts than a tiny graph allows)
    local.mesh = MeshBuilder(global.dim()).build_empty();
    return local;
  }
  // Ghost layers: breadth-first over face neighbours.
  Index layer_begin = 0;
  for (int layer = 0; layer < ghost_layers; ++layer) {
    const Index layer_end = static_cast<Index>(cells.size());
    for (Index i = layer_begin; i < layer_end; ++i)
      for (Index f : global.cell_faces(cells[i])) {
        if (global.is_boundary(f)) continue;
        Index other =
            global.face_owner(f) == cells[i] ? global.face_neighbour(f) : global.face_owner(f);
        if (!taken[other]) {
          taken[other] = 1;
          cells.push_back(other);
        }
      }
    layer_begin = layer_end;
  }

  MeshBuilder builder(global.dim());
  std::map<Index, Index> node_map;
  auto local_node = [&](Index n) {
    auto [it, inserted] = node_map.emplace(n, static_cast<Index>(node_map.size()));
    if (inserted) builder.add_node(global.nodes()[n]);
    return it->second;
  };
  for (Index c : cells) {
    std::vector<Index> nodes;
    for (Index n : global.cell_nodes(c)) nodes.push_back(local_node(n));
    builder.add_cell(global.cell_shape(c), std::move(nodes));
    local.global_cell.push_back(c);
    local.owner_part.push_back(partition.part[c]);
  }
  // Physical boundary faces keep their patches; faces cut by the ghost layer become "processor".
  for (Index c : cells)
    for (Index f : global.cell_faces(c)) {
      if (!global.is_boundary(f)) continue;
      std::vector<Index> nodes;
      for (Index n : global.face_nodes(f)) nodes.push_back(local_node(n));
      builder.add_boundary_face(std::move(nodes), global.patches()[global.face_patch(f)].name);
    }
  builder.set_ownership(n_owned, local.global_cell);
  local.mesh = builder.build(fmt::format("part {} of {}", part, partition.n_parts), "processor");
  return local;
}

}  // namespace rfmems

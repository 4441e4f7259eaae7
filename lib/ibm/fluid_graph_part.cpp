#include "ibm/fluid_graph_part.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace rfmems {

FluidGraphPart restrict_fluid_graph(const FluidFaceGraph& global, const FaceGraph& background,
                                    const CellMarking& marking, std::span<const int> part,
                                    const Communicator& comm, int band_rings) {
  const FaceGraph& g = global.graph;
  const Index nb = background.n_cells(), ng = g.n_cells();
  if (static_cast<Index>(part.size()) != nb)
    throw InputError("FLUID graph part: one owner rank per background cell");
  const int rank = comm.rank();
  auto owner_of = [&](Index c) { return part[global.background_cell[c]]; };

  // The IB band: breadth first over the background from every non-FLUID cell.
  std::vector<int> depth(nb, -1);
  std::vector<Index> frontier;
  for (Index b = 0; b < nb; ++b)
    if (marking.cell[b] != CellClass::Fluid) {
      depth[b] = 0;
      frontier.push_back(b);
    }
  for (int ring = 1; ring <= band_rings && !frontier.empty(); ++ring) {
    std::vector<Index> next;
    for (const Index b : frontier)
      for (Index i = background.cell_face_offsets[b]; i < background.cell_face_offsets[b + 1];
           ++i) {
        const Index f = background.cell_faces[i];
        if (background.is_boundary(f)) continue;
        const Index n =
            background.face_owner[f] == b ? background.face_neighbour[f] : background.face_owner[f];
        if (depth[n] >= 0) continue;
        depth[n] = ring;
        next.push_back(n);
      }
    frontier = std::move(next);
  }

  // Cells held: owned, then ghosts (transport neighbours and the band), each ascending.
  std::vector<char> held(ng, 0);
  std::vector<Index> owned, ghosts;
  for (Index c = 0; c < ng; ++c)
    if (owner_of(c) == rank) {
      held[c] = 1;
      owned.push_back(c);
    }
  for (Index f = 0; f < g.n_interior_faces; ++f) {
    const Index a = g.face_owner[f], b = g.face_neighbour[f];
    if (owner_of(a) == rank && !held[b]) held[b] = 2;
    if (owner_of(b) == rank && !held[a]) held[a] = 2;
  }
  for (Index c = 0; c < ng; ++c)
    if (!held[c] && depth[global.background_cell[c]] >= 0) held[c] = 2;
  for (Index c = 0; c < ng; ++c)
    if (held[c] == 2) ghosts.push_back(c);

  FluidGraphPart out;
  FluidFaceGraph& local = out.local;
  FaceGraph& lg = local.graph;
  lg.dim = g.dim;
  lg.patch_names = g.patch_names;
  local.immersed_patch = global.immersed_patch;
  local.fluid_cell.assign(nb, -1);
  out.local_of_global.assign(ng, -1);
  for (const auto* list : {&owned, &ghosts})
    for (const Index c : *list) {
      const Index l = static_cast<Index>(out.global_cell.size());
      out.global_cell.push_back(c);
      out.owner_rank.push_back(owner_of(c));
      out.local_of_global[c] = l;
      const Index b = global.background_cell[c];
      local.background_cell.push_back(b);
      local.fluid_cell[b] = l;
      lg.cell_volume.push_back(g.cell_volume[c]);
      lg.cell_centroid.push_back(g.cell_centroid[c]);
      if (depth[b] >= 0) out.band.push_back(l);
    }
  lg.n_owned_cells = static_cast<Index>(owned.size());

  auto add = [&](Index f, Index owner, Index neighbour) {
    lg.face_owner.push_back(owner);
    lg.face_neighbour.push_back(neighbour);
    lg.face_area.push_back(g.face_area[f]);
    lg.face_centroid.push_back(g.face_centroid[f]);
    lg.face_patch.push_back(g.face_patch[f]);
    local.ib_face.push_back(global.ib_face[f]);
    out.global_face.push_back(f);
  };
  for (Index f = 0; f < g.n_interior_faces; ++f) {
    const Index a = g.face_owner[f], b = g.face_neighbour[f];
    if (owner_of(a) == rank || owner_of(b) == rank)
      add(f, out.local_of_global[a], out.local_of_global[b]);
  }
  lg.n_interior_faces = lg.n_faces();
  for (Index f = g.n_interior_faces; f < g.n_faces(); ++f)
    if (owner_of(g.face_owner[f]) == rank) add(f, out.local_of_global[g.face_owner[f]], -1);
  lg.build_cell_faces();
  out.exchange = GhostExchange(comm, lg.n_owned_cells, out.global_cell, out.owner_rank);
  return out;
}

}  // namespace rfmems

// Coarse levels of a FaceGraph by pairwise agglomeration, for the geometric (FAS) multigrid of
// COMET (thesis ch. 5, after Mathur & Murthy): "each fine level cell is agglomerated
// to the neighbouring cell with which it shares the largest face area".
//
// Pairing: cells are visited in index order; an unpaired cell takes the unpaired neighbour
// across its largest interior face (ties: the first face in its face list). A cell left with
// no unpaired neighbour (a singleton) joins the already formed group it shares the largest
// total face area with, so every coarse cell holds >= 2 fine cells and the count roughly
// halves per level. On a structured mesh the rule alternates direction by itself: after
// pairing along x the coarse cells' largest faces are the y faces.
//
// Coarse geometry (the thesis re-discretises the transport equation on the coarse cells, so
// these are all it needs): volume = sum of fine volumes, centroid = volume-weighted mean;
// fine faces between the same two coarse cells merge into one coarse face whose area vector is
// their sum (oriented out of the coarse owner) and whose centroid is the |S|-weighted mean;
// fine faces inside a coarse cell are dropped; boundary faces merge per (coarse cell, patch).
// Summing area vectors keeps every coarse cell closed (sum of outward S = 0) and conserves
// volume and every patch's area vector exactly; it is exact for the upwind flux c.S of a
// state that is uniform on the merged face, which is what first-order upwind assumes anyway.
//
// Distributed meshes (steps 5-7 of the thesis's parallel algorithm, ch. 5): a rank's FaceGraph
// holds its owned cells and one ghost layer. Each rank pairs only its owned cells with owned
// neighbours, so a coarse cell never crosses ranks and a coarse level is again "owned coarse cells,
// then ghosts":
//   - owned coarse cells are numbered rank by rank (global number = the rank's offset, an
//     exclusive sum of the owned coarse counts, + local index);
//   - the coarse global number and owner rank of every owned fine cell go to the ranks that
//     hold it as a ghost through the fine level's GhostExchange (step 6), so every fine
//     ghost knows its coarse cell; the distinct coarse cells of the fine ghosts are the coarse
//     ghosts, with a GhostExchange of their own;
//   - coarse connectivity is rebuilt from the fine faces with at least one owned side (step
//     7): since the fine ghost layer holds every neighbour of an owned fine cell, every face of
//     an owned coarse cell is complete, and the coarse ghosts are again one full layer, so the
//     next level agglomerates the same way. Faces between two ghosts are dropped; ghosts' volume
//     and centroid come from their owners.
// Invariant the grid transfers use (comet/fas_transfer.hpp): a fine cell is owned exactly when
// its coarse cell is (coarse_of_fine[c] < coarse.n_owned_cells). On one rank everything
// reduces to the serial agglomeration. The level count is decided on global cell counts, so
// every rank (also one with no cells) builds the same number of levels.
#pragma once
#include <vector>

#include "fv/face_graph.hpp"
#include "parallel/ghost_exchange.hpp"

namespace rfmems {

struct Agglomeration {
  FaceGraph coarse;
  std::vector<Index> coarse_of_fine;  // coarse cell (local index) of each fine cell, ghosts too
  // Distributed levels only (empty / serial otherwise): per coarse cell its global number and
  // owning rank, and the exchange that refreshes the coarse ghosts.
  std::vector<Index> coarse_global;
  std::vector<int> coarse_owner;
  GhostExchange coarse_exchange;
};

// One coarsening step of a serial graph (InputError if it has ghost cells).
Agglomeration agglomerate(const FaceGraph& fine);
// One coarsening step of a rank's part: `fine_exchange` refreshes the fine ghosts (null: the
// serial step). Collective over comm.
Agglomeration agglomerate(const FaceGraph& fine, const Communicator& comm,
                          const GhostExchange* fine_exchange);

// Successive coarsenings of `fine`: levels[0] maps fine -> level 1, levels[i] maps level i ->
// level i + 1 (levels[i].coarse is level i + 1). Coarsening stops before a level would have
// fewer than `min_cells` cells, when it no longer reduces the count by at least 1/4, or after
// `max_levels` coarse levels (cell counts summed over comm's ranks).
std::vector<Agglomeration> agglomeration_hierarchy(
    const FaceGraph& fine, Index min_cells, int max_levels = 30,
    const Communicator& comm = Communicator::serial(),
    const GhostExchange* fine_exchange = nullptr);

}  // namespace rfmems

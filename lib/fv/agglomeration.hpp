// Coarse levels of a FaceGraph by pairwise agglomeration, for the geometric (FAS) multigrid of
// COMET (thesis sec. 5.3.2-5.4, after Mathur & Murthy): "each fine level cell is agglomerated
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
// Serial only for now: ghost cells (n_owned_cells < n_cells) are rejected (InputError); the
// MPI issue will agglomerate owned cells and exchange coarse indices (thesis sec. 5.4 step 6).
#pragma once
#include <vector>

#include "fv/face_graph.hpp"

namespace rfmems {

struct Agglomeration {
  FaceGraph coarse;
  std::vector<Index> coarse_of_fine;  // coarse cell of each fine cell
};

// One coarsening step.
Agglomeration agglomerate(const FaceGraph& fine);

// Successive coarsenings of `fine`: levels[0] maps fine -> level 1, levels[i] maps level i ->
// level i + 1 (levels[i].coarse is level i + 1). Coarsening stops before a level would have
// fewer than `min_cells` cells, when it no longer reduces the count by at least 1/4, or after
// `max_levels` coarse levels.
std::vector<Agglomeration> agglomeration_hierarchy(const FaceGraph& fine, Index min_cells,
                                                   int max_levels = 30);

}  // namespace rfmems

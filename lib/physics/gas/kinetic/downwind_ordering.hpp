// Downwind cell orderings for first-order upwind transport along each discrete velocity.
//
// For ordinate c_k, the upwind FV equation of cell C couples it only to the neighbours across
// faces with c_k . S_f < 0 (its upwind neighbours). Directed edges upwind -> downwind form a
// graph that is acyclic on meshes of convex cells for most directions; in a topological order
// of that graph one pass ("sweep") solves the per-ordinate system exactly (it is triangular).
//
// Ordinates whose signs of c_k . S_f agree on every interior face share one graph and one
// order: on a Cartesian mesh that is one group per octant (quadrant in 2D), so the orders cost
// O(groups x cells) memory, not O(ordinates x cells), and a sweep can visit each cell once per
// group with all of the group's ordinates contiguous in memory.
//
// Cycles (possible on skewed or 3D meshes): Kahn's algorithm forces the lowest-numbered
// unvisited cell when no cell is ready, so the cycle's closing edge uses the value of the
// previous sweep (a Gauss-Seidel step there); n_forced counts such cells.
#pragma once
#include <vector>

#include "core/types.hpp"
#include "fv/face_graph.hpp"
#include "physics/gas/kinetic/velocity_grid.hpp"

namespace rfmems {

struct DownwindGroup {
  std::vector<Index> ordinates;  // ordinates sharing the sign pattern
  std::vector<Index> cells;      // owned cells in downwind order
  Index n_forced = 0;            // cells taken out of order to break cycles
};

std::vector<DownwindGroup> downwind_groups(const FaceGraph& graph, const VelocityGrid& grid);

}  // namespace rfmems

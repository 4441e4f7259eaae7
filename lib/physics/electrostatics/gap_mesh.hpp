// The air gap under a 2D beam: the rectangle [x_0, x_n] x [-g0, 0] meshed with quads whose
// top nodes sit at the beam mesh's bottom node positions (conformal, so the beam's
// displacement moves the gap's top wall node by node and the electrostatic traction acts on
// the beam's own faces).
//
// Patches: `top` (y = 0, the beam's bottom face, the moving conductor), `left`, `right`
// (x = x_0, x_n), and the bottom (y = -g0) split into `electrode` (faces whose centroid lies
// in [electrode_begin, electrode_end]) and `substrate` (the rest; absent if empty). The
// electrode ends are thus snapped to the nearest node positions; choose the beam mesh so
// they fall on nodes if the exact extent matters.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace rfmems {

struct GapMeshSpec {
  std::vector<Real> x;  // node x positions along the gap, strictly increasing (>= 2)
  Real gap = 0;         // g0 > 0
  int n_y = 1;          // cells across the gap
  Real grading_y = 1;   // last/first cell height from the electrode up
  Real electrode_begin = -1e300, electrode_end = 1e300;
};

Mesh make_gap_mesh(const GapMeshSpec& spec);

// The x positions of the nodes of patch `patch` of a 2D mesh, sorted (e.g. a beam's bottom).
std::vector<Real> patch_node_x(const Mesh& mesh, const std::string& patch);

// For each node to_nodes[i] of mesh `to`, the node of `from_nodes` in mesh `from` at the
// same position (KD-tree); throws MeshError if the nearest is farther than tolerance.
std::vector<Index> match_nodes(const Mesh& from, std::span<const Index> from_nodes, const Mesh& to,
                               std::span<const Index> to_nodes, Real tolerance);

}  // namespace rfmems

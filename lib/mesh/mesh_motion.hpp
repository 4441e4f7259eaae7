// Mesh motion for the electrostatic gap under a deflecting beam (thesis ch. 2): the nodes
// of the moving patches (the beam's face) take a prescribed displacement, the nodes of the
// fixed patches (the electrode, the substrate) stay, and every other node follows by
//
//  1. blending: node i takes the displacement of its nearest moving node m (KD-tree,
//     nanoflann through io/point_locator), scaled by a distance function of r_m = |x_i - x_m|
//     and r_f = distance to the nearest fixed node:
//
//         s = (exp(-r_m/r0) - exp(-(r_m + r_f)/r0)) / (1 - exp(-(r_m + r_f)/r0)),
//
//     the thesis' exponential decay exp(-r_m/r0) renormalised so that s = 1 on the moving wall
//     and s = 0 on the fixed wall. r0 -> infinity (decay_length = 0, the default) gives
//     s = r_f / (r_m + r_f): uniform compression across the gap. Why that default: the local
//     compression of the gap is 1 - delta ds/dr, and s has slope 1/((1 - exp(-L/r0)) r0) at
//     the moving wall (L = r_m + r_f the local gap); with r0 = L that is 1.58/L, so a
//     deflection beyond 63 % of the gap inverts the first cell row, while the linear profile
//     (slope 1/L everywhere) keeps every cell valid up to a full gap closure. A finite r0 is
//     for open regions (no fixed wall nearby: s -> exp(-r_m/r0)).
//  2. spring-analogy smoothing: Jacobi sweeps  d_i <- sum_j w_ij d_j / sum_j w_ij  over edge
//     neighbours with w_ij = 1 / |x_i - x_j| (reference lengths). We smooth displacements,
//     not positions, so the reference mesh (graded, possibly skewed) is a fixed point, and
//     with the 1/length weights a displacement linear along a mesh line is one too.
//
// Nodes of patches that are neither moving nor fixed slide along them (the normal component
// of their displacement is removed, per face normal of those patches) or, with
// slide_on_other_patches = false, stay. A node on a moving patch is moving even if it also
// lies on a fixed or sliding patch; a node on a fixed patch is fixed.
//
// Each move() is relative to the reference mesh (the mesh at construction), not cumulative.
// If a cell inverts or collapses, the mesh is put back where it was and MeshError is thrown
// naming the cell (the message of Mesh::check_quality, prefixed with "mesh motion: ").
#pragma once
#include <span>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace rfmems {

struct MeshMotionOptions {
  // r0 of the exponential decay [m]; 0 = no decay (linear blend between the walls).
  Real decay_length = 0;
  // Jacobi sweeps of spring smoothing after blending.
  int smoothing_sweeps = 10;
  // Nodes of patches neither moving nor fixed slide along them (true) or stay (false).
  bool slide_on_other_patches = true;
};

class MeshMotion {
 public:
  MeshMotion(Mesh& mesh, std::vector<std::string> moving_patches,
             std::vector<std::string> fixed_patches, MeshMotionOptions options = {});

  // Moves the mesh to reference + displacement: one displacement per moving node, in
  // moving_nodes() order. Throws InputError on a wrong count, MeshError if a cell inverts.
  void move(std::span<const Vec3> moving_node_displacement);

  // Nodes of the moving patches, sorted.
  std::span<const Index> moving_nodes() const { return moving_nodes_; }
  const std::vector<Vec3>& reference_nodes() const { return reference_; }
  // Displacement of every node at the last successful move().
  const std::vector<Vec3>& node_displacement() const { return displacement_; }
  // min over cells of current volume / reference volume (1 before any move).
  Real min_volume_ratio() const;

 private:
  enum class Role { Free, Moving, Fixed, Sliding };
  void project_sliding(Index node, Vec3& d) const;

  Mesh& mesh_;
  MeshMotionOptions options_;
  std::vector<Vec3> reference_;
  std::vector<Real> reference_volume_;
  std::vector<Role> role_;
  std::vector<Index> moving_nodes_;
  std::vector<Index> moving_slot_;  // node -> position in moving_nodes_, or -1
  // Free and sliding nodes: nearest moving node (as a node index) and blend factor s.
  std::vector<Index> blended_nodes_, nearest_moving_;
  std::vector<Real> blend_;
  // Sliding nodes: orthonormal normals to remove (CSR by node).
  std::vector<Index> normal_offsets_;
  std::vector<Vec3> normals_;
  // Edge graph with spring weights (CSR by node).
  std::vector<Index> edge_offsets_, edge_nodes_;
  std::vector<Real> edge_weights_;
  std::vector<Vec3> displacement_;
};

}  // namespace rfmems

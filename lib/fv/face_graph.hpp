// The geometry a first-order finite-volume transport operator needs, and nothing more: cell
// volumes and centroids, and faces (owner, neighbour, outward area vector, patch).
//
// Why not the Mesh itself: the kinetic gas solver runs on the Mesh's cells and on coarse
// levels made by agglomerating them (COMET's geometric multigrid, thesis ch. 5), whose
// cells are unions of fine cells with no node lists. Both are a FaceGraph, so one upwind
// discretisation serves every level.
//
// Conventions follow Mesh: face_area[f] points out of face_owner[f]; interior faces first
// (f < n_interior_faces), boundary faces after, each with face_patch[f] >= 0 (interior: -1).
// Cells [0, n_owned_cells) belong to this rank; the rest are ghosts (none in a serial run).
#pragma once
#include <string>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

class Mesh;

struct FaceGraph {
  int dim = 2;
  Index n_owned_cells = 0;
  std::vector<Real> cell_volume;
  std::vector<Vec3> cell_centroid;

  Index n_interior_faces = 0;
  std::vector<Index> face_owner;
  std::vector<Index> face_neighbour;  // -1 on a boundary face
  std::vector<Vec3> face_area;        // outward from the owner, |S_f| = face area
  std::vector<Vec3> face_centroid;
  std::vector<int> face_patch;  // -1 on an interior face
  std::vector<std::string> patch_names;

  // Faces of each cell (CSR): cell_faces[cell_face_offsets[c] .. cell_face_offsets[c+1]).
  std::vector<Index> cell_face_offsets{0};
  std::vector<Index> cell_faces;

  Index n_cells() const { return static_cast<Index>(cell_volume.size()); }
  Index n_faces() const { return static_cast<Index>(face_owner.size()); }
  bool is_boundary(Index f) const { return f >= n_interior_faces; }
  // Index of the patch with this name, -1 if absent.
  int find_patch(const std::string& name) const;
  // Rebuilds cell_faces from face_owner / face_neighbour.
  void build_cell_faces();
};

FaceGraph face_graph_of(const Mesh& mesh);

}  // namespace rfmems

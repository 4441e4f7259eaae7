// Cell-centred finite-volume mesh, 2D (polygons, unit depth) or 3D (general polyhedra).
//
// Geometry conventions:
//  - face_area(f) is the area vector S_f, outward from face_owner(f); |S_f| is the face area
//    (2D: edge length times unit depth, S_z = 0).
//  - Interior faces come first (f < n_interior_faces()); boundary faces follow, grouped by
//    patch, so patch(p).faces is a contiguous range.
//  - cell_volume is the area in 2D (unit depth).
//  - Cells [0, n_owned_cells()) belong to this rank; the rest are ghost copies of cells owned
//    by other ranks (none in a serial run). global_cell_id maps local to global numbering.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

enum class CellShape { Triangle, Quad, Polygon, Tetra, Hexa, Prism, Pyramid };

struct Patch {
  std::string name;
  Index first_face = 0;  // boundary faces [first_face, first_face + n_faces)
  Index n_faces = 0;
};

class Mesh {
 public:
  int dim() const { return dim_; }
  Index n_nodes() const { return static_cast<Index>(nodes_.size()); }
  Index n_cells() const { return static_cast<Index>(cell_shape_.size()); }
  Index n_owned_cells() const { return n_owned_cells_; }
  Index n_faces() const { return static_cast<Index>(face_owner_.size()); }
  Index n_interior_faces() const { return n_interior_faces_; }

  // Nodes (for output and mesh motion).
  const std::vector<Vec3>& nodes() const { return nodes_; }

  // Cells.
  CellShape cell_shape(Index c) const { return cell_shape_[c]; }
  std::span<const Index> cell_nodes(Index c) const;
  std::span<const Index> cell_faces(Index c) const;
  const Vec3& cell_centroid(Index c) const { return cell_centroid_[c]; }
  std::span<const Vec3> cell_centroids() const { return cell_centroid_; }
  Real cell_volume(Index c) const { return cell_volume_[c]; }
  Index global_cell_id(Index c) const { return global_cell_id_[c]; }

  // Faces.
  Index face_owner(Index f) const { return face_owner_[f]; }
  // Neighbour cell, or -1 on a boundary face.
  Index face_neighbour(Index f) const { return face_neighbour_[f]; }
  bool is_boundary(Index f) const { return f >= n_interior_faces_; }
  const Vec3& face_area(Index f) const { return face_area_[f]; }
  const Vec3& face_centroid(Index f) const { return face_centroid_[f]; }
  std::span<const Index> face_nodes(Index f) const;
  // Patch index of a boundary face, -1 for an interior face.
  int face_patch(Index f) const {
    return f < n_interior_faces_ ? -1 : face_patch_[f - n_interior_faces_];
  }

  // Patches.
  const std::vector<Patch>& patches() const { return patches_; }
  // Index of the patch with this name, -1 if absent.
  int find_patch(const std::string& name) const;
  // The nodes of the faces of patch p, sorted and unique.
  std::vector<Index> patch_nodes(int p) const;

  // Moves the nodes and recomputes all geometry; throws MeshError if a cell inverts.
  void set_node_coordinates(std::vector<Vec3> nodes);

  // Throws MeshError naming the first cell or face that has non-positive volume, zero area,
  // or an area vector that points into its owner.
  void check_quality() const;

  // Smallest and largest cell size (volume^(1/dim)); handy for CFL numbers and reports.
  Real min_cell_size() const;
  Real max_cell_size() const;

 private:
  friend class MeshBuilder;
  void compute_geometry();

  int dim_ = 2;
  std::vector<Vec3> nodes_;

  std::vector<CellShape> cell_shape_;
  std::vector<Index> cell_node_offsets_{0}, cell_node_list_;
  std::vector<Index> cell_face_offsets_{0}, cell_face_list_;
  std::vector<Vec3> cell_centroid_;
  std::vector<Real> cell_volume_;
  std::vector<Index> global_cell_id_;
  Index n_owned_cells_ = 0;

  std::vector<Index> face_owner_, face_neighbour_;
  std::vector<Index> face_node_offsets_{0}, face_node_list_;
  std::vector<Vec3> face_area_, face_centroid_;
  std::vector<int> face_patch_;  // for boundary faces only
  Index n_interior_faces_ = 0;
  std::vector<Patch> patches_;
};

// Assembles a Mesh from nodes, cells (by node list, in Gmsh/VTK node order) and tagged
// boundary faces. Faces are found from the cells; a boundary face gets the patch of the
// tagged face with the same nodes, or `default_patch` if it has none.
class MeshBuilder {
 public:
  explicit MeshBuilder(int dim);
  Index add_node(const Vec3& x);
  Index add_cell(CellShape shape, std::vector<Index> nodes);
  // Tags a boundary face (2D: an edge of two nodes; 3D: a polygon) with a patch name.
  void add_boundary_face(std::vector<Index> nodes, const std::string& patch);
  // Builds faces, geometry, and checks quality (throws MeshError). `source` names the file
  // or generator in error messages.
  Mesh build(const std::string& source, const std::string& default_patch = "unassigned");
  // A mesh with no cells: the part of a rank that METIS left empty (build() refuses one).
  Mesh build_empty() const;

  Index n_nodes() const { return static_cast<Index>(nodes_.size()); }
  Index n_cells() const { return static_cast<Index>(cells_.size()); }
  // Marks cells [0, n_owned) as owned by this rank and the rest as ghosts, with their global
  // numbers (default: all owned, global = local).
  void set_ownership(Index n_owned, std::vector<Index> global_ids);
  // Reverses the node order of every cell: a 2D mesh drawn clockwise becomes counterclockwise.
  void reverse_all_cells();
  // Signed area (2D) or volume (3D) of cell c from its node order.
  Real signed_measure(Index c) const;

 private:
  int dim_;
  std::vector<Vec3> nodes_;
  std::vector<std::pair<CellShape, std::vector<Index>>> cells_;
  std::vector<std::pair<std::vector<Index>, std::string>> tagged_faces_;
  Index n_owned_ = -1;
  std::vector<Index> global_ids_;
};

// The faces of a cell as node lists, each ordered so its normal points out of the cell
// (right-hand rule). 2D cells give their edges.
std::vector<std::vector<Index>> cell_face_nodes(int dim, CellShape shape,
                                                std::span<const Index> nodes);

}  // namespace rfmems

// Marking of a fixed 2D background FV mesh against an immersed body (thesis ch. 6,
// after the 8 steps of its ref. [135]):
//
//   1. IB cells: the cells whose interior the body's surface cuts. Candidates come from a
//      Boost.Geometry R-tree of the background cells' bounding boxes (built once), queried
//      with each surface segment's box; the exact test is the DE-9IM relation "the interiors
//      of the segment and of the cell polygon intersect" (bg::relate, mask T********).
//   2. FLUID cells: a flood fill over faces from the uncut cells that touch the outer
//      boundary and lie outside the body, into every uncut neighbour whose centroid lies
//      outside the body. An uncut cell lies wholly on one side of the surface, so between two
//      uncut cells a face lies on the surface (a body edge along a grid line) exactly when
//      their centroids are on opposite sides; the centroid test (crossing number) is the
//      robust form of "the face is on the surface" when the surface runs within round-off of
//      a grid line, where an exact overlap test and the cut test can disagree.
//   3. SOLID cells: the rest (inside the body, or, rarely, fluid pockets the flood cannot
//      reach because a layer of IB cells closes them off: counted in n_unreached_outside).
//
// Rule for a cut cell whose centroid lies inside the body (or outside): it is an IB cell
// whatever its centroid, as in the thesis. The IB cells then form a closed layer around the
// body, the fluid domain (the FLUID cells) is bounded by IB faces that lie at most one cell
// from the surface, and which side a centroid falls on (a round-off question for a surface
// through it) never decides a class. `centroid_inside` keeps the side of each cell's
// centroid for later use (cut-cell volume fractions, a sharper rule).
//
// Faces:
//   ImmersedBoundary  between a FLUID cell and a non-FLUID cell: the fluid domain's boundary,
//                     where the gas and the potential take interpolated values. Usually
//                     FLUID | IB; FLUID | SOLID only when the face lies on the surface.
//   Solid             between two non-FLUID cells, or a boundary face of a non-FLUID cell
//   Fluid             between two FLUID cells, or a boundary face of a FLUID cell
//
// Slivers (snap_fraction). A surface at or within a few nm of a grid line cuts slivers off the
// cells beside it, e.g. the switch's tip face (on x = 45 um at rest) that bending tilts by
// ~1 nm: the sliver cells turn IB, and IB faces appear whose normal is not the wall's (a
// horizontal face beside a vertical wall, next to a corner), where the interpolated flux and
// the force eps E_n^2 / 2 are wrong (measured: 4.3e-3 N/m instead of 1.8e-5 N/m on the top of
// the tip, docs/ibm.md "Slivers"). So the marking uses the surface with every vertex within
// snap_fraction of a cell's width of an axis-aligned cell edge moved onto that edge; the
// surface then lies on the grid line (no cut, the FLUID | SOLID faces of the robust centroid
// test) and the classes do not change until the surface is snap_fraction h away. The
// interpolation and the transfer keep the true surface: the IB faces' targets lie at most
// snap_fraction h inside the body (a short extrapolation past the wall points). If snapping
// would make the polygon non-simple (a body thinner than 2 snap_fraction h across a grid line)
// the true surface is marked instead (snap_rejected).
//
// Re-marking after the body moved is one call of mark() with the moved surface (the R-tree
// of the background stays). Cost: O(n_segments log n_cells) for the cuts, O(n_cells) for the
// flood, plus a crossing-number test per cell centroid inside the body's bounding box.
#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/types.hpp"
#include "ibm/immersed_surface.hpp"
#include "mesh/mesh.hpp"

namespace rfmems {

enum class CellClass : std::uint8_t { Fluid, Solid, ImmersedBoundary };
enum class FaceClass : std::uint8_t { Fluid, Solid, ImmersedBoundary };

struct CellMarking {
  std::vector<CellClass> cell;        // per background cell
  std::vector<FaceClass> face;        // per background face
  std::vector<bool> centroid_inside;  // per cell: centroid strictly inside the body

  // IB faces in ascending order, with, for each, the FLUID cell beside it and
  // the unit normal pointing out of the fluid (into the body side).
  std::vector<Index> ib_faces;
  std::vector<Index> ib_face_fluid_cell;
  std::vector<Vec3> ib_face_normal;

  // The surface segments that cut each cell (CSR over cells; empty for uncut
  // cells).
  std::vector<Index> cut_offsets;
  std::vector<Index> cut_segments;
  std::span<const Index> segments_cutting(Index c) const {
    return {cut_segments.data() + cut_offsets[c],
            static_cast<std::size_t>(cut_offsets[c + 1] - cut_offsets[c])};
  }

  // Uncut cells outside the body that the flood fill did not reach (marked
  // SOLID).
  Index n_unreached_outside = 0;
  // Surface vertices moved onto a grid line for the marking; true if the snapped polygon was
  // not simple and the true surface was marked.
  Index n_snapped_vertices = 0;
  bool snap_rejected = false;

  Index count(CellClass k) const;
  Index count(FaceClass k) const;
  std::vector<Index> cells_of(CellClass k) const;
  // Total area (2D volume) of the cells of class k.
  Real area(const Mesh& mesh, CellClass k) const;
};

struct CellMarkingOptions {
  // Vertices within this fraction of the cell's width (per direction) of an axis-aligned
  // cell edge are moved onto it for the marking; 0 disables. 0.1: the IB faces' targets stay
  // within 0.1 h of the wall (inside), below the method's own O(h) wall offset, and it covers
  // the switch tip face's axial motion (0.025 h_x at pull-in on 150 x 50). docs/ibm.md.
  Real snap_fraction = 0.1;
};

class CellMarker {
 public:
  // Indexes the cells of a 2D background mesh (MeshError otherwise). The mesh
  // must outlive the marker and keep its geometry.
  explicit CellMarker(const Mesh& background, CellMarkingOptions options = {});
  ~CellMarker();
  CellMarker(const CellMarker&) = delete;
  CellMarker& operator=(const CellMarker&) = delete;

  CellMarking mark(const ImmersedSurface& body) const;
  // The surface the marking uses: `body` with its vertices snapped to nearby grid lines
  // (counted in *n_snapped), or `body` itself if that would not be a simple polygon.
  ImmersedSurface snapped(const ImmersedSurface& body, Index* n_snapped = nullptr,
                          bool* rejected = nullptr) const;
  const CellMarkingOptions& options() const { return options_; }

  const Mesh& mesh() const { return mesh_; }

 private:
  struct Index2D;
  const Mesh& mesh_;
  CellMarkingOptions options_;
  std::unique_ptr<Index2D> index_;
};

}  // namespace rfmems

#include "ibm/fluid_face_graph.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace rfmems {

FluidFaceGraph fluid_face_graph(const FaceGraph& bg, const CellMarking& marking) {
  FluidFaceGraph out;
  FaceGraph& g = out.graph;
  g.dim = bg.dim;
  out.fluid_cell.assign(bg.n_cells(), -1);
  for (Index c = 0; c < bg.n_cells(); ++c) {
    if (marking.cell[c] != CellClass::Fluid) continue;
    out.fluid_cell[c] = static_cast<Index>(out.background_cell.size());
    out.background_cell.push_back(c);
    g.cell_volume.push_back(bg.cell_volume[c]);
    g.cell_centroid.push_back(bg.cell_centroid[c]);
  }
  g.n_owned_cells = g.n_cells();
  if (g.n_cells() == 0) throw MeshError("fluid face graph: no FLUID cell");
  g.patch_names = bg.patch_names;
  g.patch_names.push_back("immersed");
  out.immersed_patch = static_cast<int>(g.patch_names.size()) - 1;

  auto add = [&](Index owner, Index neighbour, const Vec3& area, const Vec3& centroid, int patch,
                 Index ib) {
    g.face_owner.push_back(owner);
    g.face_neighbour.push_back(neighbour);
    g.face_area.push_back(area);
    g.face_centroid.push_back(centroid);
    g.face_patch.push_back(patch);
    out.ib_face.push_back(ib);
  };
  // Interior faces first (both sides FLUID).
  for (Index f = 0; f < bg.n_interior_faces; ++f) {
    const Index a = out.fluid_cell[bg.face_owner[f]], b = out.fluid_cell[bg.face_neighbour[f]];
    if (a >= 0 && b >= 0) add(a, b, bg.face_area[f], bg.face_centroid[f], -1, -1);
  }
  g.n_interior_faces = g.n_faces();
  // Outer boundary faces of FLUID cells.
  for (Index f = bg.n_interior_faces; f < bg.n_faces(); ++f) {
    const Index a = out.fluid_cell[bg.face_owner[f]];
    if (a >= 0) add(a, -1, bg.face_area[f], bg.face_centroid[f], bg.face_patch[f], -1);
  }
  // IB faces, in the marking's order, oriented out of the fluid.
  for (std::size_t k = 0; k < marking.ib_faces.size(); ++k) {
    const Index f = marking.ib_faces[k];
    const Index cf = marking.ib_face_fluid_cell[k];
    const Vec3 S = bg.face_owner[f] == cf ? bg.face_area[f] : Vec3(-bg.face_area[f]);
    add(out.fluid_cell[cf], -1, S, bg.face_centroid[f], out.immersed_patch, static_cast<Index>(k));
  }
  g.build_cell_faces();
  return out;
}

}  // namespace rfmems

#include "fv/face_graph.hpp"

#include "mesh/mesh.hpp"

namespace rfmems {

int FaceGraph::find_patch(const std::string& name) const {
  for (std::size_t p = 0; p < patch_names.size(); ++p)
    if (patch_names[p] == name) return static_cast<int>(p);
  return -1;
}

void FaceGraph::build_cell_faces() {
  const Index nc = n_cells();
  std::vector<Index> count(nc, 0);
  for (Index f = 0; f < n_faces(); ++f) {
    ++count[face_owner[f]];
    if (face_neighbour[f] >= 0) ++count[face_neighbour[f]];
  }
  cell_face_offsets.assign(nc + 1, 0);
  for (Index c = 0; c < nc; ++c) cell_face_offsets[c + 1] = cell_face_offsets[c] + count[c];
  cell_faces.assign(cell_face_offsets[nc], 0);
  std::vector<Index> next(cell_face_offsets.begin(), cell_face_offsets.end() - 1);
  for (Index f = 0; f < n_faces(); ++f) {
    cell_faces[next[face_owner[f]]++] = f;
    if (face_neighbour[f] >= 0) cell_faces[next[face_neighbour[f]]++] = f;
  }
}

FaceGraph face_graph_of(const Mesh& mesh) {
  FaceGraph g;
  g.dim = mesh.dim();
  g.n_owned_cells = mesh.n_owned_cells();
  const Index nc = mesh.n_cells();
  g.cell_volume.resize(nc);
  g.cell_centroid.resize(nc);
  for (Index c = 0; c < nc; ++c) {
    g.cell_volume[c] = mesh.cell_volume(c);
    g.cell_centroid[c] = mesh.cell_centroid(c);
  }
  g.n_interior_faces = mesh.n_interior_faces();
  const Index nf = mesh.n_faces();
  g.face_owner.resize(nf);
  g.face_neighbour.resize(nf);
  g.face_area.resize(nf);
  g.face_centroid.resize(nf);
  g.face_patch.resize(nf);
  for (Index f = 0; f < nf; ++f) {
    g.face_owner[f] = mesh.face_owner(f);
    g.face_neighbour[f] = mesh.face_neighbour(f);
    g.face_area[f] = mesh.face_area(f);
    g.face_centroid[f] = mesh.face_centroid(f);
    g.face_patch[f] = mesh.face_patch(f);
  }
  for (const Patch& p : mesh.patches()) g.patch_names.push_back(p.name);
  g.build_cell_faces();
  return g;
}

}  // namespace rfmems

#include "fv/agglomeration.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "core/error.hpp"

namespace rfmems {
namespace {

// The other cell of interior face f seen from cell c.
Index across(const FaceGraph& g, Index f, Index c) {
  return g.face_owner[f] == c ? g.face_neighbour[f] : g.face_owner[f];
}

// Coarse index of every fine cell (pairs, then singletons joined to a neighbouring group).
std::vector<Index> pair_cells(const FaceGraph& fine, Index& n_coarse) {
  const Index nc = fine.n_cells();
  std::vector<Index> group(nc, -1);
  n_coarse = 0;
  for (Index c = 0; c < nc; ++c) {
    if (group[c] >= 0) continue;
    Index best = -1;
    Real best_area = -1;
    for (Index i = fine.cell_face_offsets[c]; i < fine.cell_face_offsets[c + 1]; ++i) {
      const Index f = fine.cell_faces[i];
      if (fine.is_boundary(f)) continue;
      const Index n = across(fine, f, c);
      if (n == c || group[n] >= 0) continue;
      const Real a = fine.face_area[f].norm();
      if (a > best_area) best_area = a, best = n;
    }
    if (best >= 0) group[c] = group[best] = n_coarse++;
  }
  // Singletons: join the group sharing the largest total face area; if none of the
  // neighbours is grouped yet (only when they are singletons too), open a new group.
  for (Index c = 0; c < nc; ++c) {
    if (group[c] >= 0) continue;
    std::map<Index, Real> shared;
    for (Index i = fine.cell_face_offsets[c]; i < fine.cell_face_offsets[c + 1]; ++i) {
      const Index f = fine.cell_faces[i];
      if (fine.is_boundary(f)) continue;
      const Index n = across(fine, f, c);
      if (group[n] >= 0) shared[group[n]] += fine.face_area[f].norm();
    }
    Index best = -1;
    Real best_area = -1;
    for (const auto& [g, a] : shared)
      if (a > best_area) best_area = a, best = g;
    group[c] = best >= 0 ? best : n_coarse++;
  }
  return group;
}

}  // namespace

Agglomeration agglomerate(const FaceGraph& fine) {
  if (fine.n_owned_cells != fine.n_cells())
    throw InputError("agglomerate: ghost cells are not supported (serial meshes only)");
  Agglomeration a;
  Index nc = 0;
  a.coarse_of_fine = pair_cells(fine, nc);
  FaceGraph& g = a.coarse;
  g.dim = fine.dim;
  g.n_owned_cells = nc;
  g.patch_names = fine.patch_names;
  g.cell_volume.assign(nc, 0.0);
  g.cell_centroid.assign(nc, Vec3::Zero());
  for (Index c = 0; c < fine.n_cells(); ++c) {
    const Index k = a.coarse_of_fine[c];
    g.cell_volume[k] += fine.cell_volume[c];
    g.cell_centroid[k] += fine.cell_volume[c] * fine.cell_centroid[c];
  }
  for (Index k = 0; k < nc; ++k) g.cell_centroid[k] /= g.cell_volume[k];

  // Merged faces keyed by (owner, neighbour) with owner < neighbour for interior faces and
  // (cell, patch) for boundary faces; centroids accumulate |S|-weighted.
  struct Merged {
    Vec3 area = Vec3::Zero();
    Vec3 centroid_sum = Vec3::Zero();
    Real weight = 0;
  };
  std::map<std::pair<Index, Index>, Merged> interior;
  std::map<std::pair<int, Index>, Merged> boundary;  // key (patch, cell): grouped by patch
  for (Index f = 0; f < fine.n_faces(); ++f) {
    const Index o = a.coarse_of_fine[fine.face_owner[f]];
    const Real w = fine.face_area[f].norm();
    if (fine.is_boundary(f)) {
      Merged& m = boundary[{fine.face_patch[f], o}];
      m.area += fine.face_area[f];
      m.centroid_sum += w * fine.face_centroid[f];
      m.weight += w;
      continue;
    }
    const Index n = a.coarse_of_fine[fine.face_neighbour[f]];
    if (o == n) continue;  // inside a coarse cell
    Merged& m = interior[{std::min(o, n), std::max(o, n)}];
    m.area += o < n ? Vec3(fine.face_area[f]) : Vec3(-fine.face_area[f]);
    m.centroid_sum += w * fine.face_centroid[f];
    m.weight += w;
  }
  auto add_face = [&g](Index owner, Index neighbour, const Merged& m, int patch) {
    g.face_owner.push_back(owner);
    g.face_neighbour.push_back(neighbour);
    g.face_area.push_back(m.area);
    g.face_centroid.push_back(m.weight > 0 ? Vec3(m.centroid_sum / m.weight) : Vec3::Zero());
    g.face_patch.push_back(patch);
  };
  for (const auto& [key, m] : interior) add_face(key.first, key.second, m, -1);
  g.n_interior_faces = g.n_faces();
  for (const auto& [key, m] : boundary) add_face(key.second, -1, m, key.first);
  g.build_cell_faces();
  return a;
}

std::vector<Agglomeration> agglomeration_hierarchy(const FaceGraph& fine, Index min_cells,
                                                   int max_levels) {
  std::vector<Agglomeration> levels;
  const FaceGraph* current = &fine;
  while (static_cast<int>(levels.size()) < max_levels) {
    Agglomeration next = agglomerate(*current);
    const Index n_fine = current->n_cells(), n_coarse = next.coarse.n_cells();
    if (n_coarse < min_cells || 4 * n_coarse > 3 * n_fine) break;
    levels.push_back(std::move(next));
    current = &levels.back().coarse;  // valid until the next push_back, which follows its use
  }
  return levels;
}

}  // namespace rfmems

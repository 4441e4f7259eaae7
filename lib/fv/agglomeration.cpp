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

// Coarse index of every owned fine cell (pairs, then singletons joined to a neighbouring
// group), pairing owned cells with owned neighbours only; ghosts stay -1.
std::vector<Index> pair_cells(const FaceGraph& fine, Index& n_coarse) {
  const Index nc = fine.n_owned_cells;
  std::vector<Index> group(fine.n_cells(), -1);
  n_coarse = 0;
  for (Index c = 0; c < nc; ++c) {
    if (group[c] >= 0) continue;
    Index best = -1;
    Real best_area = -1;
    for (Index i = fine.cell_face_offsets[c]; i < fine.cell_face_offsets[c + 1]; ++i) {
      const Index f = fine.cell_faces[i];
      if (fine.is_boundary(f)) continue;
      const Index n = across(fine, f, c);
      if (n == c || n >= nc || group[n] >= 0) continue;
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
      if (n < nc && group[n] >= 0) shared[group[n]] += fine.face_area[f].norm();
    }
    Index best = -1;
    Real best_area = -1;
    for (const auto& [g, a] : shared)
      if (a > best_area) best_area = a, best = g;
    group[c] = best >= 0 ? best : n_coarse++;
  }
  return group;
}

// Step 6 of the thesis's parallel agglomeration (ch. 5): the owners tell the fine ghosts their
// coarse cells. Numbers the owned coarse cells globally, gives each distinct coarse cell of a fine
// ghost a local ghost index after the owned ones, and completes coarse_of_fine, coarse_global,
// coarse_owner.
Index number_coarse_ghosts(const FaceGraph& fine, const Communicator& comm,
                           const GhostExchange& fine_exchange, Index n_coarse_owned,
                           Agglomeration& a) {
  const Index n_owned = fine.n_owned_cells, n_cells = fine.n_cells();
  const Index offset = comm.exclusive_sum(n_coarse_owned);
  std::vector<Index> tagged(2 * n_cells, -1);  // (coarse global number, owner rank) per cell
  for (Index c = 0; c < n_owned; ++c) {
    tagged[2 * c] = offset + a.coarse_of_fine[c];
    tagged[2 * c + 1] = comm.rank();
  }
  fine_exchange.exchange(std::span<Index>(tagged), 2);
  a.coarse_global.resize(n_coarse_owned);
  for (Index k = 0; k < n_coarse_owned; ++k) a.coarse_global[k] = offset + k;
  a.coarse_owner.assign(n_coarse_owned, comm.rank());
  std::map<Index, Index> ghost_of_global;
  for (Index c = n_owned; c < n_cells; ++c) {
    const Index global = tagged[2 * c];
    if (global < 0)
      throw SolverError("agglomerate: a fine ghost got no coarse cell from its owner");
    auto [it, added] = ghost_of_global.emplace(global, static_cast<Index>(a.coarse_global.size()));
    if (added) {
      a.coarse_global.push_back(global);
      a.coarse_owner.push_back(static_cast<int>(tagged[2 * c + 1]));
    }
    a.coarse_of_fine[c] = it->second;
  }
  return static_cast<Index>(a.coarse_global.size());
}

}  // namespace

Agglomeration agglomerate(const FaceGraph& fine) {
  return agglomerate(fine, Communicator::serial(), nullptr);
}

Agglomeration agglomerate(const FaceGraph& fine, const Communicator& comm,
                          const GhostExchange* fine_exchange) {
  const bool distributed = fine_exchange != nullptr && !comm.is_serial();
  if (!distributed && fine.n_owned_cells != fine.n_cells())
    throw InputError("agglomerate: ghost cells need the fine level's ghost exchange");
  Agglomeration a;
  Index n_owned = 0;
  a.coarse_of_fine = pair_cells(fine, n_owned);
  const Index nc =
      distributed ? number_coarse_ghosts(fine, comm, *fine_exchange, n_owned, a) : n_owned;
  FaceGraph& g = a.coarse;
  g.dim = fine.dim;
  g.n_owned_cells = n_owned;
  g.patch_names = fine.patch_names;
  g.cell_volume.assign(nc, 0.0);
  g.cell_centroid.assign(nc, Vec3::Zero());
  for (Index c = 0; c < fine.n_owned_cells; ++c) {
    const Index k = a.coarse_of_fine[c];
    g.cell_volume[k] += fine.cell_volume[c];
    g.cell_centroid[k] += fine.cell_volume[c] * fine.cell_centroid[c];
  }
  for (Index k = 0; k < n_owned; ++k) g.cell_centroid[k] /= g.cell_volume[k];
  if (distributed) {
    // Coarse ghosts: only part of their fine cells is here; their owners know the whole.
    a.coarse_exchange = GhostExchange(comm, n_owned, a.coarse_global, a.coarse_owner);
    a.coarse_exchange.exchange(g.cell_volume, 1);
    std::vector<Real> x(3 * nc);
    for (Index k = 0; k < nc; ++k)
      for (int d = 0; d < 3; ++d) x[3 * k + d] = g.cell_centroid[k][d];
    a.coarse_exchange.exchange(x, 3);
    for (Index k = n_owned; k < nc; ++k)
      g.cell_centroid[k] = Vec3(x[3 * k], x[3 * k + 1], x[3 * k + 2]);
  }

  // Merged faces keyed by (owner, neighbour) with owner < neighbour for interior faces and
  // (cell, patch) for boundary faces; centroids accumulate |S|-weighted. Faces with no owned
  // side (between ghosts, or a ghost's boundary) carry no equation of this rank: dropped.
  struct Merged {
    Vec3 area = Vec3::Zero();
    Vec3 centroid_sum = Vec3::Zero();
    Real weight = 0;
  };
  std::map<std::pair<Index, Index>, Merged> interior;
  std::map<std::pair<int, Index>, Merged> boundary;  // key (patch, cell): grouped by patch
  const Index fine_owned = fine.n_owned_cells;
  for (Index f = 0; f < fine.n_faces(); ++f) {
    const Index o = a.coarse_of_fine[fine.face_owner[f]];
    const Real w = fine.face_area[f].norm();
    if (fine.is_boundary(f)) {
      if (fine.face_owner[f] >= fine_owned) continue;
      Merged& m = boundary[{fine.face_patch[f], o}];
      m.area += fine.face_area[f];
      m.centroid_sum += w * fine.face_centroid[f];
      m.weight += w;
      continue;
    }
    if (fine.face_owner[f] >= fine_owned && fine.face_neighbour[f] >= fine_owned) continue;
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
                                                   int max_levels, const Communicator& comm,
                                                   const GhostExchange* fine_exchange) {
  std::vector<Agglomeration> levels;
  const FaceGraph* current = &fine;
  const GhostExchange* exchange = fine_exchange;
  while (static_cast<int>(levels.size()) < max_levels) {
    Agglomeration next = agglomerate(*current, comm, exchange);
    const Index n_fine = comm.sum(current->n_owned_cells);
    const Index n_coarse = comm.sum(next.coarse.n_owned_cells);
    if (n_coarse < min_cells || 4 * n_coarse > 3 * n_fine) break;
    levels.push_back(std::move(next));
    // valid until the next push_back, which follows their use
    current = &levels.back().coarse;
    exchange = exchange ? &levels.back().coarse_exchange : nullptr;
  }
  return levels;
}

}  // namespace rfmems

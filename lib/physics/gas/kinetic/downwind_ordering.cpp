#include "physics/gas/kinetic/downwind_ordering.hpp"

#include <cstdint>
#include <map>

namespace rfmems {
namespace {

// Kahn's algorithm on the owned cells; the edge of interior face f goes owner -> neighbour if
// bit f of `owner_upwind` is set, else neighbour -> owner.
DownwindGroup order_cells(const FaceGraph& g, const std::vector<std::uint64_t>& owner_upwind) {
  const Index nc = g.n_owned_cells;
  auto is_set = [&](Index f) { return (owner_upwind[f / 64] >> (f % 64)) & 1u; };
  std::vector<Index> in_degree(nc, 0);
  auto owned = [&](Index c) { return c >= 0 && c < nc; };
  for (Index f = 0; f < g.n_interior_faces; ++f) {
    const Index o = g.face_owner[f], n = g.face_neighbour[f];
    if (!owned(o) || !owned(n)) continue;
    ++in_degree[is_set(f) ? n : o];
  }
  DownwindGroup group;
  group.cells.reserve(nc);
  std::vector<Index> ready;
  std::vector<bool> done(nc, false);
  for (Index c = nc - 1; c >= 0; --c)
    if (in_degree[c] == 0) ready.push_back(c);
  Index next_forced = 0;
  while (static_cast<Index>(group.cells.size()) < nc) {
    if (ready.empty()) {
      while (done[next_forced]) ++next_forced;
      ready.push_back(next_forced);
      in_degree[next_forced] = 0;
      ++group.n_forced;
    }
    const Index c = ready.back();
    ready.pop_back();
    if (done[c]) continue;
    done[c] = true;
    group.cells.push_back(c);
    for (Index i = g.cell_face_offsets[c]; i < g.cell_face_offsets[c + 1]; ++i) {
      const Index f = g.cell_faces[i];
      if (g.is_boundary(f)) continue;
      const Index o = g.face_owner[f], n = g.face_neighbour[f];
      if (!owned(o) || !owned(n)) continue;
      const Index downwind = is_set(f) ? n : o;
      if (downwind == c || done[downwind]) continue;
      if (--in_degree[downwind] == 0) ready.push_back(downwind);
    }
  }
  return group;
}

}  // namespace

std::vector<DownwindGroup> downwind_groups(const FaceGraph& graph, const VelocityGrid& grid) {
  const Index nf = graph.n_interior_faces;
  const std::size_t words = static_cast<std::size_t>((nf + 63) / 64);
  std::map<std::vector<std::uint64_t>, std::vector<Index>> by_pattern;
  std::vector<std::uint64_t> pattern(words);
  for (Index k = 0; k < grid.size(); ++k) {
    std::fill(pattern.begin(), pattern.end(), 0);
    for (Index f = 0; f < nf; ++f)
      if (grid.c[k].dot(graph.face_area[f]) > 0) pattern[f / 64] |= std::uint64_t{1} << (f % 64);
    by_pattern[pattern].push_back(k);
  }
  std::vector<DownwindGroup> groups;
  groups.reserve(by_pattern.size());
  for (auto& [bits, ordinates] : by_pattern) {
    DownwindGroup group = order_cells(graph, bits);
    group.ordinates = std::move(ordinates);
    groups.push_back(std::move(group));
  }
  return groups;
}

}  // namespace rfmems

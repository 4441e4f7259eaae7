// MeshMotion: blending by nearest moving node, spring smoothing of displacements, sliding on
// side patches, and the validity check. See mesh_motion.hpp for the equations and defaults.
#include "mesh/mesh_motion.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include "core/error.hpp"
#include "io/point_locator.hpp"

namespace rfmems {

namespace {

std::vector<int> patch_ids(const Mesh& mesh, const std::vector<std::string>& names,
                           const char* what) {
  std::vector<int> ids;
  for (const auto& name : names) {
    const int p = mesh.find_patch(name);
    if (p < 0)
      throw InputError(fmt::format("mesh motion: {} patch '{}' is not in the mesh", what, name));
    ids.push_back(p);
  }
  return ids;
}

// Blend factor s(r_m, r_f) of the header: 1 on the moving wall, 0 on the fixed wall.
Real blend_factor(Real r_moving, Real r_fixed, Real r0) {
  if (!std::isfinite(r_fixed)) return r0 > 0 ? std::exp(-r_moving / r0) : 1.0;
  if (r_moving + r_fixed <= 0) return 0.0;
  if (r0 <= 0) return r_fixed / (r_moving + r_fixed);
  // (e^-a - e^-b) / (1 - e^-b) with a = r_m/r0, b = (r_m + r_f)/r0, written with expm1 so a
  // large r0 tends to the linear blend without cancellation.
  return std::exp(-r_moving / r0) * std::expm1(-r_fixed / r0) /
         std::expm1(-(r_moving + r_fixed) / r0);
}

}  // namespace

MeshMotion::MeshMotion(Mesh& mesh, std::vector<std::string> moving_patches,
                       std::vector<std::string> fixed_patches, MeshMotionOptions options)
    : mesh_(mesh), options_(options), reference_(mesh.nodes()) {
  if (moving_patches.empty()) throw InputError("mesh motion: no moving patch");
  if (options_.smoothing_sweeps < 0 || !(options_.decay_length >= 0))
    throw InputError("mesh motion: negative smoothing sweeps or decay length");
  const Index nn = mesh.n_nodes();
  const int dim = mesh.dim();
  const auto moving_ids = patch_ids(mesh, moving_patches, "moving");
  const auto fixed_ids = patch_ids(mesh, fixed_patches, "fixed");

  // Roles, by precedence moving > fixed > sliding > free.
  role_.assign(nn, Role::Free);
  std::vector<int> sliding_ids;
  for (int p = 0; p < static_cast<int>(mesh.patches().size()); ++p) {
    const bool listed = std::count(moving_ids.begin(), moving_ids.end(), p) ||
                        std::count(fixed_ids.begin(), fixed_ids.end(), p);
    if (listed) continue;
    if (options_.slide_on_other_patches)
      sliding_ids.push_back(p);
    else
      for (Index n : mesh.patch_nodes(p)) role_[n] = Role::Fixed;
  }
  for (int p : sliding_ids)
    for (Index n : mesh.patch_nodes(p))
      if (role_[n] == Role::Free) role_[n] = Role::Sliding;
  for (int p : fixed_ids)
    for (Index n : mesh.patch_nodes(p)) role_[n] = Role::Fixed;
  for (int p : moving_ids)
    for (Index n : mesh.patch_nodes(p)) role_[n] = Role::Moving;

  moving_slot_.assign(nn, -1);
  std::vector<Vec3> moving_points, fixed_points;
  for (Index n = 0; n < nn; ++n) {
    if (role_[n] == Role::Moving) {
      moving_slot_[n] = static_cast<Index>(moving_nodes_.size());
      moving_nodes_.push_back(n);
      moving_points.push_back(reference_[n]);
    } else if (role_[n] == Role::Fixed) {
      fixed_points.push_back(reference_[n]);
    }
  }

  // Blend factors from the reference positions (moves are relative to the reference).
  PointLocator moving_locator(moving_points, dim);
  std::unique_ptr<PointLocator> fixed_locator;
  if (!fixed_points.empty()) fixed_locator = std::make_unique<PointLocator>(fixed_points, dim);
  for (Index n = 0; n < nn; ++n) {
    if (role_[n] != Role::Free && role_[n] != Role::Sliding) continue;
    const Vec3& x = reference_[n];
    const Index m = moving_locator.nearest(x);
    const Real r_moving = (x - moving_points[m]).norm();
    const Real r_fixed = fixed_locator ? (x - fixed_points[fixed_locator->nearest(x)]).norm()
                                       : std::numeric_limits<Real>::infinity();
    blended_nodes_.push_back(n);
    nearest_moving_.push_back(moving_nodes_[m]);
    blend_.push_back(blend_factor(r_moving, r_fixed, options_.decay_length));
  }

  // Sliding nodes: an orthonormal set of the unit normals of their sliding faces.
  std::vector<std::vector<Vec3>> node_normals(nn);
  for (int p : sliding_ids) {
    const Patch& patch = mesh.patches()[p];
    for (Index f = patch.first_face; f < patch.first_face + patch.n_faces; ++f) {
      const Vec3 unit = mesh.face_area(f).normalized();
      for (Index n : mesh.face_nodes(f)) {
        if (role_[n] != Role::Sliding) continue;
        Vec3 v = unit;
        for (const Vec3& e : node_normals[n]) v -= v.dot(e) * e;
        if (v.norm() > 1e-6) node_normals[n].push_back(v.normalized());  // Gram-Schmidt
      }
    }
  }
  normal_offsets_.assign(1, 0);
  for (Index n = 0; n < nn; ++n) {
    normals_.insert(normals_.end(), node_normals[n].begin(), node_normals[n].end());
    normal_offsets_.push_back(static_cast<Index>(normals_.size()));
  }

  // Edges: consecutive nodes of every face polygon (in 2D a face is an edge).
  std::vector<std::pair<Index, Index>> edges;
  for (Index f = 0; f < mesh.n_faces(); ++f) {
    auto fn = mesh.face_nodes(f);
    const std::size_t m = fn.size();
    for (std::size_t i = 0; i < (m == 2 ? 1 : m); ++i) {
      Index a = fn[i], b = fn[(i + 1) % m];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<std::vector<std::pair<Index, Real>>> adjacency(nn);
  for (auto [a, b] : edges) {
    const Real length = (reference_[a] - reference_[b]).norm();
    if (!(length > 0)) throw MeshError(fmt::format("mesh motion: nodes {} and {} coincide", a, b));
    adjacency[a].emplace_back(b, 1.0 / length);
    adjacency[b].emplace_back(a, 1.0 / length);
  }
  edge_offsets_.assign(1, 0);
  for (Index n = 0; n < nn; ++n) {
    for (auto [j, w] : adjacency[n]) {
      edge_nodes_.push_back(j);
      edge_weights_.push_back(w);
    }
    edge_offsets_.push_back(static_cast<Index>(edge_nodes_.size()));
  }

  reference_volume_.resize(mesh.n_cells());
  for (Index c = 0; c < mesh.n_cells(); ++c) reference_volume_[c] = mesh.cell_volume(c);
  displacement_.assign(nn, Vec3::Zero());
}

void MeshMotion::project_sliding(Index node, Vec3& d) const {
  for (Index k = normal_offsets_[node]; k < normal_offsets_[node + 1]; ++k)
    d -= d.dot(normals_[k]) * normals_[k];
}

void MeshMotion::move(std::span<const Vec3> moving_node_displacement) {
  if (moving_node_displacement.size() != moving_nodes_.size())
    throw InputError(fmt::format("mesh motion: {} displacements for {} moving nodes",
                                 moving_node_displacement.size(), moving_nodes_.size()));
  const Index nn = mesh_.n_nodes();
  std::vector<Vec3> d(nn, Vec3::Zero());
  for (std::size_t i = 0; i < moving_nodes_.size(); ++i) {
    d[moving_nodes_[i]] = moving_node_displacement[i];
    if (mesh_.dim() == 2) d[moving_nodes_[i]].z() = 0;  // 2D meshes stay in the plane
  }
  for (std::size_t i = 0; i < blended_nodes_.size(); ++i) {
    const Index n = blended_nodes_[i];
    d[n] = blend_[i] * d[nearest_moving_[i]];
    if (role_[n] == Role::Sliding) project_sliding(n, d[n]);
  }
  std::vector<Vec3> next = d;
  for (int sweep = 0; sweep < options_.smoothing_sweeps; ++sweep) {
    for (Index n : blended_nodes_) {
      Vec3 sum = Vec3::Zero();
      Real weight = 0;
      for (Index k = edge_offsets_[n]; k < edge_offsets_[n + 1]; ++k) {
        sum += edge_weights_[k] * d[edge_nodes_[k]];
        weight += edge_weights_[k];
      }
      next[n] = sum / weight;
      if (role_[n] == Role::Sliding) project_sliding(n, next[n]);
    }
    std::swap(d, next);
    for (Index n : blended_nodes_) next[n] = d[n];
  }

  std::vector<Vec3> x(nn);
  for (Index n = 0; n < nn; ++n) x[n] = reference_[n] + d[n];
  std::vector<Vec3> previous = mesh_.nodes();
  try {
    mesh_.set_node_coordinates(std::move(x));
  } catch (const MeshError& e) {
    mesh_.set_node_coordinates(std::move(previous));
    throw MeshError(std::string("mesh motion: ") + e.what());
  }
  displacement_ = std::move(d);
}

Real MeshMotion::min_volume_ratio() const {
  Real ratio = std::numeric_limits<Real>::infinity();
  for (Index c = 0; c < mesh_.n_cells(); ++c)
    ratio = std::min(ratio, mesh_.cell_volume(c) / reference_volume_[c]);
  return ratio;
}

}  // namespace rfmems

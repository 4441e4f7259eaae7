// Mesh assembly and geometry. Face area vectors and volumes follow the standard FV
// decomposition (e.g. OpenFOAM's primitiveMesh): a polygon face is split into triangles about
// its node average; a polyhedral cell into pyramids over its faces.
#include "mesh/mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"

namespace rfmems {

namespace {

// Area vector and centroid of a (possibly non-planar) polygon, by a triangle fan about the
// node average.
void polygon_geometry(const std::vector<Vec3>& x, std::span<const Index> nodes, Vec3& area,
                      Vec3& centroid) {
  Vec3 mid = Vec3::Zero();
  for (Index n : nodes) mid += x[n];
  mid /= static_cast<Real>(nodes.size());
  area.setZero();
  Vec3 weighted = Vec3::Zero();
  Real total = 0;
  const std::size_t m = nodes.size();
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3& a = x[nodes[i]];
    const Vec3& b = x[nodes[(i + 1) % m]];
    Vec3 s = 0.5 * (a - mid).cross(b - mid);
    area += s;
    Real w = s.norm();
    weighted += w * (a + b + mid) / 3.0;
    total += w;
  }
  centroid = total > 0 ? Vec3(weighted / total) : mid;
}

std::vector<Index> sorted_key(std::span<const Index> nodes) {
  std::vector<Index> key(nodes.begin(), nodes.end());
  std::sort(key.begin(), key.end());
  return key;
}

}  // namespace

std::vector<std::vector<Index>> cell_face_nodes(int dim, CellShape shape,
                                                std::span<const Index> n) {
  if (dim == 2) {
    // Counterclockwise polygon: edge i -> i+1; outward normal is the edge rotated clockwise.
    std::vector<std::vector<Index>> edges;
    for (std::size_t i = 0; i < n.size(); ++i) edges.push_back({n[i], n[(i + 1) % n.size()]});
    return edges;
  }
  // Gmsh/VTK first-order node order; each face ordered so the right-hand normal points out.
  switch (shape) {
    case CellShape::Tetra:
      return {{n[0], n[2], n[1]}, {n[0], n[1], n[3]}, {n[1], n[2], n[3]}, {n[0], n[3], n[2]}};
    case CellShape::Hexa:
      return {{n[0], n[3], n[2], n[1]}, {n[4], n[5], n[6], n[7]}, {n[0], n[1], n[5], n[4]},
              {n[1], n[2], n[6], n[5]}, {n[2], n[3], n[7], n[6]}, {n[3], n[0], n[4], n[7]}};
    case CellShape::Prism:
      return {{n[0], n[2], n[1]},
              {n[3], n[4], n[5]},
              {n[0], n[1], n[4], n[3]},
              {n[1], n[2], n[5], n[4]},
              {n[2], n[0], n[3], n[5]}};
    case CellShape::Pyramid:
      return {{n[0], n[3], n[2], n[1]},
              {n[0], n[1], n[4]},
              {n[1], n[2], n[4]},
              {n[2], n[3], n[4]},
              {n[3], n[0], n[4]}};
    default:
      throw MeshError("a 2D cell shape in a 3D mesh");
  }
}

// ----------------------------------------------------------------------------------------
std::span<const Index> Mesh::cell_nodes(Index c) const {
  return {cell_node_list_.data() + cell_node_offsets_[c],
          static_cast<std::size_t>(cell_node_offsets_[c + 1] - cell_node_offsets_[c])};
}

std::span<const Index> Mesh::cell_faces(Index c) const {
  return {cell_face_list_.data() + cell_face_offsets_[c],
          static_cast<std::size_t>(cell_face_offsets_[c + 1] - cell_face_offsets_[c])};
}

std::span<const Index> Mesh::face_nodes(Index f) const {
  return {face_node_list_.data() + face_node_offsets_[f],
          static_cast<std::size_t>(face_node_offsets_[f + 1] - face_node_offsets_[f])};
}

int Mesh::find_patch(const std::string& name) const {
  for (std::size_t p = 0; p < patches_.size(); ++p)
    if (patches_[p].name == name) return static_cast<int>(p);
  return -1;
}

std::vector<Index> Mesh::patch_nodes(int p) const {
  const Patch& patch = patches_.at(p);
  std::vector<Index> nodes;
  for (Index f = patch.first_face; f < patch.first_face + patch.n_faces; ++f)
    for (Index n : face_nodes(f)) nodes.push_back(n);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

void Mesh::set_node_coordinates(std::vector<Vec3> nodes) {
  if (nodes.size() != nodes_.size()) throw MeshError("set_node_coordinates: wrong node count");
  nodes_ = std::move(nodes);
  compute_geometry();
  check_quality();
}

void Mesh::compute_geometry() {
  const Index nf = n_faces();
  face_area_.assign(nf, Vec3::Zero());
  face_centroid_.assign(nf, Vec3::Zero());
  for (Index f = 0; f < nf; ++f) {
    auto fn = face_nodes(f);
    if (dim_ == 2) {
      const Vec3& a = nodes_[fn[0]];
      const Vec3& b = nodes_[fn[1]];
      Vec3 t = b - a;
      face_area_[f] = Vec3(t.y(), -t.x(), 0.0);  // unit depth
      face_centroid_[f] = 0.5 * (a + b);
    } else {
      polygon_geometry(nodes_, fn, face_area_[f], face_centroid_[f]);
    }
  }
  const Index nc = n_cells();
  cell_volume_.assign(nc, 0.0);
  cell_centroid_.assign(nc, Vec3::Zero());
  for (Index c = 0; c < nc; ++c) {
    if (dim_ == 2) {
      Vec3 area, centroid;
      polygon_geometry(nodes_, cell_nodes(c), area, centroid);
      cell_volume_[c] = area.z();  // signed: negative when the cell is inverted
      cell_centroid_[c] = centroid;
      continue;
    }
    // Pyramids from the node average to each face; the face's sign relative to this cell.
    auto cn = cell_nodes(c);
    Vec3 mid = Vec3::Zero();
    for (Index n : cn) mid += nodes_[n];
    mid /= static_cast<Real>(cn.size());
    Real volume = 0;
    Vec3 weighted = Vec3::Zero();
    for (Index f : cell_faces(c)) {
      Real sign = face_owner_[f] == c ? 1.0 : -1.0;
      Real v = sign * face_area_[f].dot(face_centroid_[f] - mid) / 3.0;
      volume += v;
      weighted += v * (0.75 * face_centroid_[f] + 0.25 * mid);
    }
    cell_volume_[c] = volume;
    cell_centroid_[c] = volume != 0 ? Vec3(weighted / volume) : mid;
  }
}

void Mesh::check_quality() const {
  for (Index c = 0; c < n_cells(); ++c) {
    if (!(cell_volume_[c] > 0))
      throw MeshError(fmt::format(
          "cell {} at ({:.4g}, {:.4g}, {:.4g}) is inverted or degenerate "
          "(volume {:.3g})",
          c, cell_centroid_[c].x(), cell_centroid_[c].y(), cell_centroid_[c].z(), cell_volume_[c]));
  }
  Real size = min_cell_size();
  Real tiny = 1e-12 * std::pow(size, dim_ - 1);
  for (Index f = 0; f < n_faces(); ++f) {
    if (!(face_area_[f].norm() > tiny))
      throw MeshError(fmt::format("face {} at ({:.4g}, {:.4g}, {:.4g}) has zero area", f,
                                  face_centroid_[f].x(), face_centroid_[f].y(),
                                  face_centroid_[f].z()));
    // The area vector must point out of the owner: from the owner's centroid to the face.
    Vec3 d = face_centroid_[f] - cell_centroid_[face_owner_[f]];
    if (face_area_[f].dot(d) <= 0)
      throw MeshError(fmt::format(
          "face {} at ({:.4g}, {:.4g}, {:.4g}) points into its cell {}: "
          "inverted or tangled cell",
          f, face_centroid_[f].x(), face_centroid_[f].y(), face_centroid_[f].z(), face_owner_[f]));
  }
}

Real Mesh::min_cell_size() const {
  Real v = *std::min_element(cell_volume_.begin(), cell_volume_.end());
  return std::pow(std::max(v, 0.0), 1.0 / dim_);
}

Real Mesh::max_cell_size() const {
  Real v = *std::max_element(cell_volume_.begin(), cell_volume_.end());
  return std::pow(v, 1.0 / dim_);
}

// ----------------------------------------------------------------------------------------
MeshBuilder::MeshBuilder(int dim) : dim_(dim) {
  if (dim != 2 && dim != 3) throw MeshError(fmt::format("mesh dimension {} is not 2 or 3", dim));
}

Index MeshBuilder::add_node(const Vec3& x) {
  nodes_.push_back(x);
  return static_cast<Index>(nodes_.size()) - 1;
}

Index MeshBuilder::add_cell(CellShape shape, std::vector<Index> nodes) {
  cells_.emplace_back(shape, std::move(nodes));
  return static_cast<Index>(cells_.size()) - 1;
}

void MeshBuilder::add_boundary_face(std::vector<Index> nodes, const std::string& patch) {
  tagged_faces_.emplace_back(std::move(nodes), patch);
}

void MeshBuilder::set_ownership(Index n_owned, std::vector<Index> global_ids) {
  n_owned_ = n_owned;
  global_ids_ = std::move(global_ids);
}

void MeshBuilder::reverse_all_cells() {
  for (auto& cell : cells_) std::reverse(cell.second.begin(), cell.second.end());
}

Real MeshBuilder::signed_measure(Index c) const {
  const auto& [shape, nodes] = cells_[c];
  if (dim_ == 2) {
    Vec3 area, centroid;
    polygon_geometry(nodes_, nodes, area, centroid);
    return area.z();
  }
  Vec3 mid = Vec3::Zero();
  for (Index n : nodes) mid += nodes_[n];
  mid /= static_cast<Real>(nodes.size());
  Real volume = 0;
  for (const auto& face : cell_face_nodes(dim_, shape, nodes)) {
    Vec3 area, centroid;
    polygon_geometry(nodes_, face, area, centroid);
    volume += area.dot(centroid - mid) / 3.0;
  }
  return volume;
}

Mesh MeshBuilder::build_empty() const {
  Mesh mesh;
  mesh.dim_ = dim_;
  return mesh;
}

Mesh MeshBuilder::build(const std::string& source, const std::string& default_patch) {
  Mesh mesh;
  mesh.dim_ = dim_;
  mesh.nodes_ = nodes_;
  const Index nc = n_cells();
  if (nc == 0) throw MeshError(source + ": mesh has no cells");

  // Faces of every cell, matched by their sorted node lists.
  struct RawFace {
    std::vector<Index> nodes;
    Index owner, neighbour = -1;
  };
  std::vector<RawFace> raw;
  std::map<std::vector<Index>, Index> by_key;
  std::vector<std::vector<Index>> cell_raw_faces(nc);
  for (Index c = 0; c < nc; ++c) {
    const auto& [shape, nodes] = cells_[c];
    for (Index n : nodes)
      if (n < 0 || n >= n_nodes())
        throw MeshError(fmt::format("{}: cell {} references missing node {}", source, c, n));
    for (auto& fn : cell_face_nodes(dim_, shape, nodes)) {
      auto key = sorted_key(fn);
      auto it = by_key.find(key);
      if (it == by_key.end()) {
        by_key.emplace(std::move(key), static_cast<Index>(raw.size()));
        cell_raw_faces[c].push_back(static_cast<Index>(raw.size()));
        raw.push_back({std::move(fn), c});
      } else {
        RawFace& face = raw[it->second];
        if (face.neighbour >= 0)
          throw MeshError(
              fmt::format("{}: a face of cell {} is shared by more than two cells", source, c));
        face.neighbour = c;
        cell_raw_faces[c].push_back(it->second);
      }
    }
  }

  // Patch of each boundary face from the tagged faces.
  std::map<std::vector<Index>, std::string> tag_of;
  for (const auto& [nodes, patch] : tagged_faces_) tag_of[sorted_key(nodes)] = patch;
  std::vector<std::string> patch_names;
  auto patch_id = [&](const std::string& name) {
    auto it = std::find(patch_names.begin(), patch_names.end(), name);
    if (it != patch_names.end()) return static_cast<int>(it - patch_names.begin());
    patch_names.push_back(name);
    return static_cast<int>(patch_names.size()) - 1;
  };
  // Keep the tag order so patches appear as the file or generator lists them.
  for (const auto& [nodes, patch] : tagged_faces_) patch_id(patch);

  std::vector<Index> interior, boundary;
  std::vector<int> raw_patch(raw.size(), -1);
  for (Index r = 0; r < static_cast<Index>(raw.size()); ++r) {
    if (raw[r].neighbour >= 0) {
      interior.push_back(r);
    } else {
      auto it = tag_of.find(sorted_key(raw[r].nodes));
      raw_patch[r] = patch_id(it == tag_of.end() ? default_patch : it->second);
      boundary.push_back(r);
    }
  }
  std::stable_sort(boundary.begin(), boundary.end(),
                   [&](Index a, Index b) { return raw_patch[a] < raw_patch[b]; });

  // Final face order: interior, then boundary by patch.
  std::vector<Index> order = interior;
  order.insert(order.end(), boundary.begin(), boundary.end());
  std::vector<Index> new_index(raw.size());
  mesh.n_interior_faces_ = static_cast<Index>(interior.size());
  for (Index f = 0; f < static_cast<Index>(order.size()); ++f) {
    const RawFace& face = raw[order[f]];
    new_index[order[f]] = f;
    mesh.face_owner_.push_back(face.owner);
    mesh.face_neighbour_.push_back(face.neighbour);
    mesh.face_node_list_.insert(mesh.face_node_list_.end(), face.nodes.begin(), face.nodes.end());
    mesh.face_node_offsets_.push_back(static_cast<Index>(mesh.face_node_list_.size()));
    if (face.neighbour < 0) mesh.face_patch_.push_back(raw_patch[order[f]]);
  }
  mesh.patches_.resize(patch_names.size());
  for (std::size_t p = 0; p < patch_names.size(); ++p) mesh.patches_[p].name = patch_names[p];
  for (Index i = 0; i < static_cast<Index>(boundary.size()); ++i) {
    Patch& patch = mesh.patches_[mesh.face_patch_[i]];
    if (patch.n_faces == 0) patch.first_face = mesh.n_interior_faces_ + i;
    ++patch.n_faces;
  }
  // A tagged name with no faces (e.g. a physical group on interior lines) is dropped.
  std::erase_if(mesh.patches_, [](const Patch& p) { return p.n_faces == 0; });
  for (Index i = 0; i < static_cast<Index>(boundary.size()); ++i) {
    Index f = mesh.n_interior_faces_ + i;
    for (std::size_t p = 0; p < mesh.patches_.size(); ++p)
      if (f >= mesh.patches_[p].first_face &&
          f < mesh.patches_[p].first_face + mesh.patches_[p].n_faces)
        mesh.face_patch_[i] = static_cast<int>(p);
  }

  for (Index c = 0; c < nc; ++c) {
    const auto& [shape, nodes] = cells_[c];
    mesh.cell_shape_.push_back(shape);
    mesh.cell_node_list_.insert(mesh.cell_node_list_.end(), nodes.begin(), nodes.end());
    mesh.cell_node_offsets_.push_back(static_cast<Index>(mesh.cell_node_list_.size()));
    for (Index r : cell_raw_faces[c]) mesh.cell_face_list_.push_back(new_index[r]);
    mesh.cell_face_offsets_.push_back(static_cast<Index>(mesh.cell_face_list_.size()));
    mesh.global_cell_id_.push_back(global_ids_.empty() ? c : global_ids_.at(c));
  }
  mesh.n_owned_cells_ = n_owned_ >= 0 ? n_owned_ : nc;

  mesh.compute_geometry();
  try {
    mesh.check_quality();
  } catch (const MeshError& e) {
    throw MeshError(source + ": " + e.what());
  }
  return mesh;
}

}  // namespace rfmems

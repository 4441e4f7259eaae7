// Gap mesh builder and the node map between the beam and the gap. See gap_mesh.hpp.
#include "physics/electrostatics/gap_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.hpp"
#include "io/point_locator.hpp"
#include "mesh/structured_mesh.hpp"

namespace rfmems {

Mesh make_gap_mesh(const GapMeshSpec& spec) {
  const auto& x = spec.x;
  if (x.size() < 2) throw InputError("gap mesh: fewer than two node positions along x");
  for (std::size_t i = 1; i < x.size(); ++i)
    if (!(x[i] > x[i - 1]))
      throw InputError(fmt::format("gap mesh: x positions not increasing at {} ({} after {})", i,
                                   x[i], x[i - 1]));
  if (!(spec.gap > 0)) throw InputError(fmt::format("gap mesh: gap {} is not > 0", spec.gap));
  const std::vector<Real> y = graded_points(-spec.gap, 0.0, spec.n_y, spec.grading_y);
  const int nx = static_cast<int>(x.size()) - 1, ny = spec.n_y;

  MeshBuilder builder(2);
  auto node = [&](int i, int j) -> Index { return static_cast<Index>(j) * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) builder.add_node(Vec3(x[i], y[j], 0.0));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      builder.add_cell(CellShape::Quad,
                       {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)});
  // Tag order fixes the patch order: top first (the moving conductor), then the electrode.
  for (int i = 0; i < nx; ++i) builder.add_boundary_face({node(i, ny), node(i + 1, ny)}, "top");
  int n_electrode = 0;
  for (int i = 0; i < nx; ++i) {
    const Real mid = 0.5 * (x[i] + x[i + 1]);
    const bool on_electrode = mid >= spec.electrode_begin && mid <= spec.electrode_end;
    n_electrode += on_electrode;
    builder.add_boundary_face({node(i, 0), node(i + 1, 0)},
                              on_electrode ? "electrode" : "substrate");
  }
  if (n_electrode == 0)
    throw InputError(fmt::format("gap mesh: no bottom face centre in the electrode [{}, {}]",
                                 spec.electrode_begin, spec.electrode_end));
  for (int j = 0; j < ny; ++j) {
    builder.add_boundary_face({node(0, j), node(0, j + 1)}, "left");
    builder.add_boundary_face({node(nx, j), node(nx, j + 1)}, "right");
  }
  return builder.build("gap mesh generator");
}

std::vector<Real> patch_node_x(const Mesh& mesh, const std::string& patch) {
  const int p = mesh.find_patch(patch);
  if (p < 0) throw InputError(fmt::format("no patch '{}' in the mesh", patch));
  std::vector<Real> x;
  for (Index n : mesh.patch_nodes(p)) x.push_back(mesh.nodes()[n].x());
  std::sort(x.begin(), x.end());
  return x;
}

std::vector<Index> match_nodes(const Mesh& from, std::span<const Index> from_nodes, const Mesh& to,
                               std::span<const Index> to_nodes, Real tolerance) {
  std::vector<Vec3> points;
  for (Index n : from_nodes) points.push_back(from.nodes()[n]);
  if (points.empty()) throw InputError("match_nodes: no nodes to match against");
  PointLocator locator(points, std::max(from.dim(), to.dim()));
  std::vector<Index> match;
  for (Index n : to_nodes) {
    const Vec3& x = to.nodes()[n];
    const Index k = locator.nearest(x);
    const Real distance = (points[k] - x).norm();
    if (distance > tolerance)
      throw MeshError(
          fmt::format("match_nodes: node {} at ({:.6g}, {:.6g}, {:.6g}) has no "
                      "partner within {:.3g} m (nearest {:.3g} m away)",
                      n, x.x(), x.y(), x.z(), tolerance, distance));
    match.push_back(from_nodes[k]);
  }
  return match;
}

}  // namespace rfmems

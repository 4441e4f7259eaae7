#include "mesh/structured_mesh.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"

namespace rfmems {

std::vector<Real> graded_points(Real a, Real b, int n, Real ratio) {
  if (n < 1) throw MeshError(fmt::format("structured mesh: {} cells along an axis", n));
  if (!(ratio > 0)) throw MeshError(fmt::format("structured mesh: grading {} is not > 0", ratio));
  // Sizes s_i = s_0 q^i with q^(n-1) = ratio.
  Real q = n > 1 ? std::pow(ratio, 1.0 / (n - 1)) : 1.0;
  std::vector<Real> sizes(n);
  Real total = 0;
  for (int i = 0; i < n; ++i) total += sizes[i] = std::pow(q, i);
  std::vector<Real> x(n + 1, a);
  for (int i = 0; i < n; ++i) x[i + 1] = x[i] + (b - a) * sizes[i] / total;
  x[n] = b;
  return x;
}

Mesh make_structured_mesh(const BoxSpec& spec, const NodeMap& map) {
  const int dim = spec.dim;
  MeshBuilder builder(dim);
  std::vector<Real> axes[3];
  for (int d = 0; d < 3; ++d)
    axes[d] = d < dim ? graded_points(spec.lower[d], spec.upper[d], spec.n[d], spec.grading[d])
                      : std::vector<Real>{0.0};
  const int nx = spec.n[0], ny = spec.n[1], nz = dim == 3 ? spec.n[2] : 0;
  auto node = [&](int i, int j, int k) -> Index {
    return (static_cast<Index>(k) * (ny + 1) + j) * (nx + 1) + i;
  };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        Vec3 x(axes[0][i], axes[1][j], dim == 3 ? axes[2][k] : 0.0);
        builder.add_node(map ? map(x) : x);
      }

  if (dim == 2) {
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        builder.add_cell(CellShape::Quad, {node(i, j, 0), node(i + 1, j, 0), node(i + 1, j + 1, 0),
                                           node(i, j + 1, 0)});
    for (int j = 0; j < ny; ++j) {
      builder.add_boundary_face({node(0, j, 0), node(0, j + 1, 0)}, "left");
      builder.add_boundary_face({node(nx, j, 0), node(nx, j + 1, 0)}, "right");
    }
    for (int i = 0; i < nx; ++i) {
      builder.add_boundary_face({node(i, 0, 0), node(i + 1, 0, 0)}, "bottom");
      builder.add_boundary_face({node(i, ny, 0), node(i + 1, ny, 0)}, "top");
    }
  } else {
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
          builder.add_cell(CellShape::Hexa,
                           {node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k),
                            node(i, j + 1, k), node(i, j, k + 1), node(i + 1, j, k + 1),
                            node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)});
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j) {
        builder.add_boundary_face(
            {node(0, j, k), node(0, j + 1, k), node(0, j + 1, k + 1), node(0, j, k + 1)}, "left");
        builder.add_boundary_face(
            {node(nx, j, k), node(nx, j + 1, k), node(nx, j + 1, k + 1), node(nx, j, k + 1)},
            "right");
      }
    for (int k = 0; k < nz; ++k)
      for (int i = 0; i < nx; ++i) {
        builder.add_boundary_face(
            {node(i, 0, k), node(i + 1, 0, k), node(i + 1, 0, k + 1), node(i, 0, k + 1)}, "bottom");
        builder.add_boundary_face(
            {node(i, ny, k), node(i + 1, ny, k), node(i + 1, ny, k + 1), node(i, ny, k + 1)},
            "top");
      }
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        builder.add_boundary_face(
            {node(i, j, 0), node(i + 1, j, 0), node(i + 1, j + 1, 0), node(i, j + 1, 0)}, "back");
        builder.add_boundary_face(
            {node(i, j, nz), node(i + 1, j, nz), node(i + 1, j + 1, nz), node(i, j + 1, nz)},
            "front");
      }
  }
  return builder.build(dim == 2 ? "rectangle generator" : "box generator");
}

}  // namespace rfmems

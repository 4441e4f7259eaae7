#include "physics/gas/kinetic/velocity_grid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace rfmems {

VelocityGrid VelocityGrid::uniform(int n1, int n2, int n3, Real extent) {
  return uniform(n1, n2, n3, Vec3(extent, extent, extent));
}

VelocityGrid VelocityGrid::uniform(int n1, int n2, int n3, const Vec3& extent) {
  if (n1 < 2 || n2 < 2 || n3 < 2)
    throw InputError("velocity grid: need at least 2 points per direction, got " +
                     std::to_string(n1) + " x " + std::to_string(n2) + " x " + std::to_string(n3));
  if (!(extent.minCoeff() > 0))
    throw InputError("velocity grid: the extent must be > 0 in every direction");
  VelocityGrid g;
  g.n = {n1, n2, n3};
  g.extent = extent;
  for (int d = 0; d < 3; ++d) g.spacing[d] = 2 * extent[d] / g.n[d];
  g.reference_speed = extent.maxCoeff();
  const Real weight = g.spacing.prod();
  g.c.reserve(Index(n1) * n2 * n3);
  for (int i = 0; i < n1; ++i)
    for (int j = 0; j < n2; ++j)
      for (int l = 0; l < n3; ++l)
        g.c.emplace_back(-extent[0] + (i + 0.5) * g.spacing[0],
                         -extent[1] + (j + 0.5) * g.spacing[1],
                         -extent[2] + (l + 0.5) * g.spacing[2]);
  g.w.assign(g.c.size(), weight);
  return g;
}

Index VelocityGrid::nearest_ordinate(const Vec3& v) const {
  int idx[3];
  for (int d = 0; d < 3; ++d) {
    // Point i sits at -E + (i + 1/2) dc.
    const Real s = (v[d] + extent[d]) / spacing[d] - 0.5;
    idx[d] = std::clamp(static_cast<int>(std::lround(s)), 0, n[d] - 1);
  }
  return index(idx[0], idx[1], idx[2]);
}

Index VelocityGrid::specular_image(Index k, const Vec3& unit_normal) const {
  const Vec3& ck = c[k];
  return nearest_ordinate(ck - 2 * ck.dot(unit_normal) * unit_normal);
}

std::vector<Index> VelocityGrid::reflection_map(const Vec3& unit_normal) const {
  std::vector<Index> map(c.size());
  for (Index k = 0; k < size(); ++k) map[k] = specular_image(k, unit_normal);
  return map;
}

bool VelocityGrid::reflection_is_exact(const Vec3& unit_normal) {
  int axes = 0;
  for (int d = 0; d < 3; ++d)
    if (std::abs(unit_normal[d]) > 1e-12) ++axes;
  return axes == 1;
}

}  // namespace rfmems

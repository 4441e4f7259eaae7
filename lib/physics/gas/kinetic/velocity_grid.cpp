#include "physics/gas/kinetic/velocity_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rfmems {

VelocityGrid VelocityGrid::product(const std::array<VelocityRule, 3>& rule,
                                   const std::array<int, 3>& n, const Vec3& extent, Real stretch,
                                   Real scale) {
  VelocityGrid g;
  g.n = n;
  g.rule = rule;
  g.reference_speed = 0;
  for (int d = 0; d < 3; ++d) {
    const VelocityAxis a = velocity_axis(rule[d], n[d], extent[d], stretch);
    g.axis[d].resize(a.x.size());
    g.axis_weight[d].resize(a.w.size());
    for (std::size_t i = 0; i < a.x.size(); ++i) {
      g.axis[d][i] = scale * a.x[i];
      g.axis_weight[d][i] = scale * a.w[i];
    }
    const bool truncated = velocity_rule_is_truncated(rule[d]);
    g.extent[d] = truncated ? scale * extent[d] : std::numeric_limits<Real>::infinity();
    g.reference_speed = std::max(g.reference_speed, truncated ? g.extent[d] : g.axis[d].back());
  }
  g.c.reserve(Index(n[0]) * n[1] * n[2]);
  g.w.reserve(Index(n[0]) * n[1] * n[2]);
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int l = 0; l < n[2]; ++l) {
        g.c.emplace_back(g.axis[0][i], g.axis[1][j], g.axis[2][l]);
        g.w.push_back(g.axis_weight[0][i] * g.axis_weight[1][j] * g.axis_weight[2][l]);
      }
  return g;
}

VelocityGrid VelocityGrid::uniform(int n1, int n2, int n3, Real extent) {
  return uniform(n1, n2, n3, Vec3(extent, extent, extent));
}

VelocityGrid VelocityGrid::uniform(int n1, int n2, int n3, const Vec3& extent) {
  return product({VelocityRule::Uniform, VelocityRule::Uniform, VelocityRule::Uniform},
                 {n1, n2, n3}, extent, 1.0, 1.0);
}

Index VelocityGrid::nearest_ordinate(const Vec3& v) const {
  // Per direction the nearest node; halfway between two, the upper one.
  int idx[3];
  for (int d = 0; d < 3; ++d) {
    const std::vector<Real>& x = axis[d];
    const auto above = std::lower_bound(x.begin(), x.end(), v[d]);
    int i = static_cast<int>(above - x.begin());
    if (i == static_cast<int>(x.size()) || (i > 0 && v[d] - x[i - 1] < x[i] - v[d])) --i;
    idx[d] = i;
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

// Reading probes from a case and keeping their samples.
#include "io/probes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "io/point_locator.hpp"

namespace rfmems {

std::vector<Probe> read_probes(const CaseNode& probes_node, const Mesh& mesh) {
  std::vector<Probe> probes;
  const std::size_t n = probes_node.size();
  if (n == 0) return probes;

  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::infinity());
  Vec3 hi = -lo;
  for (const Vec3& x : mesh.nodes()) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const Real tolerance = 1e-6 * (hi - lo).maxCoeff();

  std::vector<Vec3> centroids(mesh.n_cells());
  for (Index c = 0; c < mesh.n_cells(); ++c) centroids[c] = mesh.cell_centroid(c);
  const PointLocator locator(std::move(centroids), mesh.dim());

  std::set<std::string> names;
  for (std::size_t i = 0; i < n; ++i) {
    const CaseNode item = probes_node.item(i);
    Probe p;
    p.name = item.get_string("name");
    item.require(!p.name.empty() && p.name.find('/') == std::string::npos && p.name != ".",
                 "name", "expected a non-empty name without '/'");
    item.require(names.insert(p.name).second, "name", "another probe has this name");
    p.at = item.get_vec3_quantity("at", Dimension::Length);
    for (int d = 0; d < mesh.dim(); ++d)
      item.require(p.at[d] >= lo[d] - tolerance && p.at[d] <= hi[d] + tolerance, "at",
                   fmt::format("probe '{}' lies outside the mesh (bounding box [{:.6g}, {:.6g}] "
                               "x [{:.6g}, {:.6g}]{})",
                               p.name, lo.x(), hi.x(), lo.y(), hi.y(),
                               mesh.dim() == 3
                                   ? fmt::format(" x [{:.6g}, {:.6g}]", lo.z(), hi.z())
                                   : std::string()));
    if (mesh.dim() == 2)
      item.require(p.at.z() == 0, "at", fmt::format("probe '{}': a 2D mesh has z = 0", p.name));
    p.cell = locator.nearest(p.at);
    probes.push_back(std::move(p));
  }
  return probes;
}

void ProbeHistory::add(Real t, std::vector<Vec3> values) {
  if (values.size() != n_probes_) throw std::logic_error("ProbeHistory::add: wrong probe count");
  times_.push_back(t);
  values_.push_back(std::move(values));
}

Real ProbeHistory::max_abs(std::size_t p, int k) const {
  Real m = 0;
  for (const auto& sample : values_) m = std::max(m, std::abs(sample[p][k]));
  return m;
}

std::vector<std::vector<double>> ProbeHistory::series(std::size_t p) const {
  std::vector<std::vector<double>> rows;
  rows.reserve(values_.size());
  for (const auto& sample : values_) rows.push_back({sample[p].x(), sample[p].y(), sample[p].z()});
  return rows;
}

}  // namespace rfmems

// Reading probes from a case and keeping their samples.
#include "io/probes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <tuple>

#include "io/case_schema_yaml.hpp"
#include "io/point_locator.hpp"

namespace rfmems {

CasePointFinder::CasePointFinder(const Mesh& mesh) : mesh_(mesh) {
  lo_ = Vec3::Constant(std::numeric_limits<Real>::infinity());
  hi_ = -lo_;
  for (const Vec3& x : mesh.nodes()) {
    lo_ = lo_.cwiseMin(x);
    hi_ = hi_.cwiseMax(x);
  }
  std::vector<Vec3> centroids(mesh.n_cells());
  for (Index c = 0; c < mesh.n_cells(); ++c) centroids[c] = mesh.cell_centroid(c);
  locator_ = std::make_unique<PointLocator>(std::move(centroids), mesh.dim());
}

CasePointFinder::~CasePointFinder() = default;

std::pair<Vec3, Index> CasePointFinder::find(const CaseNode& item, const std::string& key,
                                             const std::string& what) const {
  const Real tolerance = 1e-6 * (hi_ - lo_).maxCoeff();
  const int dim = mesh_.dim();
  const Vec3 at = item.get_vec3_quantity(key, Dimension::Length);
  item.require(static_cast<int>(item.child(key).size()) == dim, key,
               fmt::format("{}: expected {} coordinates (the mesh is {}D)", what, dim, dim));
  for (int d = 0; d < dim; ++d)
    item.require(at[d] >= lo_[d] - tolerance && at[d] <= hi_[d] + tolerance, key,
                 fmt::format("{} lies outside the mesh (bounding box [{:.6g}, {:.6g}] "
                             "x [{:.6g}, {:.6g}]{})",
                             what, lo_.x(), hi_.x(), lo_.y(), hi_.y(),
                             dim == 3 ? fmt::format(" x [{:.6g}, {:.6g}]", lo_.z(), hi_.z())
                                      : std::string()));
  return {at, locator_->nearest(at)};
}

std::vector<Probe> read_probes(const CaseNode& probes_node, const Mesh& mesh) {
  std::vector<Probe> probes;
  const std::size_t n = probes_node.size();
  if (n == 0) return probes;
  const CasePointFinder finder(mesh);
  std::set<std::string> names;
  for (std::size_t i = 0; i < n; ++i) {
    const CaseNode item = probes_node.item(i);
    Probe p;
    p.name = item.get_string("name");
    item.require(!p.name.empty() && p.name.find('/') == std::string::npos && p.name != ".", "name",
                 "expected a non-empty name without '/'");
    item.require(names.insert(p.name).second, "name", "another probe has this name");
    std::tie(p.at, p.cell) = finder.find(item, "at", fmt::format("probe '{}'", p.name));
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

CaseSchema probes_case_keys() { return embedded_case_schema("io/probes.keys.yaml"); }

}  // namespace rfmems

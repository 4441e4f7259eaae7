// PointLocator: nanoflann's KD-tree over a std::vector<Vec3> through the dataset-adaptor
// interface it expects (kdtree_get_point_count, kdtree_get_pt, kdtree_get_bbox).
#include "io/point_locator.hpp"

#include <nanoflann.hpp>
#include <stdexcept>

namespace rfmems {

namespace {

// The view of the points nanoflann reads; it must outlive the tree (both live in PointLocator).
struct Cloud {
  const std::vector<Vec3>* points;
  std::size_t kdtree_get_point_count() const { return points->size(); }
  double kdtree_get_pt(std::size_t i, std::size_t d) const {
    return (*points)[i][static_cast<Eigen::Index>(d)];
  }
  // false: let nanoflann compute the bounding box itself.
  template <class BBox>
  bool kdtree_get_bbox(BBox&) const {
    return false;
  }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>,
                                                   Cloud, -1, std::size_t>;

}  // namespace

struct PointLocator::Tree {
  Cloud cloud;
  KdTree index;
  Tree(const std::vector<Vec3>& points, int dim)
      : cloud{&points}, index(dim, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {}
};

PointLocator::PointLocator(std::vector<Vec3> points, int dim)
    : points_(std::move(points)), dim_(dim) {
  if (dim_ != 2 && dim_ != 3) throw std::logic_error("PointLocator: dim must be 2 or 3");
  tree_ = std::make_unique<Tree>(points_, dim_);  // the constructor builds the index
}

PointLocator::~PointLocator() = default;

Index PointLocator::nearest(const Vec3& x) const {
  if (points_.empty()) throw std::logic_error("PointLocator: no points to search");
  std::size_t index = 0;
  double distance2 = 0;
  nanoflann::KNNResultSet<double, std::size_t> result(1);
  result.init(&index, &distance2);
  tree_->index.findNeighbors(result, x.data(), nanoflann::SearchParams());
  return static_cast<Index>(index);
}

}  // namespace rfmems

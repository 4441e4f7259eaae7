// Nearest-point queries over a fixed set of points (cell centroids, face centroids): a KD-tree
// from nanoflann (KDTreeSingleIndexAdaptor, exact L2 search), built once at construction.
// Used to attach probes to cells and to find the face a pressure load is evaluated on.
#pragma once
#include <memory>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

class PointLocator {
 public:
  // dim 2 searches in x-y only (2D meshes keep z = 0); dim 3 in x-y-z. `points` is copied.
  PointLocator(std::vector<Vec3> points, int dim);
  ~PointLocator();
  PointLocator(const PointLocator&) = delete;
  PointLocator& operator=(const PointLocator&) = delete;

  // Index of the point nearest to x (the lowest index among exact ties is not guaranteed).
  // Throws std::logic_error on an empty set.
  Index nearest(const Vec3& x) const;
  Index size() const { return static_cast<Index>(points_.size()); }

 private:
  struct Tree;
  std::vector<Vec3> points_;
  int dim_;
  std::unique_ptr<Tree> tree_;
};

}  // namespace rfmems

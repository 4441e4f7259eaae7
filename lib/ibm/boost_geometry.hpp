// Boost.Geometry types of the immersed-boundary module (private to
// lib/ibm/*.cpp): 2D Cartesian points, segments as two-point linestrings
// (bg::relate takes linestrings), counterclockwise closed polygons, boxes, and
// an R-tree of (box, index) values.
#pragma once
#define BOOST_ALLOW_DEPRECATED_HEADERS  // Boost 1.74's geometry includes a
                                        // deprecated header
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <utility>

#include "core/types.hpp"

namespace rfmems::ibm_geometry {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

using Point = bg::model::d2::point_xy<double>;
using Linestring = bg::model::linestring<Point>;
using Polygon = bg::model::polygon<Point, /*clockwise=*/false, /*closed=*/true>;
using Box = bg::model::box<Point>;
using BoxValue = std::pair<Box, Index>;
using BoxTree = bgi::rtree<BoxValue, bgi::rstar<16>>;

inline Point point(const Vec3& x) { return {x.x(), x.y()}; }

inline Linestring segment(const Vec3& a, const Vec3& b) { return {point(a), point(b)}; }

inline Box box_of(const Vec3& a, const Vec3& b) {
  return {Point(std::min(a.x(), b.x()), std::min(a.y(), b.y())),
          Point(std::max(a.x(), b.x()), std::max(a.y(), b.y()))};
}

}  // namespace rfmems::ibm_geometry

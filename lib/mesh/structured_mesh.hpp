// Generators of graded rectangles (quads) and boxes (hexahedra).
//
// Grading: ratio of the last cell size to the first along an axis (1 = uniform); geometric.
// Patches: left (x = x0), right (x = x1), bottom (y = y0), top (y = y1), and in 3D
// back (z = z0), front (z = z1).
#pragma once
#include <functional>
#include <string>

#include "mesh/mesh.hpp"

namespace rfmems {

struct BoxSpec {
  int dim = 2;
  Vec3 lower = Vec3::Zero();
  Vec3 upper = Vec3::Ones();
  int n[3] = {1, 1, 1};
  Real grading[3] = {1.0, 1.0, 1.0};
};

// Optional map applied to every node after it is placed (to make test meshes skewed).
using NodeMap = std::function<Vec3(const Vec3&)>;

Mesh make_structured_mesh(const BoxSpec& spec, const NodeMap& map = {});

// Coordinates of n+1 points from a to b, geometrically graded with last/first size = ratio.
std::vector<Real> graded_points(Real a, Real b, int n, Real ratio);

}  // namespace rfmems

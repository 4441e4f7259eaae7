// Boundary conditions of the elasticity operator, one per mesh patch.
//   Fixed:     u = value(x, t)                      (value zero for a clamp)
//   Traction:  sigma n = value(x, t)                (zero: free surface)
//   Symmetry:  u.n = 0, tangential traction zero
#pragma once
#include <functional>
#include <string>

#include "core/types.hpp"

namespace rfmems {

using VectorField = std::function<Vec3(const Vec3& x, Real t)>;

struct ElasticityBoundary {
  enum class Kind { Fixed, Traction, Symmetry };
  Kind kind = Kind::Traction;
  VectorField value;  // empty: zero

  Vec3 at(const Vec3& x, Real t) const { return value ? value(x, t) : Vec3::Zero(); }
  bool supplies_value() const { return kind != Kind::Traction; }
};

}  // namespace rfmems

// Boundary conditions of the plate operator, one per mesh patch (an edge of the mid-surface,
// outward normal n, tangent t = z x n). Values are in the unknowns' own components:
// deflection w (+z) and rotations (beta_x, beta_y) with u = z beta_x, v = z beta_y, so the
// Kirchhoff limit is beta = -grad w.
//
//   Clamped               w = 0, beta = 0
//   Displacement          (w, beta_x, beta_y) = value(x, t)
//   SimplySupportedHard   w = value[0], beta.t = value[1:2].t (zero by default), M_nn = 0
//                         (the twisting moment M_tn is a reaction)
//   SimplySupportedSoft   w = value[0], moment M n = 0
//   Free                  moment M n = 0, shear force Q.n = 0
//   Load                  value = (Q.n, (M n)_x, (M n)_y): transverse shear force and moment
//                         per unit edge length acting on the plate (Q.n > 0 pushes in +z;
//                         (M n) is work-conjugate to beta)
#pragma once
#include <functional>

#include "core/types.hpp"

namespace rfmems {

struct PlateBoundary {
  enum class Kind { Clamped, Displacement, SimplySupportedHard, SimplySupportedSoft, Free, Load };
  Kind kind = Kind::Free;
  std::function<Vec3(const Vec3& x, Real t)> value;  // empty: zero
  // The von Karman plate (von_karman_plate.hpp) only: an edge that holds w but not the in-plane
  // displacement (N n = 0 there instead of u = 0).
  bool in_plane_free = false;

  Vec3 at(const Vec3& x, Real t) const { return value ? value(x, t) : Vec3::Zero(); }
  // w is prescribed (the transverse shear force is a reaction).
  bool prescribes_deflection() const { return kind != Kind::Free && kind != Kind::Load; }
  // Both rotations are prescribed.
  bool prescribes_rotation() const { return kind == Kind::Clamped || kind == Kind::Displacement; }
};

}  // namespace rfmems

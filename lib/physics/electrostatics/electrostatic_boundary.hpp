// Boundary conditions of the electrostatic potential, one per mesh patch:
//   Potential  phi = V (a conductor held at V), or phi = field(x) (manufactured solutions)
//   ZeroFlux   eps dphi/dn = 0 (a symmetry line, or the side of a gap far from the fringe)
//   Floating   an isolated conductor: phi = V_k on the whole patch with V_k unknown and its
//              total charge  sum_f eps dphi/dn |S_f| = Q  given (value = Q; 0 = uncharged)
#pragma once
#include <functional>

#include "core/types.hpp"
#include "physics/electrostatics/permittivity.hpp"

namespace rfmems {

struct PotentialBoundary {
  enum class Kind { Potential, ZeroFlux, Floating };
  Kind kind = Kind::ZeroFlux;
  // Potential: V [V]; Floating: total charge Q [C] (2D: per unit depth, C/m).
  Real value = 0;
  // Potential only, optional: phi at a face centroid (overrides value).
  std::function<Real(const Vec3&)> field;

  static PotentialBoundary potential(Real volts) { return {Kind::Potential, volts, {}}; }
  static PotentialBoundary potential(std::function<Real(const Vec3&)> f) {
    return {Kind::Potential, 0.0, std::move(f)};
  }
  static PotentialBoundary zero_flux() { return {Kind::ZeroFlux, 0.0, {}}; }
  static PotentialBoundary floating(Real charge = 0) { return {Kind::Floating, charge, {}}; }
};

}  // namespace rfmems

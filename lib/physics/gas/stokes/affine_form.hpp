// An affine expression sum_k a_k x_k + b in the unknowns x of a linear system. The Stokes
// discretisation builds its face values, stresses and control-volume balances as these, so
// one definition of each serves both the assembled matrix rows and the evaluation of forces
// at a solution (the force integral then telescopes exactly as the equations do).
#pragma once
#include <span>
#include <utility>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

struct AffineForm {
  std::vector<std::pair<Index, Real>> terms;  // (unknown, coefficient); repeats allowed
  Real constant = 0;

  static AffineForm unknown(Index k, Real a = 1) { return {{{k, a}}, 0}; }
  static AffineForm known(Real b) { return {{}, b}; }

  AffineForm& operator+=(const AffineForm& o) {
    terms.insert(terms.end(), o.terms.begin(), o.terms.end());
    constant += o.constant;
    return *this;
  }
  AffineForm& operator*=(Real s) {
    for (auto& t : terms) t.second *= s;
    constant *= s;
    return *this;
  }
  AffineForm& operator-=(const AffineForm& o) { return *this += Real(-1) * o; }
  friend AffineForm operator*(Real s, AffineForm f) { return f *= s; }
  friend AffineForm operator+(AffineForm a, const AffineForm& b) { return a += b; }
  friend AffineForm operator-(AffineForm a, const AffineForm& b) { return a -= b; }

  Real evaluate(std::span<const Real> x) const {
    Real s = constant;
    for (const auto& [k, a] : terms) s += a * x[k];
    return s;
  }
};

}  // namespace rfmems

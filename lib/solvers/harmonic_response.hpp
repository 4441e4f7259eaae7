// Frequency response of a differential-algebraic system F(t, y, y') = 0 linearised about a
// steady state (t, y0) with y0' = 0, driven by a small harmonic input:
//
//   y = y0 + Re(x exp(i w t)),   (dF/dy + i w dF/dy') x = -(b_value + i w b_rate),
//
// b_value and b_rate the input's forcing: dF/d(input) and dF/d(input'), per unit input
// amplitude (a prescribed gap's motion, a load's amplitude). dF/dy and dF/dy' come from the
// operator's own Jacobian, dF/dy + c_j dF/dy', at c_j = 0 and 1 (it is linear in c_j), so any
// SystemOperator (a structure, a squeeze film, a coupled switch) has its response without
// code of its own. Each frequency is one sparse LU solve of the real form of the complex
// system,
//   [ A   -w B ] [Re x]     [b_value  ]
//   [ w B   A  ] [Im x] = - [w b_rate ],   A = dF/dy, B = dF/dy',
// with KLU: the ordering once for the sweep, the numbers refactorised per frequency. For a
// transient that would reach the same periodic state (the start-up decaying over many periods),
// it is the answer at the cost of one factorisation.
#pragma once
#include <complex>
#include <memory>
#include <span>
#include <vector>

#include "core/system_operator.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

class HarmonicResponse {
 public:
  // Linearises op about (t, y0, y0' = 0).
  HarmonicResponse(SystemOperator& op, Real t, std::span<const Real> y0);
  // x for the input's forcing (b_value, b_rate) at angular frequency omega [rad/s].
  std::vector<std::complex<Real>> solve(Real omega, std::span<const Real> b_value,
                                        std::span<const Real> b_rate);
  Index size() const { return n_; }
  // LU factorisations with fresh pivoting and refactorisations so far.
  long fresh_factorizations() const { return lu_ ? lu_->fresh_factorizations() : 0; }
  long refactorizations() const { return lu_ ? lu_->refactorizations() : 0; }

 private:
  void fill_values(Real omega);

  Index n_;
  CsrPattern op_pattern_;    // of dF/dy and dF/dy'
  std::vector<Real> a_, b_;  // their values
  CsrPattern pattern_;       // of the real 2n x 2n form
  std::vector<Real> values_;
  std::unique_ptr<KluFactorization> lu_;
};

}  // namespace rfmems

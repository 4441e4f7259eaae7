// The displacement-controlled equilibrium of an electrostatically actuated structure: the
// voltage is an unknown and the deflection of one control unknown y_c is prescribed,
//
//   R(y) + lambda q(y) = 0,            lambda = V^2, q = d(residual)/d(V^2)
//   k_ref (y_c - delta) = 0            (k_ref: the structure's stiffness scale, for conditioning)
//
// a bordered system in (y, lambda) that stays regular at the fold, where dV/d(delta) = 0 and
// the voltage-controlled Jacobian K + lambda dq/dy is singular (Riks/Crisfield's displacement
// control; Pamidighantam et al. 2002 for MEMS pull-in). Its Jacobian is K's pattern with the
// column q appended to every row, and the row e_c^T.
#pragma once
#include <vector>

#include "physics/electrostatics/parallel_plate_actuation.hpp"

namespace rfmems {

class DisplacementControlSystem : public SystemOperator {
 public:
  DisplacementControlSystem(ParallelPlateActuation& actuation, Index control, Real k_ref);
  void set_target(Real delta) { delta_ = delta; }

  Index size() const override { return n_ + 1; }
  std::vector<Real> differential_components() const override {
    return std::vector<Real>(n_ + 1, 0.0);
  }
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override;
  const CsrPattern& jacobian_pattern() const override { return pattern_; }
  void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> values) override;

  // The largest electrostatic force |lambda q_i(y)| on a structure unknown: the load the
  // structure balances, the scale of its residual rows.
  Real load_scale(std::span<const Real> y);

 private:
  ParallelPlateActuation& act_;
  Index n_, control_;
  Real k_ref_, delta_ = 0;
  CsrPattern pattern_;
  std::vector<Real> k_values_, q_;
};

}  // namespace rfmems

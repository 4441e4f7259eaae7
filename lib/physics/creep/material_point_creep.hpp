// One material point under a prescribed stress history sigma(t): the creep law alone as a
// SystemOperator, for creep curves (a uniaxial test specimen) and for checking the law and
// the integrators against the closed-form uniaxial solution (materials/creep_law.hpp).
//
//   state q = (eps_p,xx, eps_p,yy, eps_p,zz, eps_p,yz, eps_p,xz, eps_p,xy, eps_eff)
//   (tensor shear components),   F = q' - g(sigma(t), eps_eff)   (all differential)
// Jacobian: c_j I - dg/dq, with dg/dq only in the eps_eff column (the stress is prescribed).
#pragma once
#include <functional>

#include "core/system_operator.hpp"
#include "materials/creep_law.hpp"

namespace rfmems {

class MaterialPointCreep : public SystemOperator {
 public:
  static constexpr int kEff = 6;
  MaterialPointCreep(const CreepLaw& law, std::function<Mat3(Real t)> stress);

  Index size() const override { return 7; }
  std::vector<Real> differential_components() const override { return std::vector<Real>(7, 1.0); }
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override;
  const CsrPattern& jacobian_pattern() const override { return pattern_; }
  void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> values) override;
  // q' = g(sigma(t), q).
  std::vector<Real> rates(Real t, std::span<const Real> y) const;

 private:
  static Eigen::Matrix<Real, 7, 1> pack(const CreepRate& r);
  CreepLaw law_;
  std::function<Mat3(Real)> stress_;
  CsrPattern pattern_;  // dense 7 x 7
};

}  // namespace rfmems

// A generic preconditioner for Krylov solves of any SystemOperator: the LU factorisation (KLU)
// of its Jacobian dF/dy + c_j dF/dy', refreshed only when the integrator asks for a setup and
// reused (lagged) in between. Operators with structure to exploit (the COMET block solve of
// the gas model) provide their own through SystemOperator::preconditioner_*.
#pragma once
#include <memory>
#include <span>
#include <vector>

#include "core/system_operator.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

class JacobianLuPreconditioner {
 public:
  explicit JacobianLuPreconditioner(SystemOperator& op) : op_(op) {}
  void setup(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp);
  void solve(std::span<const Real> r, std::span<Real> z);

 private:
  SystemOperator& op_;
  std::vector<Real> values_;
  std::unique_ptr<KluFactorization> lu_;
};

}  // namespace rfmems

#include "solvers/jacobian_lu_preconditioner.hpp"

#include <algorithm>

namespace rfmems {

void JacobianLuPreconditioner::setup(Real t, Real c_j, std::span<const Real> y,
                                     std::span<const Real> yp) {
  values_.assign(op_.jacobian_pattern().nnz(), 0.0);
  op_.jacobian(t, c_j, y, yp, values_);
  lu_ = std::make_unique<KluFactorization>(op_.jacobian_pattern(), values_);
}

void JacobianLuPreconditioner::solve(std::span<const Real> r, std::span<Real> z) {
  std::copy(r.begin(), r.end(), z.begin());
  lu_->solve(z);
}

}  // namespace rfmems

// The operator contract between physics and integrators (see SUNDIALS' IDAResFn/IDALsJacFn).
//
// A physics operator is a semi-discrete system F(t, y, y') = 0 with a sparse Jacobian
// J = dF/dy + c_j dF/dy' in CSR form whose pattern is built once. IDA (transients) and KINSOL
// (static solves, c_j = 0, y' = 0) both drive this interface; physics never sees N_Vector or
// SUNMatrix. Throwing RecoverableError from residual/jacobian asks the integrator to retry
// with a smaller step.
#pragma once
#include <span>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

struct CsrPattern {
  std::vector<Index> row_ptr{0};
  std::vector<Index> col_idx;
  Index n_rows() const { return static_cast<Index>(row_ptr.size()) - 1; }
  Index nnz() const { return static_cast<Index>(col_idx.size()); }
  // Position of (row, col) in the value array, or -1 if not in the pattern.
  Index find(Index row, Index col) const;
};

// y = A x for the matrix with this pattern and these values.
inline void multiply(const CsrPattern& pattern, std::span<const Real> values,
                     std::span<const Real> x, std::span<Real> y) {
  for (Index i = 0; i < pattern.n_rows(); ++i) {
    Real sum = 0;
    for (Index k = pattern.row_ptr[i]; k < pattern.row_ptr[i + 1]; ++k)
      sum += values[k] * x[pattern.col_idx[k]];
    y[i] = sum;
  }
}

class SystemOperator {
 public:
  virtual ~SystemOperator() = default;
  virtual Index size() const = 0;
  // 1 for differential components (y' appears), 0 for algebraic ones (IDASetId).
  virtual std::vector<Real> differential_components() const = 0;
  virtual void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                        std::span<Real> r) = 0;
  virtual const CsrPattern& jacobian_pattern() const = 0;
  // Values of dF/dy + c_j dF/dy' in jacobian_pattern() order.
  virtual void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                        std::span<Real> values) = 0;

  // Optional preconditioner P ~ dF/dy + c_j dF/dy' for Krylov solvers (SPGMR). Operators
  // without one get the generic lagged-Jacobian LU preconditioner of the solver layer.
  virtual bool has_preconditioner() const { return false; }
  virtual void preconditioner_setup(Real /*t*/, Real /*c_j*/, std::span<const Real> /*y*/,
                                    std::span<const Real> /*yp*/) {}
  // z = P^{-1} r.
  virtual void preconditioner_solve(std::span<const Real> /*r*/, std::span<Real> /*z*/) {}
};

// A structural system M y'' + C y' + R(t, y) = 0 with a diagonal (lumped FV) mass matrix and
// an optional damping C (most operators: none). The adaptors in core/structural_systems.hpp turn
// it into a static system R(t, y) = 0 for KINSOL or the first-order system
// [y' - v; M v' + C v + R(t, y)] for IDA.
class SecondOrderOperator {
 public:
  virtual ~SecondOrderOperator() = default;
  virtual Index size() const = 0;
  virtual void internal_residual(Real t, std::span<const Real> y, std::span<Real> r) = 0;
  virtual const CsrPattern& stiffness_pattern() const = 0;
  // Values of dR/dy in stiffness_pattern() order.
  virtual void stiffness(Real t, std::span<const Real> y, std::span<Real> values) = 0;
  virtual std::vector<Real> mass_diagonal() const = 0;

  // Optional stiffness-proportional (Kelvin-Voigt) damping C = beta K, K = dR/dy at
  // homogeneous boundary data: the structure's equation becomes M y'' + C y' + R(t, y) = 0.
  // beta [s]; 0: undamped (the default), and add_damping_force is then never called.
  virtual Real damping_time() const { return 0; }
  // r += C v for the velocities v.
  virtual void add_damping_force(Real /*t*/, std::span<const Real> /*v*/, std::span<Real> /*r*/) {}

  // Optional: the product kv = dR/dy(t, y) v without assembling the matrix, for Krylov
  // solvers of structures too large to store their stiffness.
  virtual bool has_stiffness_product() const { return false; }
  virtual void stiffness_product(Real /*t*/, std::span<const Real> /*y*/,
                                 std::span<const Real> /*v*/, std::span<Real> /*kv*/) {}
};

}  // namespace rfmems

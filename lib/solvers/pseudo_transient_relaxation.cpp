#include "solvers/pseudo_transient_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

#include "solvers/kinsol_solver.hpp"

namespace rfmems {

namespace {

// F(y) + D (y - y_prev) / dtau, and its Jacobian dF/dy + D / dtau.
class PseudoTransientStep : public SystemOperator {
 public:
  PseudoTransientStep(SystemOperator& system, std::span<const Real> mass)
      : system_(system), mass_(mass.begin(), mass.end()), previous_(mass.size()) {
    const CsrPattern& p = system_.jacobian_pattern();
    for (Index i = 0; i < system_.size(); ++i) diagonal_.push_back(p.find(i, i));
  }
  void set_step(std::span<const Real> previous, Real dtau) {
    std::copy(previous.begin(), previous.end(), previous_.begin());
    inverse_step_ = 1 / dtau;
  }
  Index size() const override { return system_.size(); }
  std::vector<Real> differential_components() const override {
    return std::vector<Real>(size(), 0.0);
  }
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override {
    system_.residual(t, y, yp, r);
    for (Index i = 0; i < size(); ++i) r[i] += mass_[i] * inverse_step_ * (y[i] - previous_[i]);
  }
  const CsrPattern& jacobian_pattern() const override { return system_.jacobian_pattern(); }
  void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> values) override {
    system_.jacobian(t, c_j, y, yp, values);
    for (Index i = 0; i < size(); ++i) values[diagonal_[i]] += mass_[i] * inverse_step_;
  }

 private:
  SystemOperator& system_;
  std::vector<Real> mass_, previous_;
  std::vector<Index> diagonal_;
  Real inverse_step_ = 0;
};

Real residual_norm(SystemOperator& system, std::span<const Real> y, std::vector<Real>& r) {
  const std::vector<Real> zero(y.size(), 0.0);
  system.residual(0.0, y, zero, r);
  Real norm = 0;
  for (Real v : r) norm = std::max(norm, std::abs(v));
  return std::isfinite(norm) ? norm : 1e300;
}

}  // namespace

PseudoTransientStats relax_pseudo_transient(SystemOperator& system, std::span<Real> y,
                                            std::span<const Real> pseudo_mass,
                                            const PseudoTransientOptions& options) {
  PseudoTransientStep step(system, pseudo_mass);
  KinsolOptions kin;
  kin.line_search = true;
  kin.max_iterations = options.max_newton_iterations;
  kin.residual_scale = options.tolerance;
  kin.relative_tolerance = 0.1;  // each pseudo-step to a tenth of the final tolerance
  KinsolSolver solver(step, kin);
  std::vector<Real> r(y.size()), previous(y.begin(), y.end()), trial(y.size());
  PseudoTransientStats stats;
  Real norm = residual_norm(system, y, r), dtau = options.initial_step;
  while (norm > options.tolerance && stats.steps < options.max_steps) {
    std::copy(y.begin(), y.end(), previous.begin());
    std::copy(y.begin(), y.end(), trial.begin());
    step.set_step(previous, dtau);
    bool solved = true;
    try {
      const NonlinearStats s = solver.solve(0.0, trial);
      stats.newton_iterations += s.newton_iters;
      solved = s.final_residual <= options.tolerance;
    } catch (const std::exception&) {  // SolverError; RecoverableError from the physics
      solved = false;
    }
    ++stats.steps;
    if (!solved) {
      ++stats.rejected;
      dtau *= 0.25;
      continue;
    }
    const Real next = residual_norm(system, trial, r);
    std::copy(trial.begin(), trial.end(), y.begin());
    // SER, but at least x1.5 while the residual does not double: through the slow passage
    // past a fold's ghost the residual stalls, and backward Euler is stable at any dtau.
    const Real ratio = norm / next;
    dtau = std::min(options.max_step, dtau * (ratio < 0.5 ? 0.5 : std::clamp(ratio, 1.5, 10.0)));
    norm = next;
  }
  stats.converged = norm <= options.tolerance;
  stats.residual = norm;
  return stats;
}

}  // namespace rfmems

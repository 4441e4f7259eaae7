#include "coupling/quasi_static_pull_in.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"

namespace rfmems {

namespace {

// The bordered system in (y, lambda); see the header.
class DisplacementControlSystem : public SystemOperator {
 public:
  DisplacementControlSystem(ParallelPlateActuation& act, Index control, Real k_ref)
      : act_(act), n_(act.size()), control_(control), k_ref_(k_ref), q_(n_) {
    // Rows 0..n-1: the structure's stiffness row plus the column n (q); row n: (n, control).
    const CsrPattern& k = act_.stiffness_pattern();
    pattern_.row_ptr.assign(1, 0);
    for (Index i = 0; i < n_; ++i) {
      for (Index p = k.row_ptr[i]; p < k.row_ptr[i + 1]; ++p)
        pattern_.col_idx.push_back(k.col_idx[p]);
      pattern_.col_idx.push_back(n_);
      pattern_.row_ptr.push_back(static_cast<Index>(pattern_.col_idx.size()));
    }
    pattern_.col_idx.push_back(control_);
    pattern_.row_ptr.push_back(static_cast<Index>(pattern_.col_idx.size()));
    k_values_.resize(k.nnz());
  }
  void set_target(Real delta) { delta_ = delta; }

  Index size() const override { return n_ + 1; }
  std::vector<Real> differential_components() const override {
    return std::vector<Real>(n_ + 1, 0.0);
  }
  void residual(Real t, std::span<const Real> y, std::span<const Real>,
                std::span<Real> r) override {
    const Real lambda = y[n_];
    act_.set_voltage_squared([lambda](Real) { return lambda; });
    act_.internal_residual(t, y.subspan(0, n_), r.subspan(0, n_));
    r[n_] = k_ref_ * (y[control_] - delta_);
  }
  const CsrPattern& jacobian_pattern() const override { return pattern_; }
  void jacobian(Real t, Real, std::span<const Real> y, std::span<const Real>,
                std::span<Real> values) override {
    const Real lambda = y[n_];
    act_.set_voltage_squared([lambda](Real) { return lambda; });
    act_.stiffness(t, y.subspan(0, n_), k_values_);
    act_.residual_per_volt2(y.subspan(0, n_), q_);
    const CsrPattern& k = act_.stiffness_pattern();
    Index out = 0;
    for (Index i = 0; i < n_; ++i) {
      for (Index p = k.row_ptr[i]; p < k.row_ptr[i + 1]; ++p) values[out++] = k_values_[p];
      values[out++] = q_[i];
    }
    values[out] = k_ref_;
  }

 private:
  ParallelPlateActuation& act_;
  Index n_, control_;
  Real k_ref_, delta_ = 0;
  CsrPattern pattern_;
  std::vector<Real> k_values_, q_;
};

}  // namespace

Real stiffness_scale(ParallelPlateActuation& act) {
  const CsrPattern& k = act.structure().stiffness_pattern();
  std::vector<Real> values(k.nnz());
  std::vector<Real> zero(act.size(), 0.0);
  act.structure().stiffness(0.0, zero, values);
  Real scale = 0;
  for (Index i = 0; i < act.size(); ++i) scale = std::max(scale, std::abs(values[k.find(i, i)]));
  return scale;
}

QuasiStaticPullIn trace_fold(const DeltaSolve& solve, const FoldSample& rest, Real gap,
                             const QuasiStaticOptions& options) {
  QuasiStaticPullIn result;
  std::vector<FoldSample> samples;
  for (int k = 1; k <= options.n_points; ++k) {
    const Real delta = -options.max_fraction * gap * k / options.n_points;
    samples.push_back(solve(delta, samples.empty() ? rest : samples.back()));
    result.curve.push_back(samples.back().point);
  }
  // The largest sampled voltage and its neighbours bracket the fold.
  const auto best = std::max_element(
      result.curve.begin(), result.curve.end(),
      [](const PullInPoint& a, const PullInPoint& b) { return a.voltage < b.voltage; });
  const std::size_t k = best - result.curve.begin();
  if (k + 1 == result.curve.size())
    throw SolverError(
        fmt::format("displacement control: no fold up to a deflection of {:g} of the "
                    "gap (V still rising: {:.4g} V); raise max_fraction",
                    options.max_fraction, best->voltage));
  // Golden-section search for the largest V(delta) in [a, b] (delta < 0: a is the deeper end).
  Real a = result.curve[k + 1].displacement, b = k > 0 ? result.curve[k - 1].displacement : 0.0;
  const Real ratio = (std::sqrt(5.0) - 1) / 2;
  Real c = b - ratio * (b - a), d = a + ratio * (b - a);
  FoldSample sc = solve(c, samples[k]), sd = solve(d, samples[k]);
  for (int it = 0;
       it < 80 && std::abs(sc.point.voltage - sd.point.voltage) > 0.1 * options.voltage_tolerance;
       ++it) {
    if (sc.point.voltage > sd.point.voltage) {  // the maximum lies in [a, d]
      b = d;
      d = c;
      sd = std::move(sc);
      c = b - ratio * (b - a);
      sc = solve(c, sd);
    } else {  // in [c, b]
      a = c;
      c = d;
      sc = std::move(sd);
      d = a + ratio * (b - a);
      sd = solve(d, sc);
    }
  }
  const FoldSample& best_sample = sc.point.voltage > sd.point.voltage ? sc : sd;
  const PullInPoint fold = best_sample.point;
  result.fold_state = best_sample.state;
  result.pull_in_voltage = fold.voltage;
  result.pull_in_displacement = fold.displacement;
  result.curve.push_back(fold);
  std::sort(
      result.curve.begin(), result.curve.end(),
      [](const PullInPoint& p, const PullInPoint& q) { return p.displacement > q.displacement; });
  for (PullInPoint& p : result.curve) p.stable = p.displacement >= fold.displacement;
  return result;
}

namespace {

// KINSOL on the displacement-controlled system: Newton with line search, converged when
// ||F||_inf <= tol k_ref g0 (forces small against the stiffness times the gap).
KinsolOptions displacement_control_kinsol(const ParallelPlateActuation& act, Real k_ref,
                                          const QuasiStaticOptions& options) {
  KinsolOptions kin;
  kin.max_iterations = options.max_newton_iterations;
  kin.line_search = true;
  kin.relative_tolerance = options.newton_tolerance;
  kin.residual_scale = k_ref * act.initial_gap();
  return kin;
}

}  // namespace

QuasiStaticPullIn trace_pull_in(ParallelPlateActuation& act, Index control,
                                const QuasiStaticOptions& options) {
  const Index n = act.size();
  const Real g0 = act.initial_gap();
  const Real k_ref = stiffness_scale(act);
  DisplacementControlSystem system(act, control, k_ref);
  KinsolSolver solver(system, displacement_control_kinsol(act, k_ref, options));

  long newton = 0, solves = 0;
  NonlinearStats last;
  // From a solved state (y, V^2), scaled to the new delta (exact for a linear response).
  auto solve = [&](Real delta, const FoldSample& from) {
    FoldSample s{{}, from.state};
    if (from.point.displacement == 0) {
      s.state[control] = delta;
    } else {
      for (Index i = 0; i < n; ++i) s.state[i] *= delta / from.point.displacement;
    }
    system.set_target(delta);
    last = solver.solve(0.0, s.state);
    newton += last.newton_iters;
    ++solves;
    if (s.state[n] < 0)
      throw SolverError(
          fmt::format("displacement control: negative V^2 = {:.3e} at delta = "
                      "{:.3e} m (the structure bends away from the electrode?)",
                      s.state[n], delta));
    s.point = {delta, std::sqrt(s.state[n]),
               act.min_gap(std::span<const Real>(s.state).subspan(0, n)), true, last.newton_iters};
    return s;
  };
  FoldSample rest{{0.0, 0.0, g0, true, 0}, std::vector<Real>(n + 1, 0.0)};
  QuasiStaticPullIn result = trace_fold(solve, rest, g0, options);
  result.newton_iterations = newton;
  result.solves = solves;
  result.last = last;
  return result;
}

std::vector<Real> follow_displacement(ParallelPlateActuation& act, Index control,
                                      std::span<const Real> from, const std::vector<Real>& path,
                                      const QuasiStaticOptions& options) {
  const Index n = act.size();
  const Real k_ref = stiffness_scale(act);
  DisplacementControlSystem system(act, control, k_ref);
  KinsolSolver solver(system, displacement_control_kinsol(act, k_ref, options));
  std::vector<Real> state(from.begin(), from.end());
  for (const Real delta : path) {
    const Real scale = delta / state[control];
    for (Index i = 0; i < n; ++i) state[i] *= scale;
    system.set_target(delta);
    solver.solve(0.0, state);
  }
  return state;
}

}  // namespace rfmems

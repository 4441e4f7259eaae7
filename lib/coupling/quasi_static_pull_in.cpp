#include "coupling/quasi_static_pull_in.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"
#include "coupling/displacement_control_system.hpp"
#include "solvers/static_solve.hpp"

namespace rfmems {

Real stiffness_scale(ParallelPlateActuation& act) {
  const CsrPattern& k = act.structure().stiffness_pattern();
  std::vector<Real> values(k.nnz());
  std::vector<Real> zero(act.size(), 0.0);
  act.structure().stiffness(0.0, zero, values);
  Real scale = 0;
  for (Index i = 0; i < act.size(); ++i) scale = std::max(scale, std::abs(values[k.find(i, i)]));
  return scale;
}

namespace {

// The value at x of the line through (p, vp) and (q, vq).
Real line(Real p, Real vp, Real q, Real vq, Real x) { return vp + (vq - vp) * (x - p) / (q - p); }

// An upper bound on the largest V over [a, b] from V at a < c < d < b, for V concave there (as it
// is about a smooth fold): a concave function lies below each secant's extension beyond its
// interval, so below the secant (c, d) on [a, c] and [d, b], and below both the secants (a, c)
// and (d, b) on [c, d].
Real concave_bound(Real a, Real va, Real c, Real vc, Real d, Real vd, Real b, Real vb) {
  Real bound = std::max({vc, vd, line(c, vc, d, vd, a), line(c, vc, d, vd, b)});
  bound = std::max(bound, std::min(vc, line(d, vd, b, vb, c)));
  bound = std::max(bound, std::min(line(a, va, c, vc, d), vd));
  const Real slope_ac = (vc - va) / (c - a), slope_db = (vb - vd) / (b - d);
  if (slope_ac != slope_db) {
    const Real x = (vd - vc + slope_ac * c - slope_db * d) / (slope_ac - slope_db);
    if (x > c && x < d) bound = std::max(bound, line(a, va, c, vc, x));
  }
  return bound;
}

}  // namespace

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
  // Golden-section search for the largest V(delta) in [a, b] (delta < 0: a is the deeper end),
  // until V's concave bound over the bracket exceeds the best solved point by at most
  // voltage_tolerance: the fold's voltage is then known to that, however wide the bracket.
  Real a = result.curve[k + 1].displacement, b = k > 0 ? result.curve[k - 1].displacement : 0.0;
  Real va = result.curve[k + 1].voltage, vb = k > 0 ? result.curve[k - 1].voltage : 0.0;
  const Real ratio = (std::sqrt(5.0) - 1) / 2;
  Real c = b - ratio * (b - a), d = a + ratio * (b - a);
  FoldSample sc = solve(c, samples[k]), sd = solve(d, samples[k]);
  FoldSample best_sample = samples[k];
  auto keep_best = [&](const FoldSample& s) {
    if (s.point.voltage > best_sample.point.voltage) best_sample = s;
  };
  keep_best(sc);
  keep_best(sd);
  // The bracket stops narrowing at 1e-6 g0: V varies across it by ~1e-12 V there, below the
  // round-off of any point's voltage, so a bound still wider is noise in V, not a wider fold.
  for (int it = 0; it < 80 && b - a > 1e-6 * gap &&
                   concave_bound(a, va, c, sc.point.voltage, d, sd.point.voltage, b, vb) -
                           best_sample.point.voltage >
                       options.voltage_tolerance;
       ++it) {
    if (sc.point.voltage > sd.point.voltage) {  // the maximum lies in [a, d]
      b = d;
      vb = sd.point.voltage;
      d = c;
      sd = std::move(sc);
      c = b - ratio * (b - a);
      sc = solve(c, sd);
      keep_best(sc);
    } else {  // in [c, b]
      a = c;
      va = sc.point.voltage;
      c = d;
      sc = std::move(sd);
      d = a + ratio * (b - a);
      sd = solve(d, sc);
      keep_best(sd);
    }
  }
  const PullInPoint fold = best_sample.point;
  result.fold_state = best_sample.state;
  result.pull_in_voltage = fold.voltage;
  result.pull_in_displacement = fold.displacement;
  if (best_sample.point.displacement != result.curve[k].displacement) result.curve.push_back(fold);
  std::sort(
      result.curve.begin(), result.curve.end(),
      [](const PullInPoint& p, const PullInPoint& q) { return p.displacement > q.displacement; });
  for (PullInPoint& p : result.curve) p.stable = p.displacement >= fold.displacement;
  return result;
}

namespace {

// KINSOL on the displacement-controlled system: Newton with line search, the Jacobian and its
// factors kept from point to point while Newton converges. The structure's rows are scaled by
// the load they balance, the electrostatic force (DisplacementControlSystem::load_scale), so
// the test means the same on every mesh: a scale such as k_ref g0 grows like the inverse
// fourth power of the cell size against the load of a cell, and on fine meshes accepts the
// predictor as the solution.
KinsolOptions displacement_control_kinsol(const QuasiStaticOptions& options) {
  KinsolOptions kin;
  kin.max_iterations = options.max_newton_iterations;
  kin.line_search = true;
  kin.keep_jacobian = true;
  kin.round_off_floor = true;
  kin.ordering = options.ordering;
  kin.umfpack_from = options.umfpack_from;
  kin.umfpack_ordering = UmfpackOrdering::SymmetricNestedDissection;
  // Newton corrects a solve's error at its next iteration; refinement would double each solve
  // (the 160 x 16 trace: 5.0 s CPU with 2 steps against 2.1 s without, the same iterations).
  kin.umfpack_refinement_steps = 0;
  return kin;
}

// The relative tolerance for a point whose predictor has voltage v: fixed, or tied to the
// voltage tolerance (V's error is about V tol / 2).
Real newton_tolerance(const QuasiStaticOptions& options, Real v) {
  if (options.newton_tolerance > 0) return options.newton_tolerance;
  return std::clamp(0.2 * options.voltage_tolerance / std::max(v, 1e-300), 1e-12, 1e-4);
}

// Solves the system at its target from `state` (overwritten) to the load-scaled tolerance. A
// predictor without voltage (the first point, from rest) has no load to scale by: it is solved
// by a relative reduction first, then again scaled by its solution's load.
NonlinearStats solve_scaled(DisplacementControlSystem& system, KinsolSolver& solver,
                            const QuasiStaticOptions& options, Real k_ref, Real g0,
                            std::vector<Real>& state) {
  const Index n = system.size() - 1;
  NonlinearStats total;
  for (int pass = 0; pass < 2; ++pass) {
    const Real load = system.load_scale(state);
    KinsolOptions& kin = solver.options();
    if (load > 0) {
      kin.residual_scales.assign(n + 1, load);
      kin.residual_scales[n] = k_ref * g0;
      kin.relative_tolerance = newton_tolerance(options, std::sqrt(std::max(state[n], 0.0)));
    } else {
      kin.residual_scales.clear();
      kin.relative_tolerance = 1e-8;
    }
    const NonlinearStats s = solver.solve(0.0, state);
    total.newton_iters += s.newton_iters;
    total.residual_evals += s.residual_evals;
    total.jacobian_evals += s.jacobian_evals;
    total.fresh_factorizations = s.fresh_factorizations;
    total.refactorizations = s.refactorizations;
    total.factor_entries = s.factor_entries;
    total.umfpack = s.umfpack;
    total.final_residual = s.final_residual;
    if (load > 0) break;
  }
  return total;
}

}  // namespace

QuasiStaticPullIn trace_pull_in(ParallelPlateActuation& act, Index control,
                                const QuasiStaticOptions& options) {
  const Index n = act.size();
  const Real g0 = act.initial_gap();
  const Real k_ref = stiffness_scale(act);
  DisplacementControlSystem system(act, control, k_ref);
  KinsolSolver solver(system, displacement_control_kinsol(options));

  long newton = 0, solves = 0;
  NonlinearStats last;
  FoldSample previous{{0.0, 0.0, g0, true, 0}, {}};  // the last point solved
  // The predictor: the secant through the solved state (y, V^2) and the last point solved,
  // evaluated at the new delta; from the state at rest, that state scaled to it (exact for a
  // linear response).
  auto solve = [&](Real delta, const FoldSample& from) {
    FoldSample s{{}, from.state};
    const Real d0 = from.point.displacement, d1 = previous.point.displacement;
    if (d0 == 0) {
      s.state[control] = delta;
    } else if (d1 == 0 || d1 == d0) {
      for (Index i = 0; i < n; ++i) s.state[i] *= delta / d0;
    } else {
      const Real w = (delta - d0) / (d1 - d0);
      for (Index i = 0; i <= n; ++i) s.state[i] += w * (previous.state[i] - s.state[i]);
    }
    system.set_target(delta);
    last = solve_scaled(system, solver, options, k_ref, g0, s.state);
    newton += last.newton_iters;
    ++solves;
    if (s.state[n] < 0)
      throw SolverError(
          fmt::format("displacement control: negative V^2 = {:.3e} at delta = "
                      "{:.3e} m (the structure bends away from the electrode?)",
                      s.state[n], delta));
    s.point = {delta, std::sqrt(s.state[n]),
               act.min_gap(std::span<const Real>(s.state).subspan(0, n)), true, last.newton_iters};
    previous = s;
    return s;
  };
  FoldSample rest{{0.0, 0.0, g0, true, 0}, std::vector<Real>(n + 1, 0.0)};
  QuasiStaticPullIn result = trace_fold(solve, rest, g0, options);
  result.newton_iterations = newton;
  result.solves = solves;
  result.last = last;
  return result;
}

std::vector<Real> displacement_control_start(ParallelPlateActuation& actuation,
                                             const QuasiStaticPullIn& curve) {
  const Real v = 0.1 * curve.pull_in_voltage;
  actuation.set_voltage_squared([v](Real) { return v * v; });
  std::vector<Real> state = solve_static(actuation, 0.0).y;
  state.push_back(v * v);
  return state;
}

std::vector<Real> follow_displacement(ParallelPlateActuation& act, Index control,
                                      std::span<const Real> from, const std::vector<Real>& path,
                                      const QuasiStaticOptions& options) {
  const Index n = act.size();
  const Real k_ref = stiffness_scale(act);
  DisplacementControlSystem system(act, control, k_ref);
  // Exact Newton: a path may cross into contact, where the penalty switches on and a kept
  // Jacobian would be wrong.
  KinsolOptions kin = displacement_control_kinsol(options);
  kin.keep_jacobian = false;
  KinsolSolver solver(system, kin);
  std::vector<Real> state(from.begin(), from.end());
  for (const Real delta : path) {
    const Real scale = delta / state[control];
    for (Index i = 0; i < n; ++i) state[i] *= scale;
    system.set_target(delta);
    solve_scaled(system, solver, options, k_ref, act.initial_gap(), state);
  }
  return state;
}

}  // namespace rfmems

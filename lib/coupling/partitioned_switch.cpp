#include "coupling/partitioned_switch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/reduced_inertia_system.hpp"
#include "coupling/aitken_relaxation.hpp"
#include "physics/gas/reynolds_prescribed_motion.hpp"
#include "solvers/ida_integrator.hpp"

namespace rfmems {

namespace {

// Linear in time over [t0, t1] between two per-cell vectors.
struct LinearInTime {
  Real t0 = 0, t1 = 1;
  std::vector<Real> a, b;
  Real at(std::size_t c, Real t) const {
    const Real s = t1 > t0 ? std::clamp((t - t0) / (t1 - t0), 0.0, 1.0) : 1.0;
    return (1 - s) * a[c] + s * b[c];
  }
};

// The actuated plate plus a prescribed gas force per film cell.
class GasLoadedStructure : public SecondOrderOperator {
 public:
  GasLoadedStructure(ParallelPlateActuation& act, const std::vector<Index>& w_dof)
      : act_(act), w_dof_(w_dof) {}
  LinearInTime force;  // (p - p_a) A per cell [N]
  Index size() const override { return act_.size(); }
  void internal_residual(Real t, std::span<const Real> y, std::span<Real> r) override {
    act_.internal_residual(t, y, r);
    for (std::size_t c = 0; c < w_dof_.size(); ++c) r[w_dof_[c]] -= force.at(c, t);
  }
  const CsrPattern& stiffness_pattern() const override { return act_.stiffness_pattern(); }
  void stiffness(Real t, std::span<const Real> y, std::span<Real> values) override {
    act_.stiffness(t, y, values);
  }
  std::vector<Real> mass_diagonal() const override { return act_.mass_diagonal(); }
  Real damping_time() const override { return act_.damping_time(); }
  void add_damping_force(Real t, std::span<const Real> v, std::span<Real> r) override {
    act_.add_damping_force(t, v, r);
  }

 private:
  ParallelPlateActuation& act_;
  const std::vector<Index>& w_dof_;
};

void add_stats(IntegratorStats& sum, const IntegratorStats& s) {
  sum.steps += s.steps;
  sum.residual_evals += s.residual_evals;
  sum.jacobian_evals += s.jacobian_evals;
  sum.newton_iters += s.newton_iters;
  sum.linear_setups += s.linear_setups;
  sum.error_test_fails += s.error_test_fails;
  sum.newton_fails += s.newton_fails;
}

}  // namespace

PartitionedRun run_partitioned(ParallelPlateActuation& act, std::vector<bool> quasi_static,
                               const ReynoldsFilm& film, std::vector<Index> w_dof, Index control,
                               std::function<Real(Real)> voltage, const DynamicOptions& options) {
  const CouplingOptions& part = options.coupling;
  if (part.scheme != CouplingScheme::Staggered && part.scheme != CouplingScheme::StronglyCoupled)
    throw InputError("partitioned coupling: the scheme is staggered or strongly_coupled, not " +
                     coupling_scheme_name(part.scheme));
  if (part.macro_step <= 0) throw InputError("partitioned coupling: macro_step must be > 0");
  act.set_voltage_squared([voltage](Real t) {
    const Real v = voltage(t);
    return v * v;
  });
  const std::size_t nc = film.size();
  const Real pa = film.gas().ambient_pressure, g0 = act.initial_gap();
  const auto& area = film.plate_force_derivative();

  GasLoadedStructure loaded(act, w_dof);
  loaded.force.a.assign(nc, 0.0);
  loaded.force.b.assign(nc, 0.0);
  ReducedInertiaSystem structure(loaded, std::move(quasi_static));
  // The film under the gap and gap rate linear in time over the macro step.
  LinearInTime gap{0, 1, std::vector<Real>(nc, g0), std::vector<Real>(nc, g0)};
  LinearInTime gap_rate{0, 1, std::vector<Real>(nc, 0.0), std::vector<Real>(nc, 0.0)};
  ReynoldsPrescribedMotion gas(film, [&](Real t, std::span<Real> g, std::span<Real> g_rate) {
    for (std::size_t c = 0; c < nc; ++c) {
      g[c] = gap.at(c, t);
      g_rate[c] = gap_rate.at(c, t);
    }
  });

  // States at t_n.
  std::vector<Real> s(structure.size(), 0.0), sp = structure.consistent_derivative(0.0, s);
  std::vector<Real> p(nc, pa), pp(nc, 0.0);
  IdaIntegrator structure_ida(structure, options.ida), gas_ida(gas, options.ida);
  structure_ida.set_roots(
      1, [&](Real, std::span<const Real> y, std::span<const Real>, std::span<Real> g) {
        g[0] = act.min_gap(y) - options.contact_gap;
      });
  auto gap_of = [&](std::span<const Real> y, std::vector<Real>& g, std::vector<Real>& gr) {
    g.resize(nc);
    gr.resize(nc);
    for (std::size_t c = 0; c < nc; ++c) {
      g[c] = g0 + y[w_dof[c]];
      gr[c] = y[structure.velocity_index(w_dof[c])];
    }
  };
  auto gas_force = [&](std::span<const Real> pressure, std::vector<Real>& f) {
    f.resize(nc);
    for (std::size_t c = 0; c < nc; ++c) f[c] = (pressure[c] - pa) * area[c];
  };

  PartitionedRun out;
  DynamicRun& run = out.run;
  auto sample = [&](Real t, std::span<const Real> y, std::span<const Real> pressure) {
    run.history.push_back({t, y[control], act.min_gap(y),
                           act.total_force(act.voltage_squared(t), y), film.total_force(pressure)});
  };
  sample(0.0, s, p);
  std::vector<Real> g_n, gr_n, f_n, f_end, f_prev, r_prev, g_end, gr_end;
  gas_force(p, f_n);
  Real t = 0;
  bool first = true;
  while (t < options.end_time * (1 - 1e-12) && !run.pulled_in) {
    const Real t1 = std::min(options.end_time, t + part.macro_step);
    gap_of(s, g_n, gr_n);
    // The gap at t1: predicted for the first pass (linear extrapolation of the motion).
    g_end.resize(nc);
    gr_end = gr_n;
    for (std::size_t c = 0; c < nc; ++c) g_end[c] = g_n[c] + (t1 - t) * gr_n[c];
    std::vector<Real> s_new, sp_new, p_new, pp_new;
    Real omega = 1.0;
    r_prev.clear();
    f_end = f_n;
    const int passes = part.scheme == CouplingScheme::Staggered ? 1 : part.max_iterations;
    bool converged = false, touched = false;
    Real t_reached = t1;
    for (int k = 0; k < passes; ++k) {
      ++out.coupling_iterations;
      // Film over the step under the gap motion.
      gap = {t, t1, g_n, g_end};
      gap_rate = {t, t1, gr_n, gr_end};
      gas_ida.reinitialize(t, p, pp);
      gas_ida.advance(t1);
      p_new.assign(gas_ida.y().begin(), gas_ida.y().end());
      pp_new.assign(gas_ida.yp().begin(), gas_ida.yp().end());
      add_stats(run.stats, gas_ida.stats());
      std::vector<Real> f_film;
      gas_force(p_new, f_film);
      // Interface force at t1: relaxed (Aitken) after the first pass.
      std::vector<Real> residual(nc);
      Real change = 0, size = 0;
      for (std::size_t c = 0; c < nc; ++c) {
        residual[c] = f_film[c] - f_end[c];
        change = std::max(change, std::abs(residual[c]));
        size = std::max(size, std::abs(f_film[c]));
      }
      // Converged when the force stops changing, relative to its size, or below what the film's
      // integration resolves (10 rtol of the ambient pressure on the largest cell).
      const Real floor = 10 * options.ida.rtol * pa * *std::max_element(area.begin(), area.end());
      if (k > 0 && change <= part.tolerance * size + floor) converged = true;
      if (part.scheme == CouplingScheme::Staggered || k == 0 || converged) {
        f_end = f_film;
      } else {
        // Aitken from the third pass on (the first pass saw the predicted motion only, its
        // residual says nothing about the fixed point's contraction); kept in [0.05, 1].
        if (k >= 2) omega = std::clamp(aitken_factor(omega, residual, r_prev), 0.05, 1.0);
        for (std::size_t c = 0; c < nc; ++c) f_end[c] += omega * residual[c];
      }
      r_prev = residual;
      // Structure over the step under the gas force.
      loaded.force = {t, t1, f_n, f_end};
      structure_ida.reinitialize(t, s, sp);
      if (first) structure_ida.correct_initial_conditions(t1);
      const IdaIntegrator::Status status = structure_ida.advance(t1);
      touched = status == IdaIntegrator::Status::Root;
      t_reached = structure_ida.time();
      s_new.assign(structure_ida.y().begin(), structure_ida.y().end());
      sp_new.assign(structure_ida.yp().begin(), structure_ida.yp().end());
      add_stats(run.stats, structure_ida.stats());
      if (touched || converged || part.scheme == CouplingScheme::Staggered) break;
      gap_of(s_new, g_end, gr_end);
    }
    if (part.scheme == CouplingScheme::StronglyCoupled && !converged && !touched)
      throw SolverError(
          fmt::format("strong coupling: no convergence in {} iterations at t = {:.4e} s",
                      part.max_iterations, t));
    s = s_new;
    sp = sp_new;
    p = p_new;
    pp = pp_new;
    f_n = f_end;
    t = t_reached;
    first = false;
    ++out.macro_steps;
    sample(t, s, p);
    run.extreme_control = std::min(run.extreme_control, s[control]);
    if (touched) {
      run.pulled_in = true;
      run.pull_in_time = t;
    }
  }
  run.final_time = t;
  // The monolithic layout (structure, then film) so callers read either scheme alike.
  run.final_state.t = t;
  run.final_state.y = s;
  run.final_state.y.insert(run.final_state.y.end(), p.begin(), p.end());
  run.final_state.yp = sp;
  run.final_state.yp.insert(run.final_state.yp.end(), pp.begin(), pp.end());
  return out;
}

}  // namespace rfmems

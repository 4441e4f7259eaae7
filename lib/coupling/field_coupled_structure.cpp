#include "coupling/field_coupled_structure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/process_cpu_clock.hpp"
#include "core/reduced_inertia_system.hpp"
#include "coupling/displacement_control_fixed_point.hpp"
#include "coupling/gap_scaled_lagged_load.hpp"
#include "coupling/state_tolerances.hpp"
#include "coupling/time_loop.hpp"
#include "coupling/voltage_control_fixed_point.hpp"
#include "solvers/aitken_relaxation.hpp"
#include "solvers/ida_integrator.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

namespace {

// The stiffness of the linear structure at rest, factorised.
KluFactorization factorised_stiffness(SecondOrderOperator& op) {
  std::vector<Real> values(op.stiffness_pattern().nnz()), rest(op.size(), 0.0);
  op.stiffness(0.0, rest, values);
  return KluFactorization(op.stiffness_pattern(), values);
}

std::vector<Index> cell_gap_unknowns(const ElasticityOperator& beam) {
  std::vector<Index> out;
  for (Index c = 0; c < beam.size() / beam.dim(); ++c) out.push_back(beam.gap_unknown(c));
  return out;
}

}  // namespace

Json CoupledRunTimes::json() const {
  return {{"structure_s", structure},
          {"gas_s", gas},
          {"structure_steps", structure_steps},
          {"gas_steps", gas_steps},
          {"coupling_iterations", coupling_iterations},
          {"max_coupling_iterations", max_coupling_iterations},
          {"unconverged_coupling_steps", unconverged_steps},
          {"max_coupling_residual", max_coupling_residual}};
}

FieldCoupledStructure::FieldCoupledStructure(CoupledStructure structure, GapField& field,
                                             LinearFunctional control)
    : structure_(std::move(structure)), field_(field), control_(std::move(control)) {
  if (!control_.within(structure_.op.size()))
    throw InputError(field.name() +
                     " field: the control is not a functional of the structure's unknowns");
}

FieldCoupledStructure::FieldCoupledStructure(ElasticityOperator& beam, GapField& field,
                                             LinearFunctional control)
    : FieldCoupledStructure({beam, {}, cell_gap_unknowns(beam)}, field, std::move(control)) {}

void FieldCoupledStructure::require_lagged_field() const {
  if (field_.traits().exact)
    throw InputError(field_.name() +
                     " field: its equilibria are Newton solves of the exact system "
                     "(quasi_static_pull_in.hpp), not fixed points");
}

StructureEquilibrium FieldCoupledStructure::solve_static(Real voltage) {
  require_lagged_field();
  const GapFieldTraits traits = field_.traits();
  KluFactorization stiffness = factorised_stiffness(structure_.op);
  StructureEquilibrium out;
  auto load = [&](std::span<const Real> u) {
    StructureLoad l = field_.load(u, voltage);
    out.force_y = l.force_y;
    return std::move(l.force);
  };
  VoltageControlResult r = relax_voltage_control(stiffness, load, structure_.op.size(), control_,
                                                 traits.static_tolerance, traits.max_iterations);
  if (!r.converged)
    throw SolverError(
        fmt::format("{} field: static solve at {:g} V not converged in {} iterations (above the "
                    "quasi-static pull-in?)",
                    field_.name(), voltage, traits.max_iterations));
  out.iterations = r.iterations;
  out.control = control_(r.u);
  out.u = std::move(r.u);
  return out;
}

QuasiStaticPullIn FieldCoupledStructure::trace_quasi_static(const QuasiStaticOptions& options) {
  require_lagged_field();
  const GapFieldTraits traits = field_.traits();
  KluFactorization stiffness = factorised_stiffness(structure_.op);
  long solves = 0;
  auto solve = [&](Real delta, const FoldSample& from) {
    FoldSample s{{}, from.state};
    if (from.point.displacement != 0)
      for (Real& v : s.state) v *= delta / from.point.displacement;
    std::vector<Real>& u = s.state;
    const auto load_per_volt2 = [&](std::span<const Real> state) {
      ++solves;
      return field_.load(state, 1.0).force;
    };
    const DisplacementControlResult r =
        relax_displacement_control(stiffness, load_per_volt2, control_, delta,
                                   traits.quasi_static_tolerance, traits.max_iterations, u);
    if (!r.converged || r.voltage_squared < 0)
      throw SolverError(fmt::format("{} field: quasi-static coupling failed at delta = {:.4e} m",
                                    field_.name(), delta));
    s.point = {delta, std::sqrt(r.voltage_squared), field_.min_gap(u), true, r.iterations + 1};
    return s;
  };
  const Real gap = field_.rest_gap();
  FoldSample rest{{0.0, 0.0, gap, true, 0}, std::vector<Real>(structure_.op.size(), 0.0)};
  QuasiStaticPullIn out = trace_fold(solve, rest, gap, options);
  out.solves = solves;
  return out;
}

DynamicRun FieldCoupledStructure::run(Real voltage, const DynamicOptions& options,
                                      StructureGas* gas) {
  const CouplingScheme scheme = options.coupling.scheme;
  if (scheme == CouplingScheme::Monolithic)
    throw InputError(field_.name() +
                     " field: this loop splits the models; use staggered, implicit or "
                     "strongly_coupled (monolithic: one IDA system, switch_system.hpp)");
  const bool strong = scheme == CouplingScheme::StronglyCoupled;
  if (options.coupling.strong_gas && !strong)
    throw InputError(field_.name() + " field: strong_gas needs the strongly_coupled scheme");
  const GapFieldTraits traits = field_.traits();
  if (!options.stop_at_contact && !traits.exact)
    throw InputError(field_.name() +
                     " field: a run goes on past touch-down only with a contact penalty "
                     "(the parallel_plate field's actuation.contact)");
  if (traits.exact && (scheme == CouplingScheme::Implicit || !gas))
    throw InputError(field_.name() +
                     " field: its load is exact inside the structure; the partitioned schemes "
                     "(staggered, strongly_coupled) split the gas from it");
  // An exact field leaves the gas alone to iterate on.
  const bool gas_inside = strong && gas && (options.coupling.strong_gas || traits.exact);
  if (gas_inside && options.coupling.gas_every != 1)
    throw InputError(field_.name() +
                     " field: the strong iteration advances the gas over every step (gas_every 1)");
  const Index n = structure_.op.size();
  // The field's load at u that the coupling applies (none from an exact field, whose load is in
  // the structure: reported only); a mesh that cannot follow a Newton trial state is
  // recoverable (IDA retries with a smaller step).
  auto field_load = [&](std::span<const Real> u) {
    try {
      StructureLoad l = field_.load(u, voltage);
      if (traits.exact) l.force.assign(n, 0.0);
      return l;
    } catch (const MeshError& e) {
      throw RecoverableError(e.what());
    }
  };

  GapScaledLaggedLoad structure(
      structure_.op, structure_.gap_unknowns, field_.rest_gap(),
      traits.closed_fraction > 0 ? traits.closed_fraction : GapScaledLaggedLoad::kClosedFraction);
  ReducedInertiaSystem system(structure, structure_.quasi_static);
  std::vector<Real> y(system.size(), 0.0);
  StructureLoad load = field_load(std::span<const Real>(y.data(), n));
  structure.set_reference(load.force, std::span<const Real>(y.data(), n));
  if (scheme == CouplingScheme::Implicit)
    structure.set_exact([&](std::span<const Real> u) { return field_load(u).force; });
  Real gas_force = 0;
  if (gas) {
    ScopedCpuTimer t{times_.gas};
    gas->reset(0.0);
  }
  std::vector<Real> yp = system.consistent_derivative(0.0, y);

  StateTolerances tolerances = options.tolerances;
  if (!tolerances.enabled() && traits.velocity_rate > 0)
    tolerances = {options.ida.atol, traits.velocity_rate};
  IdaOptions ida_options = options.ida;
  if (tolerances.enabled())
    ida_options.atols =
        absolute_tolerances(reduced_inertia_state_kinds(system, n), tolerances, options.ida.atol);
  IdaIntegrator ida(system, ida_options);
  ida.initialize(0.0, y, yp);

  Real t_gas = 0;  // the gas's time: it advances every gas_every accepted steps
  int since_gas = 0;
  std::vector<Real> held(n, 0.0);  // the gas load in the structure's residual
  // The gas over [t_gas, t_end] with the beam at state's displacement and velocity.
  auto advance_gas = [&](std::span<const Real> state, Real t_end) {
    ScopedCpuTimer timer{times_.gas};
    std::vector<Real> v(n, 0.0);  // zero on the quasi-static components
    for (Index i = 0; i < n; ++i)
      if (system.velocity_index(i) >= 0) v[i] = state[system.velocity_index(i)];
    StructureLoad f = gas->advance(state.subspan(0, n), v, t_gas, t_end - t_gas);
    ++times_.gas_steps;
    gas_force = f.force_y;
    return std::move(f.force);
  };
  // One structural step; its CPU without the field's share (the implicit scheme's loads).
  auto structure_step = [&](Real t_stop) {
    const double cpu0 = process_cpu_seconds(), field0 = field_.seconds();
    const IdaIntegrator::Status status = ida.step(t_stop);
    times_.structure += std::max(0.0, process_cpu_seconds() - cpu0 - (field_.seconds() - field0));
    return status;
  };
  // Strong coupling per step (block Gauss-Seidel with Aitken relaxation): the step is redone
  // from IDA's checkpoint with the interface load G_k, applied as G_k (g_k / g(u))^2 with g_k
  // the gap of iterate k's end state (k = 0 is the staggered step: G_0 = F(u_n) at g_n), until
  // the field's load F(u_k) at the step's end state (IDA's t_n, also after a root return)
  // matches the load A_k applied there: |r_k| <= tol |F(u_k)|, r_k = F(u_k) - A_k; then
  // G_{k+1} = A_k + omega_k r_k, omega_0 = 1 and Aitken's factor after. With strong_gas every
  // iterate also redoes the gas's step from the gas's checkpoint with u_k and its velocity, and
  // the interface load is the sum: F = F_e(u_k) + F_g(u_k), A_k = A_e,k + H_k (H_k the gas
  // load held over iterate k, H_0 the last step's gas force), one Aitken factor on the summed
  // residual, each part relaxed by it (G_e = A_e + omega r_e, H = H_k + omega r_g).
  auto strong_step = [&](Real t_stop) {
    ida.save_checkpoint();
    if (gas_inside) {
      ScopedCpuTimer t{times_.gas};
      gas->save_checkpoint();
    }
    std::vector<Real> residual_prev;
    Real omega = 1;
    for (int k = 0;; ++k) {
      const IdaIntegrator::Status status = structure_step(t_stop);
      const std::span<const Real> y_end = ida.internal_y();
      const std::span<const Real> u_end = y_end.subspan(0, n);
      const std::vector<Real> applied = structure.applied(u_end);
      load = field_load(u_end);
      // After a root return IDA's next call may end at the same t_n: the gas is there already.
      const Real t_end = ida.internal_time();
      const bool gas_steps = gas_inside && t_end > t_gas;
      std::vector<Real> gas_load = held;
      if (gas_steps) {
        if (k > 0) {
          ScopedCpuTimer t{times_.gas};
          gas->restore_checkpoint();
        }
        gas_load = advance_gas(y_end, t_end);
        if (k == 0) gas->hold_marking(true);  // the later iterates on iterate 0's marking
      }
      ++times_.coupling_iterations;
      std::vector<Real> residual(n);
      Real r2 = 0, f2 = 0;
      for (Index i = 0; i < n; ++i) {
        const Real total = load.force[i] + (gas_inside ? gas_load[i] : 0);
        residual[i] = total - applied[i] - (gas_inside ? held[i] : 0);
        r2 += residual[i] * residual[i];
        f2 += total * total;
      }
      const bool converged = r2 <= options.coupling.tolerance * options.coupling.tolerance * f2;
      if (converged || k + 1 >= options.coupling.max_iterations) {
        times_.unconverged_steps += !converged;
        times_.max_coupling_iterations = std::max(times_.max_coupling_iterations, k + 1);
        if (f2 > 0)
          times_.max_coupling_residual = std::max(times_.max_coupling_residual, std::sqrt(r2 / f2));
        structure.set_reference(load.force, u_end);  // the next step's k = 0
        if (gas_inside) gas->hold_marking(false);
        if (gas_steps) {
          held = std::move(gas_load);
          structure.set_held(held);
          t_gas = t_end;
        }
        return status;
      }
      if (k > 0) omega = std::clamp(aitken_factor(omega, residual, residual_prev), 0.01, 4.0);
      std::vector<Real> next(n);
      for (Index i = 0; i < n; ++i) next[i] = applied[i] + omega * (load.force[i] - applied[i]);
      structure.set_reference(std::move(next), u_end);
      if (gas_steps) {
        for (Index i = 0; i < n; ++i) held[i] += omega * (gas_load[i] - held[i]);
        structure.set_held(held);
      }
      residual_prev = std::move(residual);
      ida.restore_checkpoint();
    }
  };

  // The events (run_events.hpp) on the field's smallest gap and the control's deflection and
  // velocity (the same weights on the velocity unknowns).
  const LinearFunctional velocity =
      control_.mapped([&system](Index i) { return system.velocity_index(i); });
  TimeLoopScheme steps;
  steps.turning_after = traits.turning_after;
  steps.watch = [&](std::span<const Real> yy, std::span<const Real>) {
    return RunWatch{field_.min_gap(yy.subspan(0, n)), control_(yy), velocity(yy)};
  };
  steps.step = [&](Real t_stop) {
    ++times_.structure_steps;
    return strong ? strong_step(t_stop) : structure_step(t_stop);
  };
  // The coupled step's exchange at the accepted state: the field's load (strong_step left it
  // there as the reference already; none needed where the run ends pulled in), and the gas.
  // The forces exchanged at the last two points, for the samples between them.
  struct Exchanged {
    Real t, field, gas;
  } before{0.0, load.force_y, 0.0}, now = before;
  steps.exchange = [&](Real t, bool last, const DynamicRun& run) {
    const std::span<const Real> state = ida.y();
    const std::span<const Real> u = state.subspan(0, n);
    if (!strong && (!last || !run.pulled_in)) {
      load = field_load(u);
      structure.set_reference(load.force, u);
    }
    if (gas && !gas_inside && t > t_gas && (++since_gas >= options.coupling.gas_every || last)) {
      since_gas = 0;
      held = advance_gas(state, t);
      structure.set_held(held);  // the lagged gas force
    }
    if (since_gas == 0 && !gas_inside) t_gas = t;
    before = now;
    now = {t, load.force_y, gas_force};
  };
  steps.forces = [&](Real, std::span<const Real>) {
    return RunForces{voltage, now.field, now.gas};
  };
  // The forces linear in time between the last two exchanges.
  steps.sample = [&](Real t, std::span<const Real> y) {
    const std::span<const Real> u = y.subspan(0, n);
    const Real s =
        now.t > before.t ? std::clamp((t - before.t) / (now.t - before.t), 0.0, 1.0) : 1.0;
    return DynamicSample{t,
                         control_(u),
                         field_.min_gap(u),
                         before.field + s * (now.field - before.field),
                         before.gas + s * (now.gas - before.gas),
                         0,
                         voltage};
  };
  DynamicRun out = run_time_loop(ida, options, steps);
  if (gas) times_.gas_max_knudsen = std::max(times_.gas_max_knudsen, gas->max_knudsen());
  return out;
}

}  // namespace rfmems

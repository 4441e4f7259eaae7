#include "coupling/laplace_dynamic_switch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/process_cpu_clock.hpp"
#include "core/reduced_inertia_system.hpp"
#include "coupling/gap_scaled_lagged_load.hpp"
#include "coupling/state_tolerances.hpp"
#include "coupling/step_voltage_run.hpp"
#include "coupling/switch_system.hpp"
#include "coupling/voltage_control_fixed_point.hpp"
#include "solvers/ida_integrator.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

LaplaceDynamicSwitch::LaplaceDynamicSwitch(ElasticityOperator& beam,
                                           const std::string& bottom_patch, Real gap,
                                           const ElectrodeExtent& electrode, Index control,
                                           const LaplaceGapOptions& options)
    : beam_(beam), field_(beam, bottom_patch, gap, electrode, options), control_(control) {
  if (control < 0 || control >= beam.size())
    throw InputError("Laplace switch: the control unknown is not a beam unknown");
}

LaplaceStatic LaplaceDynamicSwitch::solve_static(Real voltage, Real tolerance, int max_iterations) {
  const Index n = beam_.size();
  std::vector<Real> k_values(beam_.stiffness_pattern().nnz()), rest(n, 0.0);
  beam_.stiffness(0.0, rest, k_values);
  KluFactorization stiffness(beam_.stiffness_pattern(), k_values);
  auto load = [&](std::span<const Real> u) {
    std::vector<Real> z = field_.load_per_volt2(u);
    for (Real& v : z) v *= voltage * voltage;
    return z;
  };
  VoltageControlResult r = relax_voltage_control(
      stiffness, load, n, LinearFunctional::unknown(control_), tolerance, max_iterations);
  if (!r.converged)
    throw SolverError(fmt::format(
        "Laplace switch: static solve at {:g} V not converged in {} iterations (above the "
        "quasi-static pull-in?)",
        voltage, max_iterations));
  LaplaceStatic out;
  out.iterations = r.iterations;
  out.control = r.u[control_];
  out.u = std::move(r.u);
  return out;
}

DynamicRun LaplaceDynamicSwitch::run(Real voltage, const DynamicOptions& options) {
  const CouplingScheme scheme = options.coupling.scheme;
  if (scheme != CouplingScheme::Staggered && scheme != CouplingScheme::Implicit)
    throw InputError("Laplace switch: the field steps staggered or implicit, not " +
                     coupling_scheme_name(scheme));
  const Index n = beam_.size();
  const Real v2 = voltage * voltage;
  const double move0 = field_.move_seconds(), field0 = field_.field_seconds();
  const long solves0 = field_.solves();
  // The field's force at u; an inverted gap cell at a Newton trial state is recoverable (IDA
  // retries with a smaller step).
  auto load = [&](std::span<const Real> u) {
    std::vector<Real> q;
    try {
      q = field_.load_per_volt2(u);
    } catch (const MeshError& e) {
      throw RecoverableError(e.what());
    }
    for (Real& x : q) x *= v2;
    return q;
  };

  GapScaledLaggedLoad structure(beam_, field_.gap());
  ReducedInertiaSystem system(structure, {});  // every component inertial
  std::vector<Real> y(system.size(), 0.0);
  const std::span<const Real> rest(y.data(), n);
  structure.set_reference(load(rest), rest);
  if (scheme == CouplingScheme::Implicit) structure.set_exact(load);
  std::vector<Real> yp = system.consistent_derivative(0.0, y);

  IdaOptions ida_options = options.ida;
  if (options.tolerances.enabled())
    ida_options.atols = absolute_tolerances(reduced_inertia_state_kinds(system, n),
                                            options.tolerances, options.ida.atol);
  IdaIntegrator ida(system, ida_options);
  ida.initialize(0.0, y, yp);
  const Index vc = system.velocity_index(control_);
  StepVoltageEvents events(options.stop_at_turning, options.turning_retreat, 0.0,
                           early_ends(options));
  events.set_roots(ida, n, LinearFunctional::unknown(control_), LinearFunctional::unknown(vc),
                   options.contact_gap,
                   [&](std::span<const Real> u) { return field_.cell_min_gap(u); });

  std::vector<StepRecord> records{{0.0, 0.0, 0.0, field_.gap(), v2 * field_.last_force_y(), 0.0}};
  DynamicRun out;
  const double cpu0 = process_cpu_seconds();
  while (true) {
    const IdaIntegrator::Status status = ida.step(options.end_time);
    const Real t = ida.time();
    const std::span<const Real> state = ida.y();
    const std::span<const Real> u = state.subspan(0, n);
    const bool stop = events.after_step(ida, status, t, u[control_], out);
    // The coupled step's exchange: the field at the accepted state (implicit: the reference
    // of the Jacobian's lagged model, and the recorded force).
    if (!stop || !out.pulled_in) {
      std::vector<Real> f = load(u);
      structure.set_reference(std::move(f), u);
    }
    records.push_back(
        {t, u[control_], state[vc], field_.cell_min_gap(u), v2 * field_.last_force_y(), 0.0});
    if (stop || events.after_record(records.back(), voltage, out)) break;
  }
  // The structure's share excludes the field solves made inside residual calls (implicit).
  const double field_cpu = field_.move_seconds() - move0 + field_.field_seconds() - field0;
  times_.move += field_.move_seconds() - move0;
  times_.field += field_.field_seconds() - field0;
  times_.structure += std::max(0.0, process_cpu_seconds() - cpu0 - field_cpu);
  times_.field_solves += field_.solves() - solves0;
  finish_step_voltage_run(ida, records, voltage, options.output_interval, false, out);
  times_.structure_steps += out.stats.steps;
  return out;
}

}  // namespace rfmems

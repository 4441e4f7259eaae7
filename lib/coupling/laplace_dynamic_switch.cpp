#include "coupling/laplace_dynamic_switch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/process_cpu_clock.hpp"
#include "core/reduced_inertia_system.hpp"
#include "coupling/gap_scaled_lagged_load.hpp"
#include "coupling/state_tolerances.hpp"
#include "coupling/switch_system.hpp"
#include "solvers/ida_integrator.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

std::string laplace_coupling_name(LaplaceCoupling coupling) {
  return coupling == LaplaceCoupling::Implicit ? "implicit" : "staggered";
}

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
  std::vector<Real> k_values(beam_.stiffness_pattern().nnz()), u(n, 0.0);
  beam_.stiffness(0.0, u, k_values);
  KluFactorization stiffness(beam_.stiffness_pattern(), k_values);
  LaplaceStatic out;
  for (int it = 0; it < max_iterations; ++it) {
    std::vector<Real> z = field_.load_per_volt2(u);
    for (Real& v : z) v *= voltage * voltage;
    stiffness.solve(z);
    const Real change = std::abs(z[control_] - u[control_]);
    u = std::move(z);
    out.iterations = it + 1;
    if (change <= tolerance * std::abs(u[control_])) {
      out.control = u[control_];
      out.u = std::move(u);
      return out;
    }
  }
  throw SolverError(fmt::format(
      "Laplace switch: static solve at {:g} V not converged in {} iterations (above the "
      "quasi-static pull-in?)",
      voltage, max_iterations));
}

DynamicRun LaplaceDynamicSwitch::run(Real voltage, const DynamicOptions& options,
                                     LaplaceCoupling coupling) {
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
  if (coupling == LaplaceCoupling::Implicit) structure.set_exact(load);
  std::vector<Real> yp = system.consistent_derivative(0.0, y);

  IdaOptions ida_options = options.ida;
  if (options.tolerances.enabled())
    ida_options.atols = absolute_tolerances(reduced_inertia_state_kinds(system, n),
                                            options.tolerances, options.ida.atol);
  IdaIntegrator ida(system, ida_options);
  ida.initialize(0.0, y, yp);
  const Index vc = system.velocity_index(control_);
  ida.set_roots(2, [&](Real, std::span<const Real> yy, std::span<const Real>, std::span<Real> g) {
    g[0] = field_.cell_min_gap(yy.subspan(0, n)) - options.contact_gap;
    g[1] = yy[vc];
  });

  struct Raw {
    Real t, u, v, gap, fe;
  };
  std::vector<Raw> raw{{0.0, 0.0, 0.0, field_.gap(), v2 * field_.last_force_y()}};
  DynamicRun out;
  bool moved_down = false;
  const double cpu0 = process_cpu_seconds();
  while (true) {
    const IdaIntegrator::Status status = ida.step(options.end_time);
    const Real t = ida.time();
    const std::span<const Real> state = ida.y();
    const std::span<const Real> u = state.subspan(0, n);
    out.extreme_control = std::min(out.extreme_control, u[control_]);
    if (u[control_] < 0) moved_down = true;
    bool stop = status == IdaIntegrator::Status::Reached;
    if (status == IdaIntegrator::Status::Root) {
      const std::vector<int> found = ida.roots_found();
      if (found[0] < 0) {
        ++out.touch_downs;
        out.pulled_in = true;
        out.pull_in_time = t;
        stop = true;
      } else if (found[1] > 0 && moved_down && out.turning_time == 0) {
        out.turning_time = t;
        stop = stop || options.stop_at_turning;
      }
    }
    // The coupled step's exchange: the field at the accepted state (implicit: the reference
    // of the Jacobian's lagged model, and the recorded force).
    if (!stop || !out.pulled_in) {
      std::vector<Real> f = load(u);
      structure.set_reference(std::move(f), u);
    }
    raw.push_back({t, u[control_], state[vc], field_.cell_min_gap(u), v2 * field_.last_force_y()});
    if (stop) break;
  }
  out.final_time = ida.time();
  out.final_state = {ida.time(), std::vector<Real>(ida.y().begin(), ida.y().end()),
                     std::vector<Real>(ida.yp().begin(), ida.yp().end())};
  out.stats = ida.stats();
  // The structure's share excludes the field solves made inside residual calls (implicit).
  const double field_cpu = field_.move_seconds() - move0 + field_.field_seconds() - field0;
  times_.move += field_.move_seconds() - move0;
  times_.field += field_.field_seconds() - field0;
  times_.structure += std::max(0.0, process_cpu_seconds() - cpu0 - field_cpu);
  times_.field_solves += field_.solves() - solves0;
  times_.structure_steps += out.stats.steps;

  auto sample = [&](const Raw& r) {
    DynamicSample s{r.t, r.u, r.gap, r.fe, 0.0};
    s.voltage = voltage;
    return s;
  };
  if (options.output_interval <= 0) {
    for (const Raw& r : raw) out.history.push_back(sample(r));
    return out;
  }
  // Uniform samples: cubic Hermite in (u, v) of the control; the other columns linear.
  std::size_t j = 0;
  for (Real t = 0; t < out.final_time; t += options.output_interval) {
    while (j + 2 < raw.size() && raw[j + 1].t < t) ++j;
    const Raw& a = raw[j];
    const Raw& b = raw[std::min(j + 1, raw.size() - 1)];
    const Real h = b.t - a.t;
    const Real s = h > 0 ? std::clamp((t - a.t) / h, 0.0, 1.0) : 0.0;
    const Real h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
    const Real h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
    out.history.push_back(sample({t, h00 * a.u + h10 * h * a.v + h01 * b.u + h11 * h * b.v, 0,
                                  (1 - s) * a.gap + s * b.gap, (1 - s) * a.fe + s * b.fe}));
  }
  out.history.push_back(sample(raw.back()));
  return out;
}

}  // namespace rfmems

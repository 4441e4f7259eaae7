// The static and transient analyses of a StructuralModel (see the header for the keys).
#include "physics/structure/structural_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <vector>

#include "core/error.hpp"
#include "core/process_cpu_clock.hpp"
#include "core/reduced_inertia_system.hpp"
#include "core/structural_systems.hpp"
#include "io/case_schema_yaml.hpp"
#include "io/frequency_sweep.hpp"
#include "physics/structure/output_schedule.hpp"
#include "solvers/harmonic_response.hpp"
#include "solvers/static_solve.hpp"

namespace rfmems {

namespace {

// Largest edge of the mesh's bounding box: the length scale of the default atol.
Real mesh_extent(const Mesh& mesh) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::infinity()), hi = -lo;
  for (const Vec3& x : mesh.nodes()) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return mesh.n_nodes() > 0 ? (hi - lo).maxCoeff() : 1.0;
}

AnalysisStats run_static(StructuralModel& model, const AnalysisSettings& settings,
                         AnalysisObserver& observer) {
  AnalysisStats stats;
  stats.type = AnalysisType::Static;
  stats.static_method = model.static_method();
  const Real t = model.ramp_end_time();
  std::vector<Real> u(model.structure().size(), 0.0);
  if (!model.solve_static_otherwise(t, settings, u, stats)) {
    KinsolOptions options;
    options.relative_tolerance = settings.tolerance;
    options.max_iterations = static_cast<int>(settings.max_iterations);
    StaticSolution solution = solve_static(model.structure(), t, options);
    u = std::move(solution.y);
    stats.newton = solution.stats;
    if (solution.stats.umfpack) stats.linear_solver = "umfpack";
  }
  observer.output(0, t, u, {});
  stats.n_outputs = 1;
  stats.final_time = t;
  return stats;
}

// The first-order system for IDA: full inertia, or the quasi-static components algebraic.
std::unique_ptr<SystemOperator> first_order_system(StructuralModel& model) {
  const std::vector<bool> quasi_static = model.quasi_static_components();
  const bool reduced =
      std::find(quasi_static.begin(), quasi_static.end(), true) != quasi_static.end();
  if (reduced) return std::make_unique<ReducedInertiaSystem>(model.structure(), quasi_static);
  return std::make_unique<FirstOrderSystem>(model.structure());
}

AnalysisStats run_transient(StructuralModel& model, const AnalysisSettings& settings,
                            AnalysisObserver& observer, ProgressReporter& progress) {
  AnalysisStats stats;
  stats.type = AnalysisType::Transient;
  SecondOrderOperator& op = model.structure();
  const Index n = op.size();
  std::unique_ptr<SystemOperator> system = first_order_system(model);
  auto* reduced = dynamic_cast<ReducedInertiaSystem*>(system.get());

  // From rest; the acceleration balances whatever load acts at t = 0.
  std::vector<Real> y(system->size(), 0.0), yp;
  if (reduced) {
    yp = reduced->consistent_derivative(0.0, y);
  } else {
    std::vector<Real> r(n);
    yp.assign(system->size(), 0.0);
    op.internal_residual(0.0, std::span<const Real>(y).subspan(0, n), r);
    const std::vector<Real> mass = op.mass_diagonal();
    for (Index i = 0; i < n; ++i) yp[n + i] = -r[i] / mass[i];
  }

  IdaIntegrator ida(*system, settings.ida);
  ida.initialize(0.0, y, yp);
  const Real dt = settings.output_interval, t_end = settings.end_time;
  // Quasi-static components must balance the load at t = 0 (zero when loads ramp from 0).
  if (reduced) ida.correct_initial_conditions(std::min(dt, t_end));
  // Velocities of the state, per structural component (zero for quasi-static ones).
  std::vector<Real> v(n, 0.0);
  auto emit = [&](int index, Real t) {
    const auto state = ida.y();
    if (reduced) {
      for (Index i = 0; i < n; ++i) {
        const Index k = reduced->velocity_index(i);
        v[i] = k >= 0 ? state[k] : ida.yp()[i];
      }
    } else {
      std::copy(state.begin() + n, state.begin() + 2 * n, v.begin());
    }
    observer.output(index, t, state.subspan(0, n), v);
  };
  emit(0, 0.0);

  const long n_intervals = advance_through_outputs(
      ida, dt, t_end, emit,
      [&](Real t, const IntegratorStats& s) { progress.update(t, s.last_step, s.steps); });
  stats.transient = ida.stats();
  stats.n_outputs = static_cast<int>(n_intervals) + 1;
  stats.final_time = t_end;
  return stats;
}

AnalysisStats run_modal(StructuralModel& model, const AnalysisSettings& settings,
                        AnalysisObserver& observer) {
  AnalysisStats stats;
  stats.type = AnalysisType::Modal;
  KinsolOptions options;
  options.relative_tolerance = settings.tolerance;
  options.max_iterations = static_cast<int>(settings.max_iterations);
  const StructuralModes modes =
      structural_modes(model, settings.modes, settings.shift_frequency, options);
  for (std::size_t k = 0; k < modes.shapes.size(); ++k)
    observer.output(static_cast<int>(k), static_cast<Real>(k + 1), modes.shapes[k], {});
  stats.modal = modes.stats;
  stats.newton = modes.stats.newton;
  stats.n_outputs = static_cast<int>(modes.shapes.size());
  stats.final_time = modes.stats.state_time;
  return stats;
}

AnalysisStats run_harmonic(StructuralModel& model, const AnalysisSettings& settings,
                           AnalysisObserver& observer) {
  AnalysisStats stats;
  stats.type = AnalysisType::Harmonic;
  const Real t = model.ramp_end_time();
  const Index n = model.structure().size();
  std::unique_ptr<SystemOperator> system = first_order_system(model);
  // About rest, F(t, x, x') = F(t, 0, 0) + A x + B x': the loads' amplitude is F(t, 0, 0).
  const std::vector<Real> rest(system->size(), 0.0);
  std::vector<Real> load(system->size());
  system->residual(t, rest, rest, load);
  HarmonicResponse response(*system, t, rest);
  std::vector<Real> real(n), imag(n);
  for (std::size_t k = 0; k < settings.frequencies.size(); ++k) {
    const Real f = settings.frequencies[k];
    std::vector<std::complex<Real>> x;
    {
      ScopedCpuTimer timer{stats.harmonic.solve_seconds};
      x = response.solve(2 * M_PI * f, load, rest);
    }
    for (Index i = 0; i < n; ++i) real[i] = x[i].real(), imag[i] = x[i].imag();
    observer.harmonic_output(static_cast<int>(k), f, t, real, imag);
  }
  stats.harmonic.frequencies = settings.frequencies;
  stats.harmonic.factorizations = response.fresh_factorizations();
  stats.harmonic.refactorizations = response.refactorizations();
  stats.n_outputs = static_cast<int>(settings.frequencies.size());
  stats.final_time = t;
  return stats;
}

}  // namespace

AnalysisType read_analysis_type(const CaseNode& root) {
  const std::string type =
      root.child("analysis").get_choice("type", {"static", "transient", "modal", "harmonic"});
  if (type == "modal") return AnalysisType::Modal;
  if (type == "harmonic") return AnalysisType::Harmonic;
  return type == "static" ? AnalysisType::Static : AnalysisType::Transient;
}

AnalysisSettings read_analysis_settings(const CaseNode& root, StructuralModel& model) {
  AnalysisSettings s;
  s.type = read_analysis_type(root);
  const CaseNode analysis = root.child("analysis");
  const CaseNode solver = root.child_or_empty("solver");
  s.distributed = solver.get_bool("distributed", false);
  const std::string linear = solver.get_choice("linear", {"auto", "direct", "multigrid"}, "auto");
  s.linear = linear == "direct"      ? AnalysisSettings::Linear::Direct
             : linear == "multigrid" ? AnalysisSettings::Linear::Multigrid
                                     : AnalysisSettings::Linear::Auto;
  if (s.type == AnalysisType::Modal) {
    // The most modes the eigensolver can return: the unknowns with inertia less 2.
    const std::vector<Real> mass = modal_mass(model);
    const Index most = max_shift_invert_modes(mass);
    s.modes = analysis.get_int("modes", 6,
                               Range::closed(1, static_cast<double>(std::max<Index>(most, 1))));
    analysis.require(most >= 1, "modes",
                     "the structure has too few unknowns with inertia for a modal analysis");
    s.shift_frequency =
        analysis.get_quantity("shift", Dimension::Frequency, 0.0, Range::non_negative());
  }
  if (s.type == AnalysisType::Harmonic) {
    s.frequencies = read_frequency_sweep(analysis);
    return s;
  }
  if (s.type == AnalysisType::Static || s.type == AnalysisType::Modal) {
    const bool newton = model.static_method() == "newton";
    s.tolerance = solver.get_real("tolerance", 1e-6, Range::open(0.0, 1.0));
    s.max_iterations =
        solver.get_int("max_iterations", newton ? 50 : 100000, Range::closed(1, 1e9));
    return s;
  }
  s.end_time = analysis.get_quantity("end_time", Dimension::Time, Range::positive());
  s.output_interval = analysis.get_quantity("output_interval", Dimension::Time, Range::positive());
  analysis.require(s.output_interval <= s.end_time, "output_interval",
                   "must not exceed analysis.end_time");
  analysis.require(s.end_time / s.output_interval <= 1e6, "output_interval",
                   "more than a million outputs; choose a longer interval");
  s.ida.rtol = solver.get_real("rtol", 1e-6, Range::open(0.0, 1.0));
  // Small-strain displacements are up to ~1e-4 of the body's size: allow rtol of that.
  s.ida.atol = solver.get_quantity("atol", Dimension::Length,
                                   s.ida.rtol * 1e-4 * mesh_extent(model.structure_mesh()),
                                   Range::positive());
  // BDF3-5 are not A-stable: on undamped elastodynamics (eigenvalues on the imaginary axis)
  // IDA collapses its step at those orders, so structural transients default to 2.
  s.ida.max_order = static_cast<int>(solver.get_int("max_order", 2, Range::closed(1, 5)));
  s.ida.fixed_step = solver.get_quantity("fixed_step", Dimension::Time, 0.0, Range::non_negative());
  return s;
}

std::string to_string(AnalysisType type) {
  switch (type) {
    case AnalysisType::Static:
      return "static";
    case AnalysisType::Transient:
      return "transient";
    case AnalysisType::Modal:
      return "modal";
    case AnalysisType::Harmonic:
      return "harmonic";
  }
  return "";
}

AnalysisStats run_analysis(StructuralModel& model, const AnalysisSettings& settings,
                           AnalysisObserver& observer, ProgressReporter& progress) {
  switch (settings.type) {
    case AnalysisType::Static:
      return run_static(model, settings, observer);
    case AnalysisType::Modal:
      return run_modal(model, settings, observer);
    case AnalysisType::Harmonic:
      return run_harmonic(model, settings, observer);
    case AnalysisType::Transient:
      break;
  }
  return run_transient(model, settings, observer, progress);
}

CaseSchema structural_analysis_case_keys() {
  return embedded_case_schema("physics/structure/structural_analysis.keys.yaml");
}

}  // namespace rfmems

// Fields, probe samples, metadata and the JSON summary of a structural run.
#include "physics/structure/structural_results.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>

namespace rfmems {

StructuralResults::StructuralResults(const std::string& path, const StructuralModel& model,
                                     std::vector<Probe> probes)
    : model_(model),
      writer_(path, model.structure_mesh()),
      probes_(std::move(probes)),
      history_(probes_.size()) {}

void StructuralResults::output(int index, Real t, std::span<const Real> y,
                               std::span<const Real> v) {
  model_.write_fields(writer_, index, t, y, v);
  history_.add(t, model_.probe_values(probes_, t, y));
}

void StructuralResults::harmonic_output(int index, Real frequency, Real t_load,
                                        std::span<const Real> real, std::span<const Real> imag) {
  model_.write_fields(writer_, index, frequency, real, {});
  // The probes are affine in the state: their constant (prescribed boundary values) belongs to
  // the real part, the load's amplitude.
  const std::vector<Real> zero(real.size(), 0.0);
  const std::vector<Vec3> re = model_.probe_values(probes_, t_load, real);
  const std::vector<Vec3> im = model_.probe_values(probes_, t_load, imag);
  const std::vector<Vec3> constant = model_.probe_values(probes_, t_load, zero);
  harmonic_.resize(probes_.size());
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    std::array<std::complex<Real>, 3> value;
    for (int k = 0; k < 3; ++k) value[k] = {re[p][k], im[p][k] - constant[p][k]};
    harmonic_[p].push_back(value);
  }
}

void StructuralResults::finish(const CaseFile& case_file, const std::string& case_name,
                               const AnalysisStats& stats, Real wall_seconds) {
  const auto components = model_.probe_components();
  if (stats.type == AnalysisType::Modal) {
    std::vector<double> numbers;
    std::vector<std::vector<double>> values;
    for (const StructuralMode& m : stats.modal.modes) {
      numbers.push_back(static_cast<double>(m.number));
      values.push_back({m.frequency, m.angular_frequency, m.damping_ratio, m.eigenvalue.real(),
                        m.eigenvalue.imag(), m.complex ? 1.0 : 0.0, m.residual});
    }
    writer_.write_time_series("modal", "modes", numbers, values,
                              {"frequency", "angular_frequency", "damping_ratio", "eigenvalue_real",
                               "eigenvalue_imag", "complex", "residual"},
                              "mode", {"Hz", "rad/s", "1", "rad^2/s^2", "rad^2/s^2", "1", "1"});
  }
  if (stats.type == AnalysisType::Harmonic) {
    std::vector<std::string> names;
    for (const std::string& c : components) names.push_back("re_" + c), names.push_back("im_" + c);
    for (std::size_t p = 0; p < harmonic_.size(); ++p) {
      std::vector<std::vector<double>> values;
      for (const auto& sample : harmonic_[p]) {
        std::vector<double> row;
        for (const std::complex<Real>& z : sample) row.push_back(z.real()), row.push_back(z.imag());
        values.push_back(row);
      }
      writer_.write_time_series("harmonic", probes_[p].name, stats.harmonic.frequencies, values,
                                names, "frequency", std::vector<std::string>(6, ""));
    }
  }
  for (std::size_t p = 0; p < probes_.size() && stats.type != AnalysisType::Harmonic; ++p)
    writer_.write_time_series("probes", probes_[p].name, history_.times(), history_.series(p),
                              {components.begin(), components.end()});
  std::map<std::string, double> numbers;
  const Json solver = solver_stats_json(stats);  // named: items() refers into it
  for (const auto& [key, value] : solver.items())
    if (value.is_number()) numbers["solver_" + key] = value.get<double>();
  numbers["wall_time_s"] = wall_seconds;
  writer_.write_metadata({{"case_file", case_file.path()},
                          {"case_name", case_name},
                          {"case_text", case_file.text()},
                          {"case_effective", case_file.effective_text()},
                          {"overrides", fmt::format("{}", fmt::join(case_file.overrides(), "\n"))},
                          {"analysis", to_string(stats.type)},
                          {"model", model_.kind()},
                          {"static_method", stats.static_method},
                          {"linear_solver", stats.linear_solver}},
                         numbers);
  writer_.finish();
}

Json solver_stats_json(const AnalysisStats& stats) {
  Json j = Json::object();
  if (stats.type == AnalysisType::Modal) {
    const ShiftInvertStats& s = stats.modal.eigen;
    j["modes_requested"] = s.requested;
    j["modes_converged"] = s.converged;
    j["operator_applications"] = s.operator_applications;
    j["restarts"] = s.restarts;
    j["subspace"] = s.subspace;
    j["factor_time_s"] = s.factor_seconds;
    j["eigensolve_time_s"] = s.solve_seconds;
    j["static_newton_iterations"] = stats.modal.newton.newton_iters;
  } else if (stats.type == AnalysisType::Harmonic) {
    j["frequencies"] = stats.harmonic.frequencies.size();
    j["factorizations"] = stats.harmonic.factorizations;
    j["refactorizations"] = stats.harmonic.refactorizations;
    j["solve_cpu_s"] = stats.harmonic.solve_seconds;
  } else if (stats.type == AnalysisType::Transient) {
    const IntegratorStats& s = stats.transient;
    j["steps"] = s.steps;
    j["residual_evals"] = s.residual_evals;
    j["jacobian_evals"] = s.jacobian_evals;
    j["newton_iterations"] = s.newton_iters;
    j["linear_setups"] = s.linear_setups;
    j["error_test_fails"] = s.error_test_fails;
    j["newton_fails"] = s.newton_fails;
    j["last_order"] = s.last_order;
    j["last_step"] = s.last_step;
  } else if (stats.static_method == "newton") {
    const NonlinearStats& s = stats.newton;
    j["newton_iterations"] = s.newton_iters;
    j["residual_evals"] = s.residual_evals;
    j["jacobian_evals"] = s.jacobian_evals;
    j["residual_initial"] = s.initial_residual;
    j["residual_final"] = s.final_residual;
  } else {
    const SegregatedStats& s = stats.segregated;
    j["outer_iterations"] = s.outer_iterations;
    j["residual_initial"] = s.initial_residual;
    j["residual_final"] = s.final_residual;
  }
  if (stats.type == AnalysisType::Static || stats.type == AnalysisType::Transient)
    j["linear_solver"] = stats.linear_solver;
  if (stats.multigrid_levels > 0) {
    j["multigrid_levels"] = stats.multigrid_levels;
    j["multigrid_operator_complexity"] = stats.multigrid_complexity;
  }
  if (stats.distributed_ranks > 0) {  // GMRES with KLU on the parts, or multigrid
    j["distributed_ranks"] = stats.distributed_ranks;
    j["krylov_iterations"] = stats.type == AnalysisType::Transient ? stats.transient.linear_iters
                                                                   : stats.newton.linear_iters;
    // GMRES solves that missed IDA's eps_lin (IDAGetNumLinConvFails): a run whose count grows
    // with its steps has a preconditioner too weak for the Krylov tolerance (docs/mpi.md, "Krylov
    // tolerance").
    if (stats.type == AnalysisType::Transient)
      j["krylov_conv_fails"] = stats.transient.linear_conv_fails;
  }
  return j;
}

Json structural_summary(const std::string& case_name, const StructuralModel& model,
                        const StructuralResults& results, const AnalysisStats& stats,
                        Real wall_seconds) {
  Json j;
  j["case"] = case_name;
  j["analysis"] = to_string(stats.type);
  j["model"] = model.kind();
  if (stats.type == AnalysisType::Static) j["static_method"] = stats.static_method;
  const Mesh& mesh = model.structure_mesh();
  j["mesh"] = {{"dim", mesh.dim()}, {"cells", mesh.n_cells()}};
  j["unknowns"] = model.structure().size();
  j["output"] = {{"h5", results.path()}, {"xdmf", results.xdmf_path()}};
  j["final_time"] = stats.final_time;
  j["n_outputs"] = stats.n_outputs;
  Json probes = Json::object();
  const auto components = model.probe_components();
  const ProbeHistory& h = results.history();
  for (std::size_t p = 0; p < results.probes().size(); ++p) {
    Json probe = Json::object();
    if (h.n_samples() > 0 && stats.type != AnalysisType::Modal &&
        stats.type != AnalysisType::Harmonic) {
      const Vec3& last = h.value(h.n_samples() - 1, p);
      for (int k = 0; k < 3; ++k) probe[components[k]] = last[k];
    }
    if (stats.type == AnalysisType::Modal) probe["samples"] = h.n_samples();  // one per mode
    if (stats.type == AnalysisType::Transient) {
      const int main = model.main_probe_component();
      probe["max_abs_" + components[main]] = h.max_abs(p, main);
      probe["samples"] = h.n_samples();
    }
    probes[results.probes()[p].name] = probe;
  }
  j["probes"] = probes;
  if (stats.type == AnalysisType::Modal) {
    Json modes = Json::array();
    for (const StructuralMode& m : stats.modal.modes)
      modes.push_back({{"index", m.number},
                       {"frequency", m.frequency},
                       {"angular_frequency", m.angular_frequency},
                       {"damping_ratio", m.damping_ratio},
                       {"eigenvalue_real", m.eigenvalue.real()},
                       {"eigenvalue_imag", m.eigenvalue.imag()},
                       {"complex", m.complex},
                       {"residual", m.residual}});
    j["modes"] = modes;
    j["state"] = {{"time", stats.modal.state_time}, {"at_rest", stats.modal.at_rest}};
  }
  if (stats.type == AnalysisType::Harmonic) {
    Json harmonic_probes = Json::object();
    for (std::size_t p = 0; p < results.harmonic().size(); ++p) {
      Json probe = Json::object();
      for (int k = 0; k < 3; ++k) {
        Json amplitude = Json::array(), phase = Json::array();
        for (const auto& sample : results.harmonic()[p]) {
          amplitude.push_back(std::abs(sample[k]));
          phase.push_back(std::arg(sample[k]) * 180 / M_PI);
        }
        probe[components[k]] = {{"amplitude", amplitude}, {"phase_deg", phase}};
      }
      harmonic_probes[results.probes()[p].name] = probe;
    }
    j["harmonic"] = {{"frequencies", stats.harmonic.frequencies}, {"probes", harmonic_probes}};
  }
  j["solver"] = solver_stats_json(stats);
  j["wall_time_s"] = wall_seconds;
  return j;
}

}  // namespace rfmems

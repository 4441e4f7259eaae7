// Fields, probe samples, metadata and the JSON summary of an elasticity run.
#include "physics/elasticity/elasticity_results.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>

namespace rfmems {

namespace {

// n_cells x 3 rows from the interleaved (cell * dim + k) unknowns; z = 0 in 2D.
std::vector<double> as_vectors(std::span<const Real> u, Index n_cells, int dim) {
  std::vector<double> out(static_cast<std::size_t>(3 * n_cells), 0.0);
  for (Index c = 0; c < n_cells; ++c)
    for (int k = 0; k < dim; ++k) out[3 * c + k] = u[c * dim + k];
  return out;
}

}  // namespace

ElasticityResults::ElasticityResults(const std::string& path, const ElasticityScene& scene,
                                     std::vector<Probe> probes)
    : scene_(scene),
      writer_(path, *scene.mesh),
      probes_(std::move(probes)),
      history_(probes_.size()) {}

void ElasticityResults::output(int index, Real t, std::span<const Real> u,
                               std::span<const Real> v) {
  const Mesh& mesh = *scene_.mesh;
  const ElasticityOperator& op = *scene_.op;
  const Index nc = mesh.n_cells();
  const int dim = mesh.dim();
  const std::vector<Mat3> gradients = op.cell_gradients(t, u);

  writer_.write_cell_field_at(index, t, "displacement", as_vectors(u, nc, dim), 3,
                              {"ux", "uy", "uz"});
  if (!v.empty())
    writer_.write_cell_field_at(index, t, "velocity", as_vectors(v, nc, dim), 3,
                                {"vx", "vy", "vz"});
  std::vector<double> stress(static_cast<std::size_t>(6 * nc));
  for (Index c = 0; c < nc; ++c) {
    const Mat3 s = scene_.material.stress(gradients[c]);
    const double voigt[6] = {s(0, 0), s(1, 1), s(2, 2), s(1, 2), s(0, 2), s(0, 1)};
    std::copy(voigt, voigt + 6, stress.begin() + 6 * c);
  }
  writer_.write_cell_field_at(index, t, "stress", stress, 6, {"xx", "yy", "zz", "yz", "xz", "xy"});

  std::vector<Vec3> samples;
  samples.reserve(probes_.size());
  for (const Probe& p : probes_) samples.push_back(op.displacement_at(p.cell, p.at, u, gradients));
  history_.add(t, std::move(samples));
}

void ElasticityResults::finish(const CaseFile& case_file, const std::string& case_name,
                               const AnalysisStats& stats, Real wall_seconds) {
  for (std::size_t p = 0; p < probes_.size(); ++p)
    writer_.write_time_series("probes", probes_[p].name, history_.times(), history_.series(p),
                              {"ux", "uy", "uz"});
  std::map<std::string, double> numbers;
  const Json solver = solver_stats_json(stats);  // named: items() refers into it
  for (const auto& [key, value] : solver.items())
    numbers["solver_" + key] = value.get<double>();
  numbers["wall_time_s"] = wall_seconds;
  writer_.write_metadata({{"case_file", case_file.path()},
                          {"case_name", case_name},
                          {"case_text", case_file.text()},
                          {"case_effective", case_file.effective_text()},
                          {"overrides", fmt::format("{}", fmt::join(case_file.overrides(), "\n"))},
                          {"analysis", to_string(stats.type)},
                          {"stress", to_string(stats.stress)}},
                         numbers);
  writer_.finish();
}

Json solver_stats_json(const AnalysisStats& stats) {
  Json j = Json::object();
  if (stats.type == AnalysisType::Transient) {
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
  } else if (stats.stress == StressMethod::Coupled) {
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
  return j;
}

Json elasticity_summary(const std::string& case_name, const ElasticityScene& scene,
                        const ElasticityResults& results, const AnalysisStats& stats,
                        Real wall_seconds) {
  Json j;
  j["case"] = case_name;
  j["analysis"] = to_string(stats.type);
  j["stress"] = to_string(stats.stress);
  j["mesh"] = {{"dim", scene.mesh->dim()}, {"cells", scene.mesh->n_cells()}};
  j["output"] = {{"h5", results.path()}, {"xdmf", results.xdmf_path()}};
  j["final_time"] = stats.final_time;
  j["n_outputs"] = stats.n_outputs;
  Json probes = Json::object();
  const ProbeHistory& h = results.history();
  for (std::size_t p = 0; p < results.probes().size(); ++p) {
    Json probe = Json::object();
    if (h.n_samples() > 0) {
      const Vec3& last = h.value(h.n_samples() - 1, p);
      probe["ux"] = last.x();
      probe["uy"] = last.y();
      probe["uz"] = last.z();
    }
    if (stats.type == AnalysisType::Transient) {
      probe["max_abs_uy"] = h.max_abs(p, 1);
      probe["samples"] = h.n_samples();
    }
    probes[results.probes()[p].name] = probe;
  }
  j["probes"] = probes;
  j["solver"] = solver_stats_json(stats);
  j["wall_time_s"] = wall_seconds;
  return j;
}

}  // namespace rfmems

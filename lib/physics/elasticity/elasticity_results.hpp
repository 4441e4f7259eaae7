// What an elasticity run writes: the result file and the --json summary.
//
// Result file (io/result_writer.hpp), at every output time:
//   /fields/<step>/displacement   n_cells x 3 [m]      (z = 0 in 2D)
//   /fields/<step>/velocity       n_cells x 3 [m/s]    (transients only)
//   /fields/<step>/stress         n_cells x 6 [Pa]     Voigt order xx yy zz yz xz xy:
//                                                      LinearElastic::stress of the cell
//                                                      gradients (cell_gradients)
// and at the end:
//   /probes/<name>/time, /probes/<name>/values (n_t x 3: ux, uy, uz)
//   /metadata  strings case_file, case_name, case_text (as read), case_effective (after the
//              overrides), overrides (one per line), analysis, stress, git_hash; numbers: the
//              solver statistics (as in the JSON summary) and wall_time_s.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "io/case_file.hpp"
#include "io/json_summary.hpp"
#include "io/probes.hpp"
#include "io/result_writer.hpp"
#include "physics/elasticity/elasticity_analysis.hpp"

namespace rfmems {

class ElasticityResults : public AnalysisObserver {
 public:
  // Creates the (temporary) result file; nothing appears at `path` before finish().
  ElasticityResults(const std::string& path, const ElasticityScene& scene,
                    std::vector<Probe> probes);

  void output(int index, Real t, std::span<const Real> u, std::span<const Real> v) override;

  // Writes the probe series and the metadata and moves the file into place.
  void finish(const CaseFile& case_file, const std::string& case_name,
              const AnalysisStats& stats, Real wall_seconds);

  const std::vector<Probe>& probes() const { return probes_; }
  const ProbeHistory& history() const { return history_; }
  const std::string& path() const { return writer_.path(); }
  const std::string& xdmf_path() const { return writer_.xdmf_path(); }

 private:
  const ElasticityScene& scene_;
  ResultWriter writer_;
  std::vector<Probe> probes_;
  ProbeHistory history_;
};

// Solver statistics by name: transient {steps, residual_evals, jacobian_evals,
// newton_iterations, linear_setups, error_test_fails, newton_fails, last_order, last_step};
// static coupled {newton_iterations, residual_evals, jacobian_evals, residual_initial,
// residual_final}; static segregated {outer_iterations, residual_initial, residual_final}.
Json solver_stats_json(const AnalysisStats& stats);

// The --json object: case, analysis, stress, mesh {dim, cells}, output {h5, xdmf},
// final_time, n_outputs, probes {name: {ux, uy, uz (at the final time), and for transients
// max_abs_uy and samples}}, solver (solver_stats_json), wall_time_s.
Json elasticity_summary(const std::string& case_name, const ElasticityScene& scene,
                        const ElasticityResults& results, const AnalysisStats& stats,
                        Real wall_seconds);

}  // namespace rfmems

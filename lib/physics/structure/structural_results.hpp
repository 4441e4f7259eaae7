// What a structural run writes: the result file and the --json summary.
//
// Result file (io/result_writer.hpp), at every output time the model's fields
// (StructuralModel::write_fields: displacement, velocity, stress for a continuum;
// deflection, rotation, moment, shear force for a plate), and at the end:
//   /probes/<name>/time, /probes/<name>/values (n_t x 3: StructuralModel::probe_components)
//   /modal/modes/mode, /modal/modes/values (modal: per mode frequency [Hz], angular_frequency,
//              damping_ratio, eigenvalue_real, eigenvalue_imag [rad^2/s^2], complex (0/1),
//              residual); output k of the fields is mode k + 1's shape
//   /harmonic/<probe>/frequency, /harmonic/<probe>/values (harmonic: per frequency [Hz] the
//              probe components' real and imaginary parts for the loads as given, re_<c>, im_<c>);
//              output k of the fields is the real part at frequency k
//   /metadata  strings case_file, case_name, case_text (as read), case_effective (after the
//              overrides), overrides (one per line), analysis, model, static_method,
//              git_hash; numbers: the solver statistics (as in the JSON summary) and
//              wall_time_s.
#pragma once
#include <array>
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "io/case_file.hpp"
#include "io/json_summary.hpp"
#include "io/probes.hpp"
#include "io/result_writer.hpp"
#include "physics/structure/structural_analysis.hpp"

namespace rfmems {

class StructuralResults : public AnalysisObserver {
 public:
  // Creates the (temporary) result file; nothing appears at `path` before finish().
  StructuralResults(const std::string& path, const StructuralModel& model,
                    std::vector<Probe> probes);

  void output(int index, Real t, std::span<const Real> u, std::span<const Real> v) override;
  void harmonic_output(int index, Real frequency, Real t_load, std::span<const Real> real,
                       std::span<const Real> imag) override;
  // Harmonic: per probe, per frequency, the complex amplitude of each probe component.
  const std::vector<std::vector<std::array<std::complex<Real>, 3>>>& harmonic() const {
    return harmonic_;
  }

  // Writes the probe series and the metadata and moves the file into place.
  void finish(const CaseFile& case_file, const std::string& case_name, const AnalysisStats& stats,
              Real wall_seconds);

  const std::vector<Probe>& probes() const { return probes_; }
  const ProbeHistory& history() const { return history_; }
  const std::string& path() const { return writer_.path(); }
  const std::string& xdmf_path() const { return writer_.xdmf_path(); }

 private:
  const StructuralModel& model_;
  ResultWriter writer_;
  std::vector<Probe> probes_;
  ProbeHistory history_;
  std::vector<std::vector<std::array<std::complex<Real>, 3>>> harmonic_;
};

// Solver statistics by name: transient {steps, residual_evals, jacobian_evals,
// newton_iterations, linear_setups, error_test_fails, newton_fails, last_order, last_step};
// static Newton {newton_iterations, residual_evals, jacobian_evals, residual_initial,
// residual_final}; static segregated {outer_iterations, residual_initial, residual_final};
// modal {modes_requested, modes_converged, operator_applications, restarts, subspace,
// factor_time_s, eigensolve_time_s, static_newton_iterations}.
Json solver_stats_json(const AnalysisStats& stats);

// The --json object: case, analysis, model, static_method (static), mesh {dim, cells},
// output {h5, xdmf}, final_time, n_outputs, probes {name: {the probe components at the final
// time (ux, uy, uz or w, beta_x, beta_y), and for transients max_abs_<main component> and
// samples; modal: samples only, one per mode, the shapes' values in the result file}}, solver
// (solver_stats_json), wall_time_s; modal also modes [{index, frequency [Hz], angular_frequency
// [rad/s], damping_ratio, eigenvalue_real, eigenvalue_imag [rad^2/s^2], complex, residual}]
// (physics/structure/modal_analysis.hpp) and state {time, at_rest}; harmonic: harmonic
// {frequencies [Hz], probes {name: {component: {amplitude, phase_deg}}}} for the loads as given
// (the phase of the response behind the load is -phase_deg).
Json structural_summary(const std::string& case_name, const StructuralModel& model,
                        const StructuralResults& results, const AnalysisStats& stats,
                        Real wall_seconds);

}  // namespace rfmems

// The pull-in studies' curves and histories in a result file, one layout for every switch
// (pull_in_study.hpp, immersed_switch_study.hpp):
//   /pull_in/curve     abscissa control_displacement; values voltage, min_gap, stable (1 / 0)
//   /pull_in/modes     abscissa voltage; values control_displacement, f1 ... fN [Hz]
//   /pull_in/harmonic  abscissa frequency [Hz]; values control_real, control_imag [m/V] and,
//                      with a film, film_force_real, film_force_imag [N/V], film_spring [N/m],
//                      film_damping [N s/m]
//   /dynamic/<name>    time; control, min_gap, electrostatic_force, gas_force, contact_force,
//                      voltage
#pragma once
#include <string>

#include "coupling/bias_modes.hpp"
#include "coupling/dynamic_pull_in.hpp"
#include "coupling/harmonic_under_bias.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "io/json_summary.hpp"
#include "io/result_writer.hpp"

namespace rfmems {

void write_pull_in_curve(ResultWriter& writer, const QuasiStaticPullIn& quasi_static);
void write_bias_modes(ResultWriter& writer, const std::vector<BiasedModes>& modes);
void write_harmonic_under_bias(ResultWriter& writer, const HarmonicUnderBias& response);
// force_units: of the run's forces, "N" (a plate: whole) or "N/m" (a plane beam: per depth).
void write_dynamic_history(ResultWriter& writer, const std::string& name, const DynamicRun& run,
                           const std::string& force_units);

// A small-signal response in the summaries: fitted (false: too few samples or no motion,
// nothing measured), damping_ratio, frequency (damped),
// natural_frequency, method (fit | log_decrement: which gave them), the fit's (fit:
// damping_ratio, frequency, residual; also fit_residual) and the log decrement's
// (log_decrement: damping_ratio, frequency, swings).
Json free_response_json(const FreeResponse& response);

// The pull-in time's check in the summaries (pull_in_time_check): the bisection's upper end
// run again to contact at `factor` x the tolerances. tolerance_factor, pulled_in, steps, and
// pull_in_time and relative_error_estimate = |pull_in_time - check| / check (both null if the
// check did not touch down: the upper end is within the integration error of V_dyn).
Json pull_in_time_check_json(Real factor, Real pull_in_time, const DynamicRun& check);

}  // namespace rfmems

// Partitioned (staggered and strongly coupled) time stepping of the plate switch with its
// squeeze film: the alternative to the monolithic SqueezeFilmSwitchSystem, kept as the
// baseline the coupling-scheme benchmark measures against (the thesis's coupled runs, and
// partitioned FSI codes in general, work this way).
//
// Two IDA integrators, one per field, advance over macro steps [t_n, t_n + H]:
//   film:      the Reynolds equation with the plate's gap g and gap rate g' prescribed per
//              cell, linear in time over the step between g_n and the end value (predicted
//              g_n + H g'_n, or the structure's last iterate);
//   structure: the plate under the parallel-plate force and the gas force (p - p_a) A per
//              cell, linear in time over the step between its values at t_n and t_n + H
//              from the film.
// Staggered: one film pass, then one structure pass (conventional serial staggering: first
// order in H). Strongly coupled: repeat both passes from the stored state at t_n until the
// gas force at t_n + H changes by less than tolerance x its size, relaxing it by Aitken's
// Delta^2 (Kuettler & Wall 2008); converged, the scheme has the accuracy of the monolithic
// system up to the linear-in-time interface interpolation (O(H^2)). Each pass restarts IDA at
// order 1 (IDAReInit), as partitioned codes restart their sub-solvers.
#pragma once
#include <functional>
#include <vector>

#include "coupling/coupling_settings.hpp"
#include "coupling/dynamic_pull_in.hpp"
#include "physics/gas/reynolds_film.hpp"

namespace rfmems {

struct PartitionedRun {
  DynamicRun run;                // pulled_in, pull_in_time (to within a macro step's contact
                                 // root), history at the macro steps, summed IDA stats
  long coupling_iterations = 0;  // passes over all macro steps
  long macro_steps = 0;
};

// The plate (actuation, rotations quasi-static) with the film under its cells (w_dof[c] is
// the plate unknown over film cell c) under the step voltage, until contact or end_time;
// options.coupling: scheme staggered or strongly_coupled, macro_step, tolerance,
// max_iterations.
PartitionedRun run_partitioned(ParallelPlateActuation& actuation, std::vector<bool> quasi_static,
                               const ReynoldsFilm& film, std::vector<Index> w_dof, Index control,
                               std::function<Real(Real)> voltage, const DynamicOptions& options);

}  // namespace rfmems

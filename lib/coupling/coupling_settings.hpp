// The coupling scheme a switch case asks for (issue 4, "Coupling manager"):
//
//   coupling:
//     scheme: monolithic        # monolithic (default) | staggered | strongly_coupled
//     macro_step: 0.1 us        # partitioned schemes: the exchange interval H (required)
//     tolerance: 1e-6           # strongly_coupled: relative change of the interface force
//     max_iterations: 50        # strongly_coupled: passes per macro step
//
// Monolithic: plate, parallel-plate force and Reynolds film in one IDA system with the exact
// coupled Jacobian (squeeze_film_switch_system.hpp). The partitioned schemes
// (partitioned_switch.hpp) split exactly that scene into a film and a structure integrator,
// so they need the gas film (gas.model: reynolds) and the parallel-plate law, and they drive
// only the single transient run (pull_in.mode: transient): the bisections and the
// quasi-static continuation stay monolithic. docs/BENCHMARKS.md section 8 measured them.
#pragma once
#include <string>

#include "coupling/partitioned_switch.hpp"
#include "coupling/switch_scene.hpp"
#include "io/case_file.hpp"

namespace rfmems {

// Reads and validates root.coupling (absent: monolithic); `transient` says whether the case's
// pull_in.mode is transient (the only mode a partitioned scheme drives).
PartitionedOptions read_coupling_options(const CaseNode& root, const SwitchScene& scene,
                                         bool transient);

// "monolithic", "staggered", "strongly_coupled": the case-file spelling.
std::string coupling_scheme_name(CouplingScheme scheme);

}  // namespace rfmems

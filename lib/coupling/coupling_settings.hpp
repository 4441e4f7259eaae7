// How a switch's models are coupled in time: the scheme (scene_combinations.hpp) and its
// settings, one reader for every scene.
//
//   coupling:
//     scheme: monolithic        # monolithic | staggered | implicit | strongly_coupled (the
//                               # scene's allowed schemes and default: scene_combinations.hpp)
//     tolerance: 1e-6           # strongly_coupled: relative change of the interface load
//     max_iterations: 20        # strongly_coupled: iterations per step
//     gas_every: 1              # with a gas, partitioned: the gas advanced over every k-th
//                               # accepted structural step (one gas step spanning k, its force
//                               # held); 1 when the strong iteration holds the gas
//     strong_gas: false         # immersed, strongly_coupled: the gas inside the iterations
//                               # (redone per iterate; the fixed point on the electrostatic +
//                               # gas load). The parallel_plate field's strongly_coupled scheme
//                               # always iterates on the gas (its field is exact)
//
// Every key is checked whatever the scheme, so that a case switched by --set stays valid; a key
// of another field's schemes is bad input.
#pragma once
#include <string>

#include "core/types.hpp"
#include "coupling/scene_combinations.hpp"
#include "io/case_file.hpp"

namespace rfmems {

struct CouplingOptions {
  CouplingScheme scheme = CouplingScheme::Monolithic;
  Real tolerance = 1e-6;    // strongly_coupled: |F_k+1 - F_k| <= tolerance |F_k+1|
  int max_iterations = 20;  // strongly_coupled: per step
  int gas_every = 1;        // with a gas
  bool strong_gas = false;  // immersed, strongly_coupled
};

CouplingOptions read_coupling_options(const CaseNode& root, const SceneChoice& choice);

// The keys read_coupling_options reads besides the scheme (coupling_settings.keys.yaml;
// io/case_schema.hpp).
CaseSchema coupling_case_keys();

}  // namespace rfmems

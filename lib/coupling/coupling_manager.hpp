// The coupling manager of a switch scene: what the pull-in study (pull_in_study.hpp) drives,
// whatever the scene's structure, field and gas (scene_combinations.hpp). It orders the models
// per step as the run's coupling scheme says (DynamicOptions::coupling):
//
//   parallel_plate   monolithic: structure, parallel-plate force (and the Reynolds film) in one
//                    IDA system with the exact coupled Jacobian (run_dynamic,
//                    switch_system.hpp); staggered / strongly_coupled (with the film): the film
//                    split from the actuated structure in the field-coupled structure's loop
//                    (below); equilibria by KINSOL under displacement control
//                    (quasi_static_pull_in.hpp);
//   laplace,         the plane beam under a field without exact blocks (the Laplace field in
//   immersed         the moving gap mesh, the immersed-boundary field and its gas on the
//                    background) in the field-coupled structure's one loop
//                    (field_coupled_structure.hpp): staggered, implicit or strongly_coupled per
//                    step; equilibria by its fixed points.
//
// Every run has the same events (dynamic_pull_in.hpp: contact, turning back, settled at rest,
// past the unstable equilibrium) and reports a DynamicRun.
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "coupling/dynamic_pull_in.hpp"
#include "coupling/quasi_static_pull_in.hpp"
#include "coupling/switch_scene.hpp"
#include "io/json_summary.hpp"

namespace rfmems {

// A static equilibrium at a voltage.
struct SwitchStatic {
  std::vector<Real> u;  // the structure's unknowns
  Real control = 0;     // the control's deflection [m]
  int iterations = 0;   // of the coupled fixed point
};

class CouplingManager {
 public:
  virtual ~CouplingManager() = default;
  // The quasi-static curve through the fold under displacement control of the control.
  virtual QuasiStaticPullIn quasi_static(const QuasiStaticOptions& options) = 0;
  // The equilibrium at `voltage` (below the fold).
  virtual SwitchStatic solve_static(Real voltage) = 0;
  // The waveform's voltage (amplitude V) from rest, or from `start`, with the run's events,
  // IDA settings and coupling scheme.
  virtual DynamicRun run(const VoltageWaveform& waveform, Real amplitude,
                         const DynamicOptions& options, const DynamicState* start = nullptr) = 0;
  // The monolithic switch system (parallel_plate; null for the others): what a release study
  // and the pull-out bisection integrate from a stored state in contact.
  virtual SwitchSystem* switch_system() { return nullptr; }
  // What the field and gas did over every call so far (field solves, coupling iterations,
  // CPU per physics), for the summary.
  virtual Json counters() const = 0;
};

std::unique_ptr<CouplingManager> make_coupling_manager(SwitchScene& scene);

}  // namespace rfmems

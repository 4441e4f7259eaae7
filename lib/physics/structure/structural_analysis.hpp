// Static, transient, modal and harmonic analyses of a StructuralModel (continuum or plate), and
// their case-file settings.
//
//   analysis:
//     type: static                 # static | transient | modal | harmonic
//     end_time: 1.25 s             # transient: simulated time, from t = 0
//     output_interval: 2.5 ms      # transient: fields and probes every this much
//     modes: 6                     # modal: how many modes (default 6), the nearest the shift
//     shift: 0 Hz                  # modal: the frequency the modes are nearest (default 0)
//     frequencies: [1 kHz, 2 kHz]  # harmonic: the load's frequencies, or
//     sweep: {from: 1 kHz, to: 1 MHz, points: 61}   # evenly spaced in log f
//   solver:                        # static (Newton, or the elasticity's segregated method),
//                                  # and the static state of a loaded modal analysis (Newton):
//     tolerance: 1e-6              #   residual reduction ||R||/||R0|| (default 1e-6: the
//                                  #   round-off floor of a slender beam is ~5e-7, and a
//                                  #   linear problem needs one Newton step to reach it)
//     max_iterations: 50           #   Newton (default 50) or outer iterations
//                                  #   (segregated, default 100000)
//   solver:                        # transient (IDA, variable-order variable-step BDF):
//     rtol: 1e-6                   #   relative tolerance (default 1e-6)
//     atol: 2e-10                  #   absolute tolerance, one value for u [m] and v [m/s]
//                                  #   (default rtol x 1e-4 x the largest edge of the mesh
//                                  #   bounding box, i.e. rtol applied to a displacement of
//                                  #   1e-4 of the body's size: 2e-10 for a 2 m beam at
//                                  #   rtol 1e-6). Far tighter values make IDA resolve the
//                                  #   elastic waves in components that are nearly zero
//                                  #   (velocities at rest, cells ahead of a wave).
//     max_order: 5                 #   BDF order limit, 1..5 (default 5). Use 2 for undamped
//                                  #   elastodynamics: BDF3-5 are not A-stable, their
//                                  #   instability near the imaginary axis excites the
//                                  #   mesh's high-frequency modes and IDA then crawls.
//     fixed_step: 0                #   > 0: fixed step size, no error control (default 0)
//   solver:                        # both:
//     distributed: false           #   true: under mpirun -np P the continuum (or a static
//                                  #   plate) is distributed
//                                  #   over P METIS parts (distributed_analysis.hpp; GMRES
//                                  #   with rank-local KLU blocks); false (default): the structure
//                                  #   is solved on rank 0 while the other ranks wait
//     linear: auto                 #   direct (KLU), multigrid (GMRES with BoomerAMG) or auto
//                                  #   (multigrid for a 3D continuum's static solve above
//                                  #   5000 unknowns; distributed_analysis.hpp)
//
// Static: R(t_load, u) = 0 at the time every ramp has finished (model.ramp_end_time()), by
// Newton with KINSOL or the model's own method (segregated); one output, index 0, at t_load.
// Transient: M u'' + R(t, u) = 0 as the first-order system [u' - v; M v' + R] with IDA
// (core/structural_systems.hpp), or, if the model neglects the inertia of some components
// (the plate's rotations), as core/reduced_inertia_system.hpp with those components
// algebraic and made consistent at t = 0 by IDACalcIC. It starts from rest (u = v = 0) with
// the consistent initial acceleration v'(0) = -M^-1 R(0, 0) (zero when every load ramps from
// zero). Outputs at t = k dt for k = 0, 1, ... and at end_time.
// Modal: the modes of the structure linearised about its static state at t_load
// (physics/structure/modal_analysis.hpp); output k holds the shape of mode k + 1 (largest
// displacement component +1), at "time" k + 1 (so a viewer's time steps through the modes).
// Harmonic: every load (pressure, tractions, point loads, prescribed boundary values) at its
// value at t_load becomes the amplitude of a load varying as exp(i w t), and the steady
// response u = Re(x exp(i w t)) of the structure about rest, with its inertia (the
// transients' first-order form: the same quasi-static components) and its Kelvin-Voigt
// damping, is solved for at each frequency (solvers/harmonic_response.hpp: one complex sparse
// LU each). Output k holds Re x at frequency k, at "time" f_k [Hz]; the probes record Re and Im
// (the result file's /harmonic/<probe>, the JSON's harmonic: amplitude and phase).
#pragma once
#include <span>

#include "io/case_file.hpp"
#include "io/progress.hpp"
#include "physics/elasticity/segregated_solver.hpp"
#include "physics/structure/modal_analysis.hpp"
#include "physics/structure/structural_model.hpp"
#include "solvers/ida_integrator.hpp"
#include "solvers/kinsol_solver.hpp"

namespace rfmems {

struct AnalysisSettings {
  AnalysisType type = AnalysisType::Static;
  // Static.
  Real tolerance = 1e-6;
  long max_iterations = 50;
  // Transient.
  Real end_time = 0;
  Real output_interval = 0;
  IdaOptions ida;
  // Modal.
  Index modes = 6;
  Real shift_frequency = 0;  // [Hz]
  // Harmonic.
  std::vector<Real> frequencies;  // [Hz]
  // solver.distributed: the structure on distributed vectors (physics/structure/
  // distributed_analysis.hpp) instead of on rank 0.
  bool distributed = false;
  // solver.linear: the linear solver of static and transient solves. Direct: KLU (serial) or
  // KLU on the parts (distributed); Multigrid: GMRES with algebraic multigrid on the
  // distributed vectors (one rank unless distributed); Auto: multigrid where it is the faster
  // (3D continua's static solves above kMultigridUnknowns: distributed_analysis.hpp).
  enum class Linear { Auto, Direct, Multigrid };
  Linear linear = Linear::Auto;
};

// analysis.type alone: the scene needs it before the rest can be read.
AnalysisType read_analysis_type(const CaseNode& root);

// The remaining analysis.* and solver.* keys for this model (defaults depend on its static
// method and mesh size).
AnalysisSettings read_analysis_settings(const CaseNode& root, StructuralModel& model);

// Receives the state at each output time. v is empty for a static analysis.
class AnalysisObserver {
 public:
  virtual ~AnalysisObserver() = default;
  virtual void output(int index, Real t, std::span<const Real> u, std::span<const Real> v) = 0;
  // A harmonic analysis's response at one frequency [Hz]: u = Re x + i Im x for the loads'
  // amplitude, the loads and boundary data taken at t_load. By default the real part goes to
  // output().
  virtual void harmonic_output(int index, Real frequency, Real /*t_load*/,
                               std::span<const Real> real, std::span<const Real> /*imag*/) {
    output(index, frequency, real, {});
  }
};

struct HarmonicStats {
  std::vector<Real> frequencies;  // [Hz]
  long factorizations = 0, refactorizations = 0;
  double solve_seconds = 0;  // CPU of the complex solves, factorisations included
};

struct AnalysisStats {
  AnalysisType type = AnalysisType::Static;
  std::string static_method = "newton";  // static: "newton" or the model's own
  IntegratorStats transient;             // transient
  NonlinearStats newton;                 // static, Newton
  SegregatedStats segregated;            // static, segregated (elasticity)
  ModalStats modal;                      // modal
  HarmonicStats harmonic;                // harmonic
  int n_outputs = 0;
  Real final_time = 0;
  int distributed_ranks = 0;  // > 0: solved distributed over this many ranks
  // The linear solver that ran: "klu", "umfpack" (a static solve of kUmfpackFrom unknowns or
  // more: solvers/sparse_direct_solver.hpp), "klu_subdomains" (GMRES, KLU on the parts) or
  // "multigrid" (GMRES, BoomerAMG); with multigrid its hierarchy's levels and operator
  // complexity (static solves).
  std::string linear_solver = "klu";
  int multigrid_levels = 0;
  Real multigrid_complexity = 0;
};

// Runs the analysis. Progress (transients) goes to `progress`; the caller finishes it.
// SolverError if the integrator or the nonlinear solver fails (also a segregated iteration
// that has not converged within its iteration limit).
AnalysisStats run_analysis(StructuralModel& model, const AnalysisSettings& settings,
                           AnalysisObserver& observer, ProgressReporter& progress);

// The keys read_analysis_settings reads (structural_analysis.keys.yaml; io/case_schema.hpp).
CaseSchema structural_analysis_case_keys();

}  // namespace rfmems

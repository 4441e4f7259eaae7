// Modal analysis of a StructuralModel: natural frequencies and mode shapes of the structure
// linearised about its static state,
//
//   M y'' + C y' + R(t_s, y) = 0,   y = y_s + x exp(s t):   (s^2 M + s C + K) x = 0,
//   K = dR/dy (y_s) (the operator's exact Jacobian),
//
// y_s the static solution at t_s = model.ramp_end_time() (every load at its final value; y_s = 0
// without solving when R(t_s, 0) = 0, a structure without loads). For a linear model K does not
// depend on y_s; a model whose stiffness depends on its state (prestress, stretching, a bias)
// is linearised about its loaded equilibrium. M is the lumped mass with the components the
// model's transients treat as quasi-static (the plate's rotations) massless, as in the
// transients, so both give the same frequencies.
//
// The eigenproblem K x = lambda M x is solved for the `modes` eigenvalues lambda nearest
// (2 pi f_shift)^2 by shift-invert Arnoldi (solvers/modal_solver.hpp). C is the model's
// Kelvin-Voigt damping beta K (SecondOrderOperator::damping_time, 0: undamped), which shares
// K's eigenvectors, so each lambda gives s from s^2 + beta lambda s + lambda = 0; of the two
// roots the one with Im s >= 0 (the larger real part if both are real) is reported:
//   frequency = |Im s| / (2 pi) [Hz],  damping ratio zeta = -Re s / |s|,
// i.e. f = sqrt(lambda) / (2 pi) and zeta = 0 for an undamped structure with real lambda > 0.
// The FV stiffness is not symmetric: a lambda with a non-negligible imaginary part (|Im| >
// 1e-8 |lambda|) is reported as such (`complex`); the pair's two members then give one decaying
// and one growing motion (zeta of opposite signs). A lambda < 0 (an unstable state) gives a
// real s > 0: frequency 0, zeta = -1.
//
// Each shape is the eigenvector scaled so that its largest displacement component (of the
// components with inertia: the plate's w, a continuum's displacements) is +1, and, for a
// complex pair, its real part at that phase.
#pragma once
#include <complex>
#include <span>
#include <vector>

#include "physics/structure/structural_model.hpp"
#include "solvers/kinsol_solver.hpp"
#include "solvers/modal_solver.hpp"

namespace rfmems {

struct StructuralMode {
  Index number = 0;               // 1, 2, ... by frequency
  std::complex<Real> eigenvalue;  // lambda of K x = lambda M x [rad^2/s^2]
  Real frequency = 0;             // |Im s| / (2 pi) [Hz]
  Real angular_frequency = 0;     // |Im s| [rad/s]
  Real damping_ratio = 0;         // -Re s / |s|
  bool complex = false;           // |Im lambda| > 1e-8 |lambda|
  Real residual = 0;              // the pair's relative residual (solvers/modal_solver.hpp)
};

struct ModalStats {
  std::vector<StructuralMode> modes;
  ShiftInvertStats eigen;
  Real state_time = 0;    // t_s
  bool at_rest = true;    // y_s = 0 without a static solve
  NonlinearStats newton;  // the static solve (at_rest false)
};

struct StructuralModes {
  ModalStats stats;
  std::vector<std::vector<Real>> shapes;  // per mode, the model's unknowns
};

// The `modes` modes nearest shift_frequency [Hz] (0: the lowest), by frequency. The static
// state, if the structure is loaded, by Newton with `static_options`. SolverError if the static
// solve or the eigensolve fails, or fewer modes converge than asked.
StructuralModes structural_modes(StructuralModel& model, Index modes, Real shift_frequency,
                                 const KinsolOptions& static_options = {});

// The same about a given state (t, y) of any second-order operator with the lumped mass `mass`
// (zeros for massless components): a structure under an electrostatic bias
// (physics/electrostatics/parallel_plate_actuation.hpp) linearised about its biased
// equilibrium, whose stiffness includes the electrostatic softening. The stats' state fields
// (at_rest, newton) are left at their defaults.
StructuralModes linearised_modes(SecondOrderOperator& op, std::span<const Real> mass, Real t,
                                 std::span<const Real> y, Index modes, Real shift_frequency = 0);

// The mass matrix the modes use: the model's lumped mass, zero on its quasi-static components.
std::vector<Real> modal_mass(StructuralModel& model);

// s of s^2 + beta lambda s + lambda = 0 as reported (see the banner).
std::complex<Real> modal_exponent(std::complex<Real> lambda, Real beta);

}  // namespace rfmems

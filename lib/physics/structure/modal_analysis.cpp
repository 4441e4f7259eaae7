// Natural frequencies and mode shapes of a structural model (see the header).
#include "physics/structure/modal_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "core/error.hpp"
#include "solvers/static_solve.hpp"

namespace rfmems {

namespace {

// An eigenvalue is reported as complex above this |Im lambda| / |lambda|: far above the
// eigensolver's tolerance (1e-10 on the Ritz values), far below any physical damping.
constexpr Real kComplexThreshold = 1e-8;

// The eigenvector scaled so that its largest component with inertia is +1 (its real part).
std::vector<Real> normalised_shape(const std::vector<std::complex<Real>>& x,
                                   std::span<const Real> mass) {
  Index largest = -1;
  for (Index i = 0; i < static_cast<Index>(x.size()); ++i)
    if (mass[i] != 0 && (largest < 0 || std::abs(x[i]) > std::abs(x[largest]))) largest = i;
  const std::complex<Real> scale = largest >= 0 ? x[largest] : std::complex<Real>(1.0);
  std::vector<Real> shape(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) shape[i] = (x[i] / scale).real();
  return shape;
}

}  // namespace

std::vector<Real> modal_mass(StructuralModel& model) {
  std::vector<Real> mass = model.structure().mass_diagonal();
  const std::vector<bool> quasi_static = model.quasi_static_components();
  for (std::size_t i = 0; i < quasi_static.size(); ++i)
    if (quasi_static[i]) mass[i] = 0;
  return mass;
}

std::complex<Real> modal_exponent(std::complex<Real> lambda, Real beta) {
  const std::complex<Real> root = std::sqrt(beta * beta * lambda * lambda - 4.0 * lambda);
  const std::complex<Real> a = (-beta * lambda + root) / 2.0, b = (-beta * lambda - root) / 2.0;
  const Real tie = 1e-12 * std::max(std::abs(a), std::abs(b));
  if (std::abs(a.imag() - b.imag()) > tie) return a.imag() > b.imag() ? a : b;
  return a.real() >= b.real() ? a : b;
}

StructuralModes structural_modes(StructuralModel& model, Index modes, Real shift_frequency,
                                 const KinsolOptions& static_options) {
  SecondOrderOperator& op = model.structure();
  const Index n = op.size();
  // The static state: rest if nothing loads the structure at t_s.
  const Real t = model.ramp_end_time();
  std::vector<Real> y(n, 0.0), r(n);
  op.internal_residual(t, y, r);
  const bool at_rest = std::all_of(r.begin(), r.end(), [](Real v) { return v == 0; });
  NonlinearStats newton;
  if (!at_rest) {
    StaticSolution state = solve_static(op, t, static_options);
    y = std::move(state.y);
    newton = state.stats;
  }

  StructuralModes result = linearised_modes(op, modal_mass(model), t, y, modes, shift_frequency);
  result.stats.state_time = t;
  result.stats.at_rest = at_rest;
  result.stats.newton = newton;
  return result;
}

StructuralModes linearised_modes(SecondOrderOperator& op, std::span<const Real> mass, Real t,
                                 std::span<const Real> y, Index modes, Real shift_frequency) {
  StructuralModes result;
  ModalStats& stats = result.stats;
  stats.state_time = t;
  const CsrPattern& pattern = op.stiffness_pattern();
  std::vector<Real> stiffness(pattern.nnz(), 0.0);
  op.stiffness(t, y, stiffness);

  ShiftInvertOptions options;
  options.n_modes = modes;
  const Real omega_shift = 2 * std::numbers::pi * shift_frequency;
  options.shift = omega_shift * omega_shift;
  ShiftInvertSolution solution = solve_shift_invert(pattern, stiffness, mass, options);
  stats.eigen = solution.stats;
  if (stats.eigen.converged < modes)
    throw SolverError(
        fmt::format("modal analysis: {} of {} modes converged in {} restarts (subspace {})",
                    stats.eigen.converged, modes, stats.eigen.restarts, stats.eigen.subspace));

  const Real beta = op.damping_time();
  std::vector<std::size_t> order(solution.pairs.size());
  std::vector<StructuralMode> found;
  for (const EigenPair& pair : solution.pairs) {
    StructuralMode mode;
    mode.eigenvalue = pair.value;
    const std::complex<Real> s = modal_exponent(pair.value, beta);
    mode.angular_frequency = std::abs(s.imag());
    mode.frequency = mode.angular_frequency / (2 * std::numbers::pi);
    // + 0.0: an undamped mode's -0 (s = +0 + i omega) reads 0.
    mode.damping_ratio = (std::abs(s) > 0 ? -s.real() / std::abs(s) : 0) + 0.0;
    mode.complex = std::abs(pair.value.imag()) > kComplexThreshold * std::abs(pair.value);
    mode.residual = pair.residual;
    found.push_back(mode);
  }
  std::iota(order.begin(), order.end(), std::size_t{0});
  // By frequency; a conjugate pair (equal frequencies) with its decaying member first.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (found[a].frequency != found[b].frequency) return found[a].frequency < found[b].frequency;
    return found[a].damping_ratio > found[b].damping_ratio;
  });
  for (std::size_t k = 0; k < order.size(); ++k) {
    StructuralMode mode = found[order[k]];
    mode.number = static_cast<Index>(k) + 1;
    stats.modes.push_back(mode);
    result.shapes.push_back(normalised_shape(solution.pairs[order[k]].vector, mass));
  }
  return result;
}

}  // namespace rfmems

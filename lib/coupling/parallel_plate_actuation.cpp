#include "coupling/parallel_plate_actuation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "core/error.hpp"

namespace rfmems {

std::vector<GapElement> elements_over_electrode(const std::vector<GapElement>& elements,
                                                const ElectrodeExtent& electrode, bool use_y) {
  auto fraction = [](Real lo, Real hi, Real a, Real b) {
    if (hi <= lo) return lo >= a && lo <= b ? 1.0 : 0.0;
    return std::max(0.0, std::min(hi, b) - std::max(lo, a)) / (hi - lo);
  };
  std::vector<GapElement> out;
  for (GapElement e : elements) {
    Real f = fraction(e.lo.x(), e.hi.x(), electrode.x_min, electrode.x_max);
    if (use_y) f *= fraction(e.lo.y(), e.hi.y(), electrode.y_min, electrode.y_max);
    if (f <= 0) continue;
    e.area *= f;
    out.push_back(e);
  }
  return out;
}

ParallelPlateActuation::ParallelPlateActuation(SecondOrderOperator& structure,
                                               std::vector<GapElement> elements, Real initial_gap,
                                               ParallelPlateLaw law)
    : structure_(structure), elements_(std::move(elements)), gap0_(initial_gap), law_(law) {
  const CsrPattern& pattern = structure_.stiffness_pattern();
  for (const GapElement& e : elements_) {
    const Index position = pattern.find(e.dof, e.dof);
    if (position < 0)
      throw std::logic_error("ParallelPlateActuation: no diagonal entry in the stiffness");
    diagonal_position_.push_back(position);
  }
}

void ParallelPlateActuation::set_contact(const ContactPenalty& contact) {
  if (contact.enabled() && (contact.gap <= 0 || contact.gap >= gap0_))
    throw std::logic_error("ParallelPlateActuation: the contact gap must lie in (0, initial gap)");
  contact_ = contact;
  p1_contact_ = contact.enabled() ? law_.pressure_per_volt2(contact.gap) : 0.0;
  slope_contact_ = contact.enabled() ? -law_.pressure_per_volt2_derivative(contact.gap) : 0.0;
}

void ParallelPlateActuation::check_gap(Real g, std::size_t e) const {
  if (!contact_.enabled() && law_.electrical_gap(g) <= 0)
    throw RecoverableError(
        fmt::format("parallel-plate gap closed (g = {:.3e} m at element {})", g, e));
}

void ParallelPlateActuation::internal_residual(Real t, std::span<const Real> y, std::span<Real> r) {
  structure_.internal_residual(t, y, r);
  const Real v2 = voltage_squared(t);
  if (v2 == 0) return;
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const Real g = gap(y, e);
    check_gap(g, e);
    r[elements_[e].dof] += v2 * elements_[e].area * net_pressure_per_volt2(g);
  }
}

void ParallelPlateActuation::stiffness(Real t, std::span<const Real> y, std::span<Real> values) {
  structure_.stiffness(t, y, values);
  const Real v2 = voltage_squared(t);
  if (v2 == 0) return;
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const Real g = gap(y, e);
    check_gap(g, e);
    values[diagonal_position_[e]] += v2 * elements_[e].area * net_pressure_per_volt2_derivative(g);
  }
}

void ParallelPlateActuation::residual_per_volt2(std::span<const Real> y,
                                                std::span<Real> out) const {
  std::fill(out.begin(), out.end(), 0.0);
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const Real g = gap(y, e);
    check_gap(g, e);
    out[elements_[e].dof] += elements_[e].area * net_pressure_per_volt2(g);
  }
}

Real ParallelPlateActuation::min_gap(std::span<const Real> y) const {
  Real g = std::numeric_limits<Real>::infinity();
  for (std::size_t e = 0; e < elements_.size(); ++e) g = std::min(g, gap(y, e));
  return g;
}

Real ParallelPlateActuation::total_force(Real voltage_squared, std::span<const Real> y) const {
  Real f = 0;
  for (std::size_t e = 0; e < elements_.size(); ++e)
    f -= voltage_squared * elements_[e].area * electrostatic_per_volt2(gap(y, e));
  return f;
}

}  // namespace rfmems

namespace rfmems {

Real ParallelPlateActuation::contact_force(Real voltage_squared, std::span<const Real> y) const {
  Real f = 0;
  for (std::size_t e = 0; e < elements_.size(); ++e)
    f += voltage_squared * elements_[e].area * contact_.pressure_per_volt2(gap(y, e), p1_contact_);
  return f;
}

Real ParallelPlateActuation::contact_fraction(std::span<const Real> y) const {
  if (!contact_.enabled()) return 0.0;
  Real touching = 0, total = 0;
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    total += elements_[e].area;
    if (gap(y, e) < contact_.gap) touching += elements_[e].area;
  }
  return total > 0 ? touching / total : 0.0;
}

}  // namespace rfmems

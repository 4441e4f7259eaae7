#include "physics/electrostatics/parallel_plate_actuation.hpp"

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
  for (GapElement& e : elements_)
    if (e.points.empty()) e.points.push_back({1.0, 0.0, {{e.dof, 1.0}}});
  // The structure's pattern, each element's row widened by its points' stencils.
  const CsrPattern& k = structure_.stiffness_pattern();
  std::vector<std::vector<Index>> extra(static_cast<std::size_t>(k.n_rows()));
  for (const GapElement& e : elements_)
    for (const GapPoint& q : e.points)
      for (const DofWeight& t : q.terms) extra[e.dof].push_back(t.dof);
  pattern_.row_ptr.assign(1, 0);
  structure_position_.resize(k.nnz());
  for (Index i = 0; i < k.n_rows(); ++i) {
    std::vector<Index> row(k.col_idx.begin() + k.row_ptr[i], k.col_idx.begin() + k.row_ptr[i + 1]);
    row.insert(row.end(), extra[i].begin(), extra[i].end());
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    pattern_.col_idx.insert(pattern_.col_idx.end(), row.begin(), row.end());
    pattern_.row_ptr.push_back(static_cast<Index>(pattern_.col_idx.size()));
    for (Index p = k.row_ptr[i]; p < k.row_ptr[i + 1]; ++p)
      structure_position_[p] = pattern_.find(i, k.col_idx[p]);
  }
  for (const GapElement& e : elements_)
    for (const GapPoint& q : e.points)
      for (const DofWeight& t : q.terms) term_position_.push_back(pattern_.find(e.dof, t.dof));
  structure_values_.resize(k.nnz());
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
    const Real p = point_sum(y, e, [&](Real g) {
      check_gap(g, e);
      return net_pressure_per_volt2(g);
    });
    r[elements_[e].dof] += v2 * elements_[e].area * p;
  }
}

void ParallelPlateActuation::stiffness(Real t, std::span<const Real> y, std::span<Real> values) {
  structure_.stiffness(t, y, structure_values_);
  std::fill(values.begin(), values.end(), 0.0);
  for (std::size_t p = 0; p < structure_values_.size(); ++p)
    values[structure_position_[p]] = structure_values_[p];
  const Real v2 = voltage_squared(t);
  if (v2 == 0) return;
  std::size_t term = 0;
  for (std::size_t e = 0; e < elements_.size(); ++e)
    for (const GapPoint& q : elements_[e].points) {
      const Real g = gap(y, q);
      check_gap(g, e);
      const Real dp =
          v2 * elements_[e].area * q.area_fraction * net_pressure_per_volt2_derivative(g);
      for (const DofWeight& k : q.terms) values[term_position_[term++]] += dp * k.weight;
    }
}

void ParallelPlateActuation::residual_per_volt2(std::span<const Real> y,
                                                std::span<Real> out) const {
  std::fill(out.begin(), out.end(), 0.0);
  for (std::size_t e = 0; e < elements_.size(); ++e)
    out[elements_[e].dof] += elements_[e].area * point_sum(y, e, [&](Real g) {
                               check_gap(g, e);
                               return net_pressure_per_volt2(g);
                             });
}

Real ParallelPlateActuation::min_gap(std::span<const Real> y) const {
  const LowestGapPoint lowest = lowest_gap_point(elements_, y);
  return lowest.point ? gap(y, *lowest.point) : std::numeric_limits<Real>::infinity();
}

Real ParallelPlateActuation::total_force(Real voltage_squared, std::span<const Real> y) const {
  Real f = 0;
  for (std::size_t e = 0; e < elements_.size(); ++e)
    f -= voltage_squared * elements_[e].area *
         point_sum(y, e, [&](Real g) { return electrostatic_per_volt2(g); });
  return f;
}

}  // namespace rfmems

namespace rfmems {

Real ParallelPlateActuation::contact_force(Real voltage_squared, std::span<const Real> y) const {
  Real f = 0;
  for (std::size_t e = 0; e < elements_.size(); ++e)
    f += voltage_squared * elements_[e].area *
         point_sum(y, e, [&](Real g) { return contact_.pressure_per_volt2(g, p1_contact_); });
  return f;
}

Real ParallelPlateActuation::contact_fraction(std::span<const Real> y) const {
  if (!contact_.enabled()) return 0.0;
  Real touching = 0, total = 0;
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    total += elements_[e].area;
    touching +=
        elements_[e].area * point_sum(y, e, [&](Real g) { return g < contact_.gap ? 1.0 : 0.0; });
  }
  return total > 0 ? touching / total : 0.0;
}

}  // namespace rfmems

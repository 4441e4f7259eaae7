#include "coupling/gap_scaled_lagged_load.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace rfmems {

GapScaledLaggedLoad::GapScaledLaggedLoad(SecondOrderOperator& structure,
                                         std::vector<Index> gap_unknowns, Real gap0,
                                         Real closed_fraction)
    : structure_(structure),
      gap0_(gap0),
      closed_fraction_(closed_fraction),
      gap_unknowns_(std::move(gap_unknowns)) {
  const Index n = structure.size();
  force_.assign(n, 0.0);
  held_.assign(n, 0.0);
  reference_gap_.assign(gap_unknowns_.size(), gap0);
  on_gap_.assign(n, 0);
  const CsrPattern& p = structure.stiffness_pattern();
  for (Index i : gap_unknowns_) {
    diagonal_.push_back(p.find(i, i));
    on_gap_[i] = 1;
  }
}

void GapScaledLaggedLoad::set_reference(std::vector<Real> force, std::span<const Real> u_ref) {
  force_ = std::move(force);
  for (std::size_t c = 0; c < gap_unknowns_.size(); ++c)
    reference_gap_[c] = gap0_ + u_ref[gap_unknowns_[c]];
}

Real GapScaledLaggedLoad::scale(std::size_t c, std::span<const Real> u) const {
  const Real g = gap0_ + u[gap_unknowns_[c]];
  if (!(g > closed_fraction_ * gap0_))
    throw RecoverableError(
        fmt::format("gap-scaled lagged load: gap {:.3e} m of facing cell {} closed", g, c));
  const Real s = reference_gap_[c] / g;
  return s * s;
}

std::vector<Real> GapScaledLaggedLoad::applied(std::span<const Real> u) const {
  std::vector<Real> f(force_.size(), 0.0);
  for (std::size_t i = 0; i < f.size(); ++i)
    if (!on_gap_[i]) f[i] = force_[i];
  for (std::size_t c = 0; c < gap_unknowns_.size(); ++c) {
    const Index i = gap_unknowns_[c];
    if (force_[i] != 0) f[i] = force_[i] * scale(c, u);
  }
  return f;
}

void GapScaledLaggedLoad::internal_residual(Real t, std::span<const Real> u, std::span<Real> r) {
  structure_.internal_residual(t, u, r);
  if (exact_) {
    const std::vector<Real> f = exact_(u);
    for (Index i = 0; i < size(); ++i) r[i] -= f[i] + held_[i];
    return;
  }
  for (Index i = 0; i < size(); ++i) {
    r[i] -= held_[i];
    if (!on_gap_[i]) r[i] -= force_[i];
  }
  for (std::size_t c = 0; c < gap_unknowns_.size(); ++c) {
    const Index i = gap_unknowns_[c];
    if (force_[i] != 0) r[i] -= force_[i] * scale(c, u);
  }
}

void GapScaledLaggedLoad::stiffness(Real t, std::span<const Real> u, std::span<Real> values) {
  structure_.stiffness(t, u, values);
  for (std::size_t c = 0; c < gap_unknowns_.size(); ++c) {
    const Index i = gap_unknowns_[c];
    if (force_[i] == 0) continue;
    // d/du of -F (g_ref/g)^2 = 2 F g_ref^2 / g^3.
    values[diagonal_[c]] += 2 * force_[i] * scale(c, u) / (gap0_ + u[i]);
  }
}

}  // namespace rfmems

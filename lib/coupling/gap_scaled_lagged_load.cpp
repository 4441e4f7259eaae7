#include "coupling/gap_scaled_lagged_load.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace rfmems {

GapScaledLaggedLoad::GapScaledLaggedLoad(ElasticityOperator& beam, Real gap0, Real closed_fraction)
    : beam_(beam), gap0_(gap0), closed_fraction_(closed_fraction) {
  const Index n = beam.size();
  force_.assign(n, 0.0);
  held_.assign(n, 0.0);
  reference_gap_.assign(n / beam.dim(), gap0);
  loaded_.assign(n / beam.dim(), 0);
  const CsrPattern& p = beam.stiffness_pattern();
  for (Index c = 0; c < n / beam.dim(); ++c)
    diagonal_.push_back(p.find(beam.gap_unknown(c), beam.gap_unknown(c)));
}

void GapScaledLaggedLoad::set_reference(std::vector<Real> force, std::span<const Real> u_ref) {
  force_ = std::move(force);
  for (std::size_t c = 0; c < reference_gap_.size(); ++c) {
    reference_gap_[c] = gap0_ + u_ref[beam_.gap_unknown(c)];
    loaded_[c] = 0;
    for (int d = 0; d < beam_.dim(); ++d) loaded_[c] |= force_[beam_.unknown(c, d)] != 0;
  }
}

Real GapScaledLaggedLoad::scale(std::size_t c, std::span<const Real> u) const {
  const Real g = gap0_ + u[beam_.gap_unknown(c)];
  if (!(g > closed_fraction_ * gap0_))
    throw RecoverableError(
        fmt::format("gap-scaled lagged load: gap {:.3e} m of cell {} closed", g, c));
  const Real s = reference_gap_[c] / g;
  return s * s;
}

std::vector<Real> GapScaledLaggedLoad::applied(std::span<const Real> u) const {
  std::vector<Real> f(force_.size(), 0.0);
  for (std::size_t c = 0; c < reference_gap_.size(); ++c) {
    if (!loaded_[c]) continue;
    for (int d = 0; d + 1 < beam_.dim(); ++d) f[beam_.unknown(c, d)] = force_[beam_.unknown(c, d)];
    f[beam_.gap_unknown(c)] = force_[beam_.gap_unknown(c)] * scale(c, u);
  }
  return f;
}

void GapScaledLaggedLoad::internal_residual(Real t, std::span<const Real> u, std::span<Real> r) {
  beam_.internal_residual(t, u, r);
  if (exact_) {
    const std::vector<Real> f = exact_(u);
    for (Index i = 0; i < size(); ++i) r[i] -= f[i] + held_[i];
    return;
  }
  for (std::size_t c = 0; c < reference_gap_.size(); ++c) {
    for (int d = 0; d < beam_.dim(); ++d) r[beam_.unknown(c, d)] -= held_[beam_.unknown(c, d)];
    if (!loaded_[c]) continue;
    for (int d = 0; d + 1 < beam_.dim(); ++d) r[beam_.unknown(c, d)] -= force_[beam_.unknown(c, d)];
    r[beam_.gap_unknown(c)] -= force_[beam_.gap_unknown(c)] * scale(c, u);
  }
}

void GapScaledLaggedLoad::stiffness(Real t, std::span<const Real> u, std::span<Real> values) {
  beam_.stiffness(t, u, values);
  for (std::size_t c = 0; c < reference_gap_.size(); ++c) {
    if (!loaded_[c] || force_[beam_.gap_unknown(c)] == 0) continue;
    const Real g = gap0_ + u[beam_.gap_unknown(c)];
    // d/du of -F (g_ref/g)^2 = 2 F g_ref^2 / g^3.
    values[diagonal_[c]] += 2 * force_[beam_.gap_unknown(c)] * scale(c, u) / g;
  }
}

}  // namespace rfmems

// The squeeze film under a prescribed gap: see reynolds_prescribed_motion.hpp.
#include "physics/gas/reynolds_prescribed_motion.hpp"

#include "core/error.hpp"

namespace rfmems {

namespace {

// The gap and its rate at the cell centroids.
CellGap at_centroids(const Mesh& mesh, FilmField gap, FilmField gap_rate) {
  if (!gap || !gap_rate)
    throw InputError("ReynoldsPrescribedMotion: the gap and its rate must both be given");
  return [&mesh, gap = std::move(gap), gap_rate = std::move(gap_rate)](Real t, std::span<Real> g,
                                                                       std::span<Real> g_rate) {
    for (std::size_t c = 0; c < g.size(); ++c) {
      const Vec3& x = mesh.cell_centroid(static_cast<Index>(c));
      g[c] = gap(x, t);
      g_rate[c] = gap_rate(x, t);
    }
  };
}

}  // namespace

ReynoldsPrescribedMotion::ReynoldsPrescribedMotion(const ReynoldsFilm& film, FilmField gap,
                                                   FilmField gap_rate, Unknown unknown, Real t0)
    : ReynoldsPrescribedMotion(film, at_centroids(film.mesh(), std::move(gap), std::move(gap_rate)),
                               unknown, t0) {}

ReynoldsPrescribedMotion::ReynoldsPrescribedMotion(const ReynoldsFilm& film, CellGap gap,
                                                   Unknown unknown, Real t0)
    : film_(film), gap_(std::move(gap)), unknown_(unknown) {
  if (!gap_) throw InputError("ReynoldsPrescribedMotion: no gap given");
  const Index n = size();
  p_.resize(n);
  p_rate_.resize(n);
  g_.resize(n);
  g_rate_.resize(n);
  values_.resize(film_.cell_pattern().nnz());
  Real sum = 0, area = 0;
  auto g0 = this->gap(t0);
  for (Index c = 0; c < n; ++c) {
    sum += g0[c] * film_.mesh().cell_volume(c);
    area += film_.mesh().cell_volume(c);
  }
  reference_gap_ = sum / area;
  if (!(reference_gap_ > 0)) throw InputError("ReynoldsPrescribedMotion: mean gap <= 0 at t0");
}

std::vector<Real> ReynoldsPrescribedMotion::differential_components() const {
  return std::vector<Real>(size(), 1.0);
}

std::vector<Real> ReynoldsPrescribedMotion::gap(Real t) const {
  std::vector<Real> g(size()), g_rate(size());
  gap_(t, g, g_rate);
  return g;
}

std::vector<Real> ReynoldsPrescribedMotion::gap_rate(Real t) const {
  std::vector<Real> g(size()), g_rate(size());
  gap_(t, g, g_rate);
  return g_rate;
}

std::vector<Real> ReynoldsPrescribedMotion::pressure(Real t, std::span<const Real> y) const {
  if (unknown_ == Unknown::Pressure) return {y.begin(), y.end()};
  auto g = gap(t);
  std::vector<Real> p(size());
  for (Index c = 0; c < size(); ++c) p[c] = reference_gap_ * y[c] / g[c];
  return p;
}

std::vector<Real> ReynoldsPrescribedMotion::state(Real t, std::span<const Real> p) const {
  if (unknown_ == Unknown::Pressure) return {p.begin(), p.end()};
  auto g = gap(t);
  std::vector<Real> y(size());
  for (Index c = 0; c < size(); ++c) y[c] = p[c] * g[c] / reference_gap_;
  return y;
}

Real ReynoldsPrescribedMotion::mass(Real t, std::span<const Real> y) const {
  Real sum = 0;
  if (unknown_ == Unknown::GapPressure) {
    for (Index c = 0; c < size(); ++c) sum += film_.mesh().cell_volume(c) * y[c];
    return sum * reference_gap_;
  }
  auto g = gap(t);
  for (Index c = 0; c < size(); ++c) sum += film_.mesh().cell_volume(c) * y[c] * g[c];
  return sum;
}

void ReynoldsPrescribedMotion::unpack(Real t, std::span<const Real> y, std::span<const Real> yp) {
  gap_(t, g_, g_rate_);
  for (Index c = 0; c < size(); ++c) {
    if (!(g_[c] > 0))
      throw RecoverableError("ReynoldsPrescribedMotion: prescribed gap <= 0 at cell " +
                             std::to_string(c));
    if (unknown_ == Unknown::Pressure) {
      p_[c] = y[c];
      p_rate_[c] = yp[c];
    } else {
      // p g = g_ref y  =>  p' g + p g' = g_ref y'.
      p_[c] = reference_gap_ * y[c] / g_[c];
      p_rate_[c] = (reference_gap_ * yp[c] - p_[c] * g_rate_[c]) / g_[c];
    }
  }
}

void ReynoldsPrescribedMotion::residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                                        std::span<Real> r) {
  unpack(t, y, yp);
  film_.residual(p_, p_rate_, g_, g_rate_, r);
}

void ReynoldsPrescribedMotion::jacobian(Real t, Real c_j, std::span<const Real> y,
                                        std::span<const Real> yp, std::span<Real> values) {
  unpack(t, y, yp);
  if (unknown_ == Unknown::Pressure) {
    film_.pressure_jacobian(c_j, p_, p_rate_, g_, g_rate_, values);
    return;
  }
  // J = (dF/dp) diag(g_ref / g) + diag(A g_ref (c_j - g'/g)); dF/dp is the c_j = 0 block.
  film_.pressure_jacobian(0.0, p_, p_rate_, g_, g_rate_, values);
  const CsrPattern& pattern = film_.cell_pattern();
  for (Index row = 0; row < size(); ++row) {
    for (Index k = pattern.row_ptr[row]; k < pattern.row_ptr[row + 1]; ++k) {
      const Index col = pattern.col_idx[k];
      values[k] *= reference_gap_ / g_[col];
      if (col == row)
        values[k] +=
            film_.mesh().cell_volume(row) * reference_gap_ * (c_j - g_rate_[row] / g_[row]);
    }
  }
}

std::vector<Real> ReynoldsPrescribedMotion::consistent_rate(Real t, std::span<const Real> y) {
  // F is affine in y' with the diagonal dF/dy' = A g (Pressure) or A g_ref (GapPressure).
  std::vector<Real> zero(size(), 0.0), r(size()), yp(size());
  residual(t, y, zero, r);
  for (Index c = 0; c < size(); ++c) {
    Real storage =
        film_.mesh().cell_volume(c) * (unknown_ == Unknown::Pressure ? g_[c] : reference_gap_);
    yp[c] = -r[c] / storage;
  }
  return yp;
}

}  // namespace rfmems

#include "coupling/immersed_reynolds_film.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace rfmems {

ImmersedReynoldsFilm::ImmersedReynoldsFilm(const GasProperties& gas, std::vector<Index> segments,
                                           Real substrate_y, Real wall_x, Real tip_x)
    : gas_(gas),
      segments_(std::move(segments)),
      substrate_y_(substrate_y),
      wall_x_(wall_x),
      tip_x_(tip_x) {
  if (segments_.empty()) throw InputError("Reynolds film: no surface segments under the beam");
  if (!(tip_x > wall_x)) throw InputError("Reynolds film: the tip is not beyond the wall");
}

void ImmersedReynoldsFilm::geometry(const ImmersedSurface& s, std::vector<Real>& h,
                                    std::vector<Real>& x, std::vector<Real>& dx) const {
  h.clear();
  x.clear();
  dx.clear();
  for (Index k : segments_) {
    const Real a = std::clamp(std::min(s.start(k).x(), s.end(k).x()), wall_x_, tip_x_);
    const Real b = std::clamp(std::max(s.start(k).x(), s.end(k).x()), wall_x_, tip_x_);
    const Real gap = s.midpoint(k).y() - substrate_y_;
    if (!(gap > 0)) throw RecoverableError(fmt::format("Reynolds film: gap {:.3e} m <= 0", gap));
    h.push_back(gap);
    x.push_back(0.5 * (a + b));
    dx.push_back(b - a);
  }
}

void ImmersedReynoldsFilm::reset(const ImmersedSurface& surface, Real) {
  std::sort(segments_.begin(), segments_.end(),
            [&](Index a, Index b) { return surface.midpoint(a).x() < surface.midpoint(b).x(); });
  std::vector<Real> x, dx;
  geometry(surface, h_, x, dx);
  p_.assign(h_.size(), gas_.ambient_pressure);
  max_knudsen_ = 0;
  saved_ = {};
}

void ImmersedReynoldsFilm::save_checkpoint() { saved_ = {p_, h_, max_knudsen_, true}; }

void ImmersedReynoldsFilm::restore_checkpoint() {
  if (!saved_.valid) throw InputError("Reynolds film: restore without a saved checkpoint");
  p_ = saved_.p;
  h_ = saved_.h;
  max_knudsen_ = saved_.max_knudsen;
}

std::vector<Vec3> ImmersedReynoldsFilm::advance(const ImmersedSurface& surface,
                                                std::span<const Vec3>, Real, Real dt) {
  std::vector<Real> h, x, dx;
  geometry(surface, h, x, dx);
  const std::size_t n = h.size();
  const Real pa = gas_.ambient_pressure;
  const std::vector<Real> p_old = p_, h_old = h_;
  std::vector<Real> p = p_, a(n), b(n), c(n), r(n), cp(n), rp(n);
  // Film coefficient h^3 p Q(Kn) / (12 mu) at a face with gap hf and pressure pf.
  auto coefficient = [&](Real hf, Real pf) {
    const Real kn = gas_.knudsen(pf, hf);
    max_knudsen_ = std::max(max_knudsen_, kn);
    return hf * hf * hf * pf * gas_.rarefaction_factor(kn) / (12 * gas_.viscosity);
  };
  for (int it = 0; it < 50; ++it) {
    for (std::size_t i = 0; i < n; ++i) {
      b[i] = h[i] * dx[i] / dt;
      a[i] = c[i] = 0;
      r[i] = p_old[i] * h_old[i] * dx[i] / dt;
    }
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const Real d = x[i + 1] - x[i];
      const Real k = coefficient(0.5 * (h[i] + h[i + 1]), 0.5 * (p[i] + p[i + 1])) / d;
      b[i] += k;
      c[i] = -k;
      b[i + 1] += k;
      a[i + 1] = -k;
    }
    const Real k_tip = coefficient(h[n - 1], 0.5 * (p[n - 1] + pa)) / (0.5 * dx[n - 1]);
    b[n - 1] += k_tip;
    r[n - 1] += k_tip * pa;
    // Thomas algorithm.
    cp[0] = c[0] / b[0];
    rp[0] = r[0] / b[0];
    for (std::size_t i = 1; i < n; ++i) {
      const Real m = b[i] - a[i] * cp[i - 1];
      cp[i] = c[i] / m;
      rp[i] = (r[i] - a[i] * rp[i - 1]) / m;
    }
    std::vector<Real> next(n);
    next[n - 1] = rp[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) next[i] = rp[i] - cp[i] * next[i + 1];
    Real change = 0;
    for (std::size_t i = 0; i < n; ++i) change = std::max(change, std::abs(next[i] - p[i]));
    p = std::move(next);
    if (change <= 1e-12 * pa) break;
  }
  p_ = p;
  h_ = h;
  std::vector<Vec3> force(surface.n_segments(), Vec3::Zero());
  for (std::size_t i = 0; i < n; ++i) {
    const Index k = segments_[i];
    force[k] = -(p_[i] - pa) * dx[i] * surface.normal(k);
  }
  return force;
}

}  // namespace rfmems

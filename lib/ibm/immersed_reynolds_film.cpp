#include "ibm/immersed_reynolds_film.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "physics/gas/reynolds_film.hpp"
#include "physics/gas/reynolds_prescribed_motion.hpp"
#include "solvers/ida_integrator.hpp"

namespace rfmems {

ImmersedReynoldsFilm::ImmersedReynoldsFilm(const GasProperties& gas, std::vector<Index> segments,
                                           Real substrate_y, Real wall_x, Real tip_x, Real rtol)
    : gas_(gas),
      segments_(std::move(segments)),
      substrate_y_(substrate_y),
      wall_x_(wall_x),
      tip_x_(tip_x),
      rtol_(rtol) {
  if (segments_.empty()) throw InputError("Reynolds film: no surface segments under the beam");
  if (!(tip_x > wall_x)) throw InputError("Reynolds film: the tip is not beyond the wall");
}

ImmersedReynoldsFilm::~ImmersedReynoldsFilm() = default;

std::vector<Real> ImmersedReynoldsFilm::gaps(const ImmersedSurface& s) const {
  std::vector<Real> h;
  h.reserve(segments_.size());
  for (Index k : segments_) {
    const Real gap = s.midpoint(k).y() - substrate_y_;
    if (!(gap > 0)) throw RecoverableError(fmt::format("Reynolds film: gap {:.3e} m <= 0", gap));
    h.push_back(gap);
  }
  return h;
}

void ImmersedReynoldsFilm::reset(const ImmersedSurface& surface, Real t0) {
  std::sort(segments_.begin(), segments_.end(),
            [&](Index a, Index b) { return surface.midpoint(a).x() < surface.midpoint(b).x(); });
  // The strip: one quad per segment between its clipped ends, unit depth along y.
  MeshBuilder builder(2);
  const std::size_t n = segments_.size();
  for (std::size_t i = 0; i <= n; ++i) {
    const Index k = segments_[std::min(i, n - 1)];
    const Real x = i < n ? std::min(surface.start(k).x(), surface.end(k).x())
                         : std::max(surface.start(k).x(), surface.end(k).x());
    const Real clipped = std::clamp(x, wall_x_, tip_x_);
    builder.add_node(Vec3(clipped, 0, 0));
    builder.add_node(Vec3(clipped, 1, 0));
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto a = static_cast<Index>(2 * i);
    builder.add_cell(CellShape::Quad, {a, a + 2, a + 3, a + 1});
    builder.add_boundary_face({a, a + 2}, "sides");
    builder.add_boundary_face({a + 3, a + 1}, "sides");
  }
  builder.add_boundary_face({1, 0}, "wall");
  builder.add_boundary_face({static_cast<Index>(2 * n), static_cast<Index>(2 * n + 1)}, "tip");
  strip_ = std::make_unique<Mesh>(builder.build("Reynolds film strip"));
  for (Index c = 0; c < strip_->n_cells(); ++c)
    if (!(strip_->cell_volume(c) > 0))
      throw InputError(
          "Reynolds film: a facing segment has no extent between the wall and the tip");
  std::vector<FilmBoundary> boundaries(strip_->patches().size());
  boundaries[strip_->find_patch("tip")].kind = FilmBoundary::Kind::Open;
  film_ = std::make_unique<ReynoldsFilm>(*strip_, gas_, boundaries);

  state_ = {std::vector<Real>(n, gas_.ambient_pressure), std::vector<Real>(n, 0.0), gaps(surface),
            0.0};
  h0_ = h1_ = state_.h;
  t0_ = t0;
  t1_ = t0 + 1;
  motion_ = std::make_unique<ReynoldsPrescribedMotion>(
      *film_,
      [this](Real t, std::span<Real> g, std::span<Real> g_rate) {
        const Real span = t1_ - t0_, s = std::clamp((t - t0_) / span, 0.0, 1.0);
        for (std::size_t c = 0; c < g.size(); ++c) {
          g[c] = (1 - s) * h0_[c] + s * h1_[c];
          g_rate[c] = (h1_[c] - h0_[c]) / span;
        }
      },
      ReynoldsPrescribedMotion::Unknown::Pressure, t0);
  IdaOptions options;
  options.rtol = rtol_;
  options.atol = rtol_ * gas_.ambient_pressure;
  options.max_order = 2;
  ida_ = std::make_unique<IdaIntegrator>(*motion_, options);
  ida_->initialize(t0, state_.p, state_.p_rate);
  has_saved_ = false;
}

void ImmersedReynoldsFilm::save_checkpoint() {
  saved_ = state_;
  has_saved_ = true;
}

void ImmersedReynoldsFilm::restore_checkpoint() {
  if (!has_saved_) throw InputError("Reynolds film: restore without a saved checkpoint");
  state_ = saved_;
}

std::vector<Vec3> ImmersedReynoldsFilm::advance(const ImmersedSurface& surface,
                                                std::span<const Vec3>, Real t, Real dt) {
  if (!film_) throw InputError("Reynolds film: advance before reset");
  h0_ = state_.h;
  h1_ = gaps(surface);
  t0_ = t;
  t1_ = t + dt;
  // The rate consistent with the new interval's gap rate (the storage term is diagonal).
  state_.p_rate = motion_->consistent_rate(t, state_.p);
  ida_->reinitialize(t, state_.p, state_.p_rate);
  ida_->advance(t + dt);
  state_.p.assign(ida_->y().begin(), ida_->y().end());
  state_.p_rate.assign(ida_->yp().begin(), ida_->yp().end());
  state_.h = h1_;
  for (std::size_t i = 0; i < segments_.size(); ++i)
    state_.max_knudsen = std::max(state_.max_knudsen, gas_.knudsen(state_.p[i], state_.h[i]));
  std::vector<Vec3> force(surface.n_segments(), Vec3::Zero());
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    const Index k = segments_[i];
    force[k] = -(state_.p[i] - gas_.ambient_pressure) * strip_->cell_volume(static_cast<Index>(i)) *
               surface.normal(k);
  }
  return force;
}

}  // namespace rfmems

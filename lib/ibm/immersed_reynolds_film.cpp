#include "ibm/immersed_reynolds_film.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "physics/gas/prescribed_gap_film.hpp"
#include "physics/gas/reynolds_film.hpp"

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

  stepped_ = std::make_unique<PrescribedGapFilm>(*film_, gaps(surface), t0, rtol_);
}

Real ImmersedReynoldsFilm::max_knudsen() const { return stepped_ ? stepped_->max_knudsen() : 0; }

PrescribedGapFilm& ImmersedReynoldsFilm::stepper() const {
  if (!stepped_) throw InputError("Reynolds film: used before reset");
  return *stepped_;
}

const std::vector<Real>& ImmersedReynoldsFilm::pressure() const { return stepper().pressure(); }

void ImmersedReynoldsFilm::save_checkpoint() { stepper().save_checkpoint(); }

void ImmersedReynoldsFilm::restore_checkpoint() { stepper().restore_checkpoint(); }

std::vector<Vec3> ImmersedReynoldsFilm::advance(const ImmersedSurface& surface,
                                                std::span<const Vec3>, Real t, Real dt) {
  const std::vector<Real>& p = stepper().advance(gaps(surface), t, dt);
  std::vector<Vec3> force(surface.n_segments(), Vec3::Zero());
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    const Index k = segments_[i];
    force[k] = -(p[i] - gas_.ambient_pressure) * strip_->cell_volume(static_cast<Index>(i)) *
               surface.normal(k);
  }
  return force;
}

}  // namespace rfmems

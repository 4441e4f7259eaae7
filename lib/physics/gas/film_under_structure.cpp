#include "physics/gas/film_under_structure.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace rfmems {

FilmUnderStructure::FilmUnderStructure(const ReynoldsFilm& film, std::vector<Index> gap_unknown,
                                       Index structure_size, Real rest_gap, Real rtol)
    : film_(film),
      gap_unknown_(std::move(gap_unknown)),
      structure_size_(structure_size),
      rest_gap_(rest_gap),
      rtol_(rtol) {
  if (static_cast<Index>(gap_unknown_.size()) != film.size())
    throw InputError("Reynolds film: one structure unknown per film cell");
}

PrescribedGapFilm& FilmUnderStructure::stepper() {
  if (!stepped_) throw InputError("Reynolds film: advance before reset");
  return *stepped_;
}

void FilmUnderStructure::reset(Real t0) {
  stepped_ = std::make_unique<PrescribedGapFilm>(
      film_, std::vector<Real>(gap_unknown_.size(), rest_gap_), t0, rtol_);
}

StructureLoad FilmUnderStructure::advance(std::span<const Real> u, std::span<const Real>, Real t,
                                          Real dt) {
  std::vector<Real> gap(gap_unknown_.size());
  for (std::size_t c = 0; c < gap.size(); ++c) {
    gap[c] = rest_gap_ + u[gap_unknown_[c]];
    if (!(gap[c] > 0))
      throw RecoverableError(fmt::format("Reynolds film: gap {:.3e} m <= 0", gap[c]));
  }
  const std::vector<Real>& p = stepper().advance(std::move(gap), t, dt);
  const Real pa = film_.gas().ambient_pressure;
  const std::vector<Real>& area = film_.plate_force_derivative();
  StructureLoad out{std::vector<Real>(structure_size_, 0.0), film_.total_force(p)};
  for (std::size_t c = 0; c < gap_unknown_.size(); ++c)
    out.force[gap_unknown_[c]] = (p[c] - pa) * area[c];
  return out;
}

}  // namespace rfmems

#include "physics/gas/prescribed_gap_film.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "physics/gas/reynolds_film.hpp"
#include "physics/gas/reynolds_prescribed_motion.hpp"
#include "solvers/ida_integrator.hpp"

namespace rfmems {

PrescribedGapFilm::PrescribedGapFilm(const ReynoldsFilm& film, std::vector<Real> gap, Real t0,
                                     Real rtol)
    : film_(film), t0_(t0), t1_(t0 + 1) {
  if (static_cast<Index>(gap.size()) != film.size())
    throw InputError("Reynolds film: one gap per film cell");
  const Real pa = film.gas().ambient_pressure;
  state_ = {std::vector<Real>(gap.size(), pa), std::vector<Real>(gap.size(), 0.0), gap, 0.0};
  h0_ = h1_ = std::move(gap);
  motion_ = std::make_unique<ReynoldsPrescribedMotion>(
      film_,
      [this](Real t, std::span<Real> g, std::span<Real> g_rate) {
        const Real span = t1_ - t0_, s = std::clamp((t - t0_) / span, 0.0, 1.0);
        for (std::size_t c = 0; c < g.size(); ++c) {
          g[c] = (1 - s) * h0_[c] + s * h1_[c];
          g_rate[c] = (h1_[c] - h0_[c]) / span;
        }
      },
      ReynoldsPrescribedMotion::Unknown::Pressure, t0);
  IdaOptions options;
  options.rtol = rtol;
  options.atol = rtol * pa;
  options.max_order = 2;
  ida_ = std::make_unique<IdaIntegrator>(*motion_, options);
  ida_->initialize(t0, state_.p, state_.p_rate);
}

PrescribedGapFilm::~PrescribedGapFilm() = default;

const std::vector<Real>& PrescribedGapFilm::advance(std::vector<Real> gap, Real t, Real dt) {
  h0_ = state_.h;
  h1_ = std::move(gap);
  t0_ = t;
  t1_ = t + dt;
  state_.p_rate = motion_->consistent_rate(t, state_.p);
  ida_->reinitialize(t, state_.p, state_.p_rate);
  ida_->advance(t + dt);
  state_.p.assign(ida_->y().begin(), ida_->y().end());
  state_.p_rate.assign(ida_->yp().begin(), ida_->yp().end());
  state_.h = h1_;
  for (std::size_t c = 0; c < state_.p.size(); ++c)
    state_.max_knudsen =
        std::max(state_.max_knudsen, film_.gas().knudsen(state_.p[c], state_.h[c]));
  return state_.p;
}

void PrescribedGapFilm::save_checkpoint() {
  saved_ = state_;
  has_saved_ = true;
}

void PrescribedGapFilm::restore_checkpoint() {
  if (!has_saved_) throw InputError("Reynolds film: restore without a saved checkpoint");
  state_ = saved_;
}

}  // namespace rfmems

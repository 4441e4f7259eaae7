#include "coupling/squeeze_film_switch_system.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace rfmems {

SqueezeFilmSwitchSystem::SqueezeFilmSwitchSystem(ParallelPlateActuation& actuation,
                                                 std::vector<bool> quasi_static,
                                                 const ReynoldsFilm& film, std::vector<Index> w_dof)
    : actuation_(actuation),
      structure_(actuation, std::move(quasi_static)),
      film_(film),
      w_dof_(std::move(w_dof)),
      m_(structure_.size()),
      n_cells_(film.size()),
      p_ambient_(film.gas().ambient_pressure) {
  if (static_cast<Index>(w_dof_.size()) != n_cells_)
    throw std::logic_error("SqueezeFilmSwitchSystem: one deflection unknown per film cell");
  for (Index c = 0; c < n_cells_; ++c) {
    v_index_.push_back(structure_.velocity_index(w_dof_[c]));
    if (v_index_.back() < 0)
      throw std::logic_error("SqueezeFilmSwitchSystem: the deflection must carry inertia");
  }
  std::map<Index, Index> cell_of_velocity;
  for (Index c = 0; c < n_cells_; ++c) cell_of_velocity[v_index_[c]] = c;

  // Rows of the structure: its own columns, then p_c in the momentum row of w_c.
  const CsrPattern& s = structure_.jacobian_pattern();
  const CsrPattern& f = film_.cell_pattern();
  coupling_position_.assign(n_cells_, -1);
  for (Index row = 0; row < m_; ++row) {
    for (Index k = s.row_ptr[row]; k < s.row_ptr[row + 1]; ++k) {
      structure_position_.push_back(pattern_.nnz());
      pattern_.col_idx.push_back(s.col_idx[k]);
    }
    const auto it = cell_of_velocity.find(row);
    if (it != cell_of_velocity.end()) {
      coupling_position_[it->second] = pattern_.nnz();
      pattern_.col_idx.push_back(m_ + it->second);
    }
    pattern_.row_ptr.push_back(pattern_.nnz());
  }
  // Rows of the film: w, v and p columns of the film's neighbours, sorted.
  film_w_position_.resize(f.nnz());
  film_v_position_.resize(f.nnz());
  film_p_position_.resize(f.nnz());
  for (Index c = 0; c < n_cells_; ++c) {
    std::vector<std::pair<Index, Index*>> columns;  // (column, where its position goes)
    for (Index k = f.row_ptr[c]; k < f.row_ptr[c + 1]; ++k) {
      const Index cc = f.col_idx[k];
      columns.emplace_back(w_dof_[cc], &film_w_position_[k]);
      columns.emplace_back(v_index_[cc], &film_v_position_[k]);
      columns.emplace_back(m_ + cc, &film_p_position_[k]);
    }
    std::sort(columns.begin(), columns.end());
    for (auto& [column, position] : columns) {
      *position = pattern_.nnz();
      pattern_.col_idx.push_back(column);
    }
    pattern_.row_ptr.push_back(pattern_.nnz());
  }
  gap_.resize(n_cells_);
  gap_rate_.resize(n_cells_);
  structure_values_.resize(s.nnz());
  film_values_.resize(f.nnz());
  film_values0_.resize(f.nnz());
}

std::vector<Real> SqueezeFilmSwitchSystem::differential_components() const {
  std::vector<Real> id = structure_.differential_components();
  id.resize(size(), 1.0);  // the film pressure is differential (d(p g)/dt)
  return id;
}

void SqueezeFilmSwitchSystem::film_inputs(std::span<const Real> y, std::span<const Real>) {
  const Real g0 = actuation_.initial_gap();
  for (Index c = 0; c < n_cells_; ++c) {
    gap_[c] = g0 + y[w_dof_[c]];
    gap_rate_[c] = y[v_index_[c]];
  }
}

void SqueezeFilmSwitchSystem::residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                                       std::span<Real> r) {
  structure_.residual(t, y.subspan(0, m_), yp.subspan(0, m_), r.subspan(0, m_));
  const auto& area = film_.plate_force_derivative();
  for (Index c = 0; c < n_cells_; ++c) r[v_index_[c]] -= (y[m_ + c] - p_ambient_) * area[c];
  film_inputs(y, yp);
  film_.residual(y.subspan(m_, n_cells_), yp.subspan(m_, n_cells_), gap_, gap_rate_,
                 r.subspan(m_, n_cells_));
}

void SqueezeFilmSwitchSystem::jacobian(Real t, Real c_j, std::span<const Real> y,
                                       std::span<const Real> yp, std::span<Real> values) {
  std::fill(values.begin(), values.end(), 0.0);
  structure_.jacobian(t, c_j, y.subspan(0, m_), yp.subspan(0, m_), structure_values_);
  for (std::size_t k = 0; k < structure_values_.size(); ++k)
    values[structure_position_[k]] = structure_values_[k];
  const auto& area = film_.plate_force_derivative();
  for (Index c = 0; c < n_cells_; ++c) values[coupling_position_[c]] = -area[c];

  film_inputs(y, yp);
  const auto p = y.subspan(m_, n_cells_), p_rate = yp.subspan(m_, n_cells_);
  film_.pressure_jacobian(c_j, p, p_rate, gap_, gap_rate_, film_values_);
  for (std::size_t k = 0; k < film_values_.size(); ++k)
    values[film_p_position_[k]] = film_values_[k];
  // dF/dg (c_j = 0) on the w columns; dF/dg' (the c_j = 1 part minus it) on the v columns.
  film_.gap_jacobian(0.0, p, p_rate, gap_, gap_rate_, film_values0_);
  film_.gap_jacobian(1.0, p, p_rate, gap_, gap_rate_, film_values_);
  for (std::size_t k = 0; k < film_values_.size(); ++k) {
    values[film_w_position_[k]] = film_values0_[k];
    values[film_v_position_[k]] = film_values_[k] - film_values0_[k];
  }
}

void SqueezeFilmSwitchSystem::initial_state(Real t0, std::vector<Real>& y, std::vector<Real>& yp) {
  y.assign(size(), 0.0);
  std::vector<Real> s(m_, 0.0);
  const std::vector<Real> sp = structure_.consistent_derivative(t0, s);
  yp.assign(size(), 0.0);
  std::copy(sp.begin(), sp.end(), yp.begin());
  for (Index c = 0; c < n_cells_; ++c) y[m_ + c] = p_ambient_;  // film at rest, ambient
}

std::vector<StateKind> SqueezeFilmSwitchSystem::state_kinds() const {
  std::vector<StateKind> kinds = reduced_inertia_state_kinds(structure_, actuation_.size());
  kinds.resize(size(), StateKind::Pressure);
  return kinds;
}

Real SqueezeFilmSwitchSystem::velocity(std::span<const Real> y, std::span<const Real> yp,
                                       Index i) const {
  const Index v = structure_.velocity_index(i);
  return v >= 0 ? y[v] : yp[i];
}

Real SqueezeFilmSwitchSystem::gas_force(std::span<const Real> y) const {
  return film_.total_force(y.subspan(m_, n_cells_));
}

}  // namespace rfmems

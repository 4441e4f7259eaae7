// Finite-volume isothermal compressible Reynolds equation: see reynolds_film.hpp.
#include "physics/gas/reynolds_film.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace rfmems {

ReynoldsFilm::ReynoldsFilm(const Mesh& mesh, GasProperties gas,
                           std::vector<FilmBoundary> boundaries)
    : mesh_(mesh), gas_(gas), boundaries_(std::move(boundaries)) {
  if (mesh_.dim() != 2) throw InputError("ReynoldsFilm: the film lives on a 2D (plate) mesh");
  if (mesh_.n_owned_cells() != mesh_.n_cells())
    throw InputError("ReynoldsFilm: distributed meshes (ghost cells) are not supported");
  if (boundaries_.size() != mesh_.patches().size())
    throw InputError("ReynoldsFilm: " + std::to_string(boundaries_.size()) +
                     " boundary conditions for " + std::to_string(mesh_.patches().size()) +
                     " mesh patches");
  if (!(gas_.viscosity > 0) || !(gas_.ambient_pressure > 0) ||
      (gas_.rarefaction != Rarefaction::None &&
       (!(gas_.mean_free_path > 0) || !(gas_.reference_pressure > 0))))
    throw InputError("ReynoldsFilm: viscosity, pressures and mean free path must be > 0");
  if (gas_.rarefaction == Rarefaction::Table && !gas_.flow_factor_table)
    throw InputError("ReynoldsFilm: rarefaction table without a flow-factor table");

  const Index n = mesh_.n_cells();
  area_.resize(n);
  for (Index c = 0; c < n; ++c) area_[c] = mesh_.cell_volume(c);

  // Pattern: each cell and its face neighbours, sorted.
  std::vector<std::vector<Index>> columns(n);
  for (Index c = 0; c < n; ++c) columns[c].push_back(c);
  for (Index f = 0; f < mesh_.n_interior_faces(); ++f) {
    Index P = mesh_.face_owner(f), N = mesh_.face_neighbour(f);
    columns[P].push_back(N);
    columns[N].push_back(P);
  }
  pattern_.row_ptr.assign(1, 0);
  pattern_.col_idx.clear();
  for (Index c = 0; c < n; ++c) {
    auto& cols = columns[c];
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
    pattern_.col_idx.insert(pattern_.col_idx.end(), cols.begin(), cols.end());
    pattern_.row_ptr.push_back(static_cast<Index>(pattern_.col_idx.size()));
  }
  diagonal_slot_.resize(n);
  for (Index c = 0; c < n; ++c) diagonal_slot_[c] = pattern_.find(c, c);

  for (Index f = 0; f < mesh_.n_faces(); ++f) {
    Face face;
    face.owner = mesh_.face_owner(f);
    face.neighbour = mesh_.face_neighbour(f);
    const Vec3& xP = mesh_.cell_centroid(face.owner);
    const Vec3& xf = mesh_.face_centroid(f);
    const Vec3& S = mesh_.face_area(f);
    if (mesh_.is_boundary(f)) {
      face.open = boundaries_[mesh_.face_patch(f)].kind == FilmBoundary::Kind::Open;
      if (!face.open) continue;  // a wall carries no flux
      Vec3 d = xf - xP;
      face.transmissibility = S.dot(d) / d.squaredNorm();  // (S.e)/|d|
      face.owner_weight = 1.0;
      face.slot = {diagonal_slot_[face.owner], -1, -1, -1};
    } else {
      const Vec3& xN = mesh_.cell_centroid(face.neighbour);
      Vec3 d = xN - xP;
      face.transmissibility = S.dot(d) / d.squaredNorm();
      face.owner_weight = std::clamp((xN - xf).dot(d) / d.squaredNorm(), 0.0, 1.0);
      face.open = false;
      face.slot = {diagonal_slot_[face.owner], pattern_.find(face.owner, face.neighbour),
                   pattern_.find(face.neighbour, face.owner), diagonal_slot_[face.neighbour]};
    }
    if (!(face.transmissibility > 0))
      throw MeshError("ReynoldsFilm: face " + std::to_string(f) +
                      " has its centroid-to-centroid vector at or beyond 90 degrees from its "
                      "normal");
    faces_.push_back(face);
  }
}

Real ReynoldsFilm::flow_coefficient(Real p, Real g) const {
  Real q = gas_.rarefaction_factor(gas_.knudsen(p, g));
  return g * g * g * p * q / (12.0 * gas_.viscosity);
}

ReynoldsFilm::FlowCoefficient ReynoldsFilm::flow_coefficient_with_derivatives(Real p,
                                                                              Real g) const {
  Real kn = gas_.knudsen(p, g);
  Real q = gas_.rarefaction_factor(kn);
  // dQ/dp = Q'(Kn) dKn/dp = -Q'(Kn) Kn / p; likewise for g. So p dQ/dp = g dQ/dg = -Q' Kn.
  Real q_log_slope = -gas_.rarefaction_factor_derivative(kn) * kn;
  Real scale = 1.0 / (12.0 * gas_.viscosity);
  Real g3 = g * g * g;
  return {g3 * p * q * scale, g3 * (q + q_log_slope) * scale,
          p * g * g * (3.0 * q + q_log_slope) * scale};
}

void ReynoldsFilm::check_state(std::span<const Real> p, std::span<const Real> gap) const {
  for (Index c = 0; c < size(); ++c) {
    if (!(gap[c] > 0))
      throw RecoverableError("ReynoldsFilm: gap " + std::to_string(gap[c]) + " m at cell " +
                             std::to_string(c) + " (the plate touches the substrate)");
    if (!(p[c] > 0))
      throw RecoverableError("ReynoldsFilm: pressure " + std::to_string(p[c]) + " Pa at cell " +
                             std::to_string(c));
  }
}

void ReynoldsFilm::residual(std::span<const Real> p, std::span<const Real> p_rate,
                            std::span<const Real> gap, std::span<const Real> gap_rate,
                            std::span<Real> r) const {
  check_state(p, gap);
  const Real pa = gas_.ambient_pressure;
  // Storage: d(p g)/dt A.
  for (Index c = 0; c < size(); ++c) r[c] = (p_rate[c] * gap[c] + p[c] * gap_rate[c]) * area_[c];
  // Fluxes out of the owner's balance and into the neighbour's.
  for (const Face& f : faces_) {
    const Index P = f.owner;
    if (f.neighbour < 0) {
      r[P] -= flow_coefficient(pa, gap[P]) * f.transmissibility * (pa - p[P]);
      continue;
    }
    const Index N = f.neighbour;
    Real D = f.owner_weight * flow_coefficient(p[P], gap[P]) +
             (1.0 - f.owner_weight) * flow_coefficient(p[N], gap[N]);
    Real flux = D * f.transmissibility * (p[N] - p[P]);
    r[P] -= flux;
    r[N] += flux;
  }
}

void ReynoldsFilm::pressure_jacobian(Real c_j, std::span<const Real> p,
                                     std::span<const Real> /*p_rate*/, std::span<const Real> gap,
                                     std::span<const Real> gap_rate, std::span<Real> values) const {
  check_state(p, gap);
  const Real pa = gas_.ambient_pressure;
  std::fill(values.begin(), values.end(), 0.0);
  for (Index c = 0; c < size(); ++c)
    values[diagonal_slot_[c]] = (gap_rate[c] + c_j * gap[c]) * area_[c];
  for (const Face& f : faces_) {
    const Index P = f.owner;
    if (f.neighbour < 0) {
      // flux = D(p_a, g_P) T (p_a - p_P): only p_P enters.
      values[f.slot[0]] += flow_coefficient(pa, gap[P]) * f.transmissibility;
      continue;
    }
    const Index N = f.neighbour;
    auto cP = flow_coefficient_with_derivatives(p[P], gap[P]);
    auto cN = flow_coefficient_with_derivatives(p[N], gap[N]);
    const Real wP = f.owner_weight, wN = 1.0 - wP, T = f.transmissibility;
    const Real D = wP * cP.value + wN * cN.value;
    const Real dp = p[N] - p[P];
    const Real dflux_dpP = T * (wP * cP.d_pressure * dp - D);
    const Real dflux_dpN = T * (wN * cN.d_pressure * dp + D);
    values[f.slot[0]] -= dflux_dpP;
    values[f.slot[1]] -= dflux_dpN;
    values[f.slot[2]] += dflux_dpP;
    values[f.slot[3]] += dflux_dpN;
  }
}

void ReynoldsFilm::gap_jacobian(Real c_j, std::span<const Real> p, std::span<const Real> p_rate,
                                std::span<const Real> gap, std::span<const Real> /*gap_rate*/,
                                std::span<Real> values) const {
  check_state(p, gap);
  const Real pa = gas_.ambient_pressure;
  std::fill(values.begin(), values.end(), 0.0);
  for (Index c = 0; c < size(); ++c)
    values[diagonal_slot_[c]] = (p_rate[c] + c_j * p[c]) * area_[c];
  for (const Face& f : faces_) {
    const Index P = f.owner;
    if (f.neighbour < 0) {
      auto cb = flow_coefficient_with_derivatives(pa, gap[P]);
      values[f.slot[0]] -= cb.d_gap * f.transmissibility * (pa - p[P]);
      continue;
    }
    const Index N = f.neighbour;
    auto cP = flow_coefficient_with_derivatives(p[P], gap[P]);
    auto cN = flow_coefficient_with_derivatives(p[N], gap[N]);
    const Real wP = f.owner_weight, T = f.transmissibility;
    const Real dp = p[N] - p[P];
    const Real dflux_dgP = T * wP * cP.d_gap * dp;
    const Real dflux_dgN = T * (1.0 - wP) * cN.d_gap * dp;
    values[f.slot[0]] -= dflux_dgP;
    values[f.slot[1]] -= dflux_dgN;
    values[f.slot[2]] += dflux_dgP;
    values[f.slot[3]] += dflux_dgN;
  }
}

void ReynoldsFilm::plate_force(std::span<const Real> p, std::span<Real> force) const {
  for (Index c = 0; c < size(); ++c) force[c] = (p[c] - gas_.ambient_pressure) * area_[c];
}

Real ReynoldsFilm::total_force(std::span<const Real> p) const {
  Real sum = 0;
  for (Index c = 0; c < size(); ++c) sum += (p[c] - gas_.ambient_pressure) * area_[c];
  return sum;
}

}  // namespace rfmems

#include "physics/plate/von_karman_plate.hpp"

#include <algorithm>
#include <stdexcept>

namespace rfmems {

namespace {

// The in-plane identity (the z row and column of the 3 x 3 tensors are unused).
Mat3 in_plane_identity() {
  Mat3 I = Mat3::Identity();
  I(2, 2) = 0;
  return I;
}

}  // namespace

VonKarmanPlate::VonKarmanPlate(PlateOperator& plate) : plate_(plate), mesh_(plate.mesh()) {
  const PlateSection& s = plate_.section();
  const Real membrane_stiffness = s.E * s.thickness / (1 - s.nu * s.nu);
  mu_ = 0.5 * membrane_stiffness * (1 - s.nu);
  lambda_ = membrane_stiffness * s.nu;
  const std::vector<PlateBoundary>& bcs = plate_.boundaries();
  // w given (held edges), u given (held and not released in-plane).
  auto w_held = [&](Index f) { return bcs[mesh_.face_patch(f)].prescribes_deflection(); };
  auto u_held = [&](Index f) {
    const PlateBoundary& bc = bcs[mesh_.face_patch(f)];
    return bc.prescribes_deflection() && !bc.in_plane_free;
  };
  auto point = [](bool given) { return given ? BoundaryPoint::Value : BoundaryPoint::None; };
  w_rec_ = std::make_unique<PolynomialReconstruction>(
      mesh_, [&](Index f) { return point(w_held(f)); }, plate_.reconstruction_degree());
  bool same = true;
  for (Index f = 0; f < mesh_.n_faces() && same; ++f)
    same = !mesh_.is_boundary(f) || w_held(f) == u_held(f);
  if (!same)
    own_u_rec_ = std::make_unique<PolynomialReconstruction>(
        mesh_, [&](Index f) { return point(u_held(f)); }, plate_.reconstruction_degree());
  const PolynomialReconstruction& u_rec = same ? *w_rec_ : *own_u_rec_;

  // Face-gradient weights: side(c, g, v) adds g grad p_c(x_f) + v p_c(x_f), with
  // p_c(x) = phi_c + sum_j value_j (phi_j - phi_c), grad p_c(x) = sum_j gradient_j (phi_j - phi_c),
  // into the w weights (slot 0) or the u weights (slot 1); u's boundary values are zero.
  std::vector<Real> value;
  std::vector<Vec3> gradient;
  std::vector<GradientWeight> face;
  auto add_side = [&](const PolynomialReconstruction& rec, int slot, Index c, const Vec3& x,
                      Real grad_factor, const Vec3& value_vector) {
    rec.weights_at(c, x, value, gradient);
    auto points = rec.points(c);
    Vec3 own = value_vector;
    auto push = [&](Index cell, Index boundary_face, const Vec3& k) {
      GradientWeight g{cell, boundary_face, Vec3::Zero(), Vec3::Zero()};
      (slot == 0 ? g.w : g.u) = k;
      face.push_back(g);
    };
    for (std::size_t j = 0; j < points.size(); ++j) {
      const Vec3 k = grad_factor * gradient[j] + value[j] * value_vector;
      own -= k;
      if (points[j].kind == StencilPoint::Kind::Cell)
        push(points[j].cell, -1, k);
      else if (points[j].kind == StencilPoint::Kind::BoundaryValue && slot == 0)
        push(-1, points[j].face, k);
      else if (points[j].kind == StencilPoint::Kind::Mirror)
        throw std::logic_error("von Karman plate: mirror stencil points are not supported");
    }
    push(c, -1, own);
  };
  for (Index f = 0; f < mesh_.n_faces(); ++f) {
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    if (n < 0 && !u_held(f)) continue;  // N n = 0
    const Vec3& xf = mesh_.face_centroid(f);
    // The plate operator's face geometry: d = x_N - x_P (x_f - x_P on a boundary).
    const Vec3 d = (n >= 0 ? mesh_.cell_centroid(n) : xf) - mesh_.cell_centroid(p);
    const Vec3 jump = d / d.squaredNorm();  // e / |d|
    face.clear();
    for (int slot = 0; slot < 2; ++slot) {
      const PolynomialReconstruction& rec = slot == 0 ? *w_rec_ : u_rec;
      if (n >= 0) {
        add_side(rec, slot, p, xf, 0.5, -jump);
        add_side(rec, slot, n, xf, 0.5, jump);
      } else {
        add_side(rec, slot, p, xf, 1.0, -jump);
      }
    }
    if (n < 0) face.push_back({-1, f, jump, Vec3::Zero()});  // w_b (u_b = 0)
    // One weight per cell and per boundary value.
    std::vector<GradientWeight> merged;
    for (const GradientWeight& g : face) {
      auto it = std::find_if(merged.begin(), merged.end(), [&](const GradientWeight& m) {
        return m.cell == g.cell && m.face == g.face;
      });
      if (it == merged.end()) {
        merged.push_back(g);
      } else {
        it->w += g.w;
        it->u += g.u;
      }
    }
    faces_.push_back(f);
    weights_.insert(weights_.end(), merged.begin(), merged.end());
    offset_.push_back(static_cast<Index>(weights_.size()));
  }

  // Pattern: the plate's entries and, for every face, the 3 x 3 blocks (w, u, v) x (w, u, v)
  // between each side's cell and each cell of the face gradients.
  const Index nc = mesh_.n_cells(), n = size();
  auto unknowns = [&](Index c) {
    return std::array<Index, 3>{3 * c + PlateOperator::kW, in_plane_index(c, 0),
                                in_plane_index(c, 1)};
  };
  std::vector<std::vector<Index>> rows(n);
  const CsrPattern& plate_pattern = plate_.stiffness_pattern();
  for (Index i = 0; i < plate_pattern.n_rows(); ++i)
    for (Index k = plate_pattern.row_ptr[i]; k < plate_pattern.row_ptr[i + 1]; ++k)
      rows[i].push_back(plate_pattern.col_idx[k]);
  for (Index i = 3 * nc; i < n; ++i) rows[i].push_back(i);
  for (std::size_t k = 0; k < faces_.size(); ++k) {
    const Index f = faces_[k];
    for (Index side : {mesh_.face_owner(f), mesh_.face_neighbour(f)}) {
      if (side < 0) continue;
      for (Index j = offset_[k]; j < offset_[k + 1]; ++j) {
        if (weights_[j].cell < 0) continue;
        for (Index row : unknowns(side))
          for (Index col : unknowns(weights_[j].cell)) rows[row].push_back(col);
      }
    }
  }
  pattern_ = CsrPattern{};
  for (auto& r : rows) {
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
    pattern_.col_idx.insert(pattern_.col_idx.end(), r.begin(), r.end());
    pattern_.row_ptr.push_back(pattern_.nnz());
  }
  for (Index i = 0; i < plate_pattern.n_rows(); ++i)
    for (Index k = plate_pattern.row_ptr[i]; k < plate_pattern.row_ptr[i + 1]; ++k)
      plate_position_.push_back(pattern_.find(i, plate_pattern.col_idx[k]));
  plate_values_.resize(plate_pattern.nnz());

  // Block positions, one per (row cell, column cell) pair.
  std::vector<std::vector<std::pair<Index, Index>>> blocks(nc);  // column cell, block
  auto block = [&](Index row_cell, Index col_cell) {
    for (const auto& [c, b] : blocks[row_cell])
      if (c == col_cell) return b;
    std::array<Index, 9> positions;
    const auto r = unknowns(row_cell), q = unknowns(col_cell);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) positions[3 * i + j] = pattern_.find(r[i], q[j]);
    block_position_.push_back(positions);
    const Index b = static_cast<Index>(block_position_.size()) - 1;
    blocks[row_cell].emplace_back(col_cell, b);
    return b;
  };
  for (std::size_t k = 0; k < faces_.size(); ++k) {
    const Index f = faces_[k];
    for (Index j = offset_[k]; j < offset_[k + 1]; ++j)
      for (Index side : {mesh_.face_owner(f), mesh_.face_neighbour(f)})
        block_of_weight_.push_back(
            side >= 0 && weights_[j].cell >= 0 ? block(side, weights_[j].cell) : Index{-1});
  }
}

Real VonKarmanPlate::boundary_w(Index face, Real t) const {
  const PlateBoundary& bc = plate_.boundaries()[mesh_.face_patch(face)];
  if (bc.kind == PlateBoundary::Kind::Clamped || bc.kind == PlateBoundary::Kind::Free) return 0;
  return bc.at(mesh_.face_centroid(face), t)[0];
}

Mat3 VonKarmanPlate::membrane(const Mat3& eps) const {
  return 2 * mu_ * eps + lambda_ * eps.trace() * in_plane_identity();
}

VonKarmanPlate::FaceState VonKarmanPlate::face_state(Index k, Real t,
                                                     std::span<const Real> y) const {
  FaceState s{Vec3::Zero(), Mat3::Zero(), Mat3::Zero()};
  for (Index j = offset_[k]; j < offset_[k + 1]; ++j) {
    const GradientWeight& g = weights_[j];
    if (g.cell < 0) {
      s.gw += g.w * boundary_w(g.face, t);  // u = 0 there
      continue;
    }
    s.gw += g.w * y[3 * g.cell + PlateOperator::kW];
    s.gu += Vec3(y[in_plane_index(g.cell, 0)], y[in_plane_index(g.cell, 1)], 0) * g.u.transpose();
  }
  s.gw.z() = 0;
  Mat3 eps = 0.5 * (s.gu + s.gu.transpose()) + 0.5 * s.gw * s.gw.transpose();
  eps.row(2).setZero();
  eps.col(2).setZero();
  s.N = membrane(eps);
  return s;
}

void VonKarmanPlate::internal_residual(Real t, std::span<const Real> y, std::span<Real> r) {
  const Index nc = mesh_.n_cells();
  plate_.internal_residual(t, y.first(3 * nc), r.first(3 * nc));
  std::fill(r.begin() + 3 * nc, r.end(), 0.0);
  for (std::size_t k = 0; k < faces_.size(); ++k) {
    const Index f = faces_[k];
    const FaceState s = face_state(static_cast<Index>(k), t, y);
    const Vec3 Fu = s.N * mesh_.face_area(f);  // N S
    const Real Fw = s.gw.dot(Fu);              // (N grad w) . S, N symmetric
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    r[3 * p + PlateOperator::kW] -= Fw;
    r[in_plane_index(p, 0)] -= Fu.x();
    r[in_plane_index(p, 1)] -= Fu.y();
    if (n >= 0) {
      r[3 * n + PlateOperator::kW] += Fw;
      r[in_plane_index(n, 0)] += Fu.x();
      r[in_plane_index(n, 1)] += Fu.y();
    }
  }
}

void VonKarmanPlate::stiffness(Real t, std::span<const Real> y, std::span<Real> values) {
  const Index nc = mesh_.n_cells();
  std::fill(values.begin(), values.end(), 0.0);
  plate_.stiffness(t, y.first(3 * nc), plate_values_);
  for (std::size_t k = 0; k < plate_values_.size(); ++k)
    values[plate_position_[k]] += plate_values_[k];
  const Mat3 I = in_plane_identity();
  for (std::size_t k = 0; k < faces_.size(); ++k) {
    const Index f = faces_[k];
    const Vec3& S = mesh_.face_area(f);
    const FaceState s = face_state(static_cast<Index>(k), t, y);
    const Vec3 NS = s.N * S;
    for (Index j = offset_[k]; j < offset_[k + 1]; ++j) {
      const GradientWeight& g = weights_[j];
      if (g.cell < 0) continue;
      const Vec3 &a = g.w, &c = g.u;
      // Rows (F_w, F_u, F_v), columns (w, u, v) of the weight's cell.
      const Vec3 dFu_dw = mu_ * (a * s.gw.dot(S) + s.gw * a.dot(S)) + lambda_ * a.dot(s.gw) * S;
      const Mat3 dFu_du = mu_ * (c.dot(S) * I + c * S.transpose()) + lambda_ * S * c.transpose();
      Mat3 b;
      b(0, 0) = a.dot(NS) + s.gw.dot(dFu_dw);
      for (int i = 0; i < 2; ++i) {
        b(0, 1 + i) = s.gw.dot(dFu_du.col(i));
        b(1 + i, 0) = dFu_dw[i];
        for (int m = 0; m < 2; ++m) b(1 + i, 1 + m) = dFu_du(i, m);
      }
      for (int side = 0; side < 2; ++side) {
        const Index blk = block_of_weight_[2 * j + side];
        if (blk < 0) continue;
        const Real sign = side == 0 ? -1.0 : 1.0;
        const std::array<Index, 9>& pos = block_position_[blk];
        for (int e = 0; e < 9; ++e) values[pos[e]] += sign * b(e / 3, e % 3);
      }
    }
  }
}

std::vector<Real> VonKarmanPlate::mass_diagonal() const {
  std::vector<Real> m = plate_.mass_diagonal();
  m.resize(size());
  const Real rho_h = plate_.section().mass_per_area();
  for (Index c = 0; c < mesh_.n_cells(); ++c)
    m[in_plane_index(c, 0)] = m[in_plane_index(c, 1)] = rho_h * mesh_.cell_volume(c);
  return m;
}

std::vector<bool> VonKarmanPlate::quasi_static_components() const {
  std::vector<bool> mask = plate_.rotation_components();
  mask.resize(size(), true);
  return mask;
}

std::vector<Mat3> VonKarmanPlate::membrane_forces(Real t, std::span<const Real> y) const {
  std::vector<Mat3> N(mesh_.n_cells(), Mat3::Zero());
  std::vector<Real> weight(mesh_.n_cells(), 0.0);
  for (std::size_t k = 0; k < faces_.size(); ++k) {
    const Index f = faces_[k];
    const Mat3 Nf = face_state(static_cast<Index>(k), t, y).N;
    const Real area = mesh_.face_area(f).norm();
    for (Index c : {mesh_.face_owner(f), mesh_.face_neighbour(f)}) {
      if (c < 0) continue;
      N[c] += area * Nf;
      weight[c] += area;
    }
  }
  for (Index c = 0; c < mesh_.n_cells(); ++c)
    if (weight[c] > 0) N[c] /= weight[c];
  return N;
}

}  // namespace rfmems

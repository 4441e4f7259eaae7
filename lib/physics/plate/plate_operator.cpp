#include "physics/plate/plate_operator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "core/error.hpp"

namespace rfmems {

using Kind = PlateBoundary::Kind;

namespace {

// Maps a cell's unknowns (w, beta_x, beta_y) to its rotation vector (beta_x, beta_y, 0); the
// transpose sends a rotation-space vector to the two moment rows.
Mat3 rotation_selector() {
  Mat3 s = Mat3::Zero();
  s(0, 1) = 1;
  s(1, 2) = 1;
  return s;
}

Vec3 tangent(const Vec3& S) {
  const Vec3 n = S.normalized();
  return Vec3(-n.y(), n.x(), 0);
}

}  // namespace

PlateOperator::PlateOperator(const Mesh& mesh, const PlateSection& section,
                             std::vector<PlateBoundary> boundaries, ScalarField pressure,
                             int reconstruction_degree)
    : mesh_(mesh),
      section_(section),
      boundaries_(std::move(boundaries)),
      pressure_(std::move(pressure)),
      reconstruction_degree_(reconstruction_degree) {
  if (mesh_.dim() != 2) throw InputError("plate: the mid-surface mesh must be 2D");
  if (boundaries_.size() != mesh_.patches().size())
    throw InputError(fmt::format("plate: {} boundary conditions for {} patches", boundaries_.size(),
                                 mesh_.patches().size()));
  if (!(section_.E > 0) || !(section_.thickness > 0) || !(section_.nu > -1 && section_.nu < 0.5) ||
      !(section_.shear_factor > 0) || section_.rho < 0)
    throw InputError(fmt::format("plate: bad section (E = {}, nu = {}, h = {}, k = {}, rho = {})",
                                 section_.E, section_.nu, section_.thickness, section_.shear_factor,
                                 section_.rho));
  const Real D = section_.bending_stiffness();
  mu_ = 0.5 * D * (1 - section_.nu);
  lambda_ = D * section_.nu;
  kgh_ = section_.shear_stiffness();

  auto patch_bc = [this](Index f) -> const PlateBoundary& {
    return boundaries_[mesh_.face_patch(f)];
  };
  auto beta_point = [&](Index f) {
    return patch_bc(f).prescribes_rotation() ? BoundaryPoint::Value : BoundaryPoint::None;
  };
  auto w_point = [&](Index f) {
    return patch_bc(f).prescribes_deflection() ? BoundaryPoint::Value : BoundaryPoint::None;
  };
  beta_rec_ = std::make_unique<PolynomialReconstruction>(mesh_, beta_point, reconstruction_degree);
  // Where every edge prescribes both w and beta or neither (clamped and free edges), the two
  // reconstructions have the same stencils and weights: build one.
  bool same_points = true;
  for (Index f = 0; f < mesh_.n_faces() && same_points; ++f)
    same_points = !mesh_.is_boundary(f) || beta_point(f) == w_point(f);
  if (!same_points)
    own_w_rec_ = std::make_unique<PolynomialReconstruction>(mesh_, w_point, reconstruction_degree);
  w_rec_ = same_points ? beta_rec_.get() : own_w_rec_.get();

  // Face geometry: d = x_N - x_P (x_f - x_P on a boundary), S = alpha e + k (over-relaxed).
  const Index nf = mesh_.n_faces();
  face_e_.resize(nf);
  face_k_.resize(nf);
  face_d_.resize(nf);
  face_alpha_.resize(nf);
  face_eval_.resize(2 * nf);
  mid_eval_.resize(2 * nf);
  for (Index f = 0; f < nf; ++f) {
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    const Vec3& S = mesh_.face_area(f);
    const Vec3 d =
        (n >= 0 ? mesh_.cell_centroid(n) : mesh_.face_centroid(f)) - mesh_.cell_centroid(p);
    face_d_[f] = d.norm();
    face_e_[f] = d / face_d_[f];
    const Real eS = face_e_[f].dot(S);
    if (!(eS > 0))
      throw MeshError(fmt::format("plate: face {} is crossed backwards by its centroid line", f));
    face_alpha_[f] = S.squaredNorm() / eS;
    face_k_[f] = S - face_alpha_[f] * face_e_[f];
    const Vec3 mid = mesh_.cell_centroid(p) + 0.5 * d;
    face_eval_[2 * f] = make_eval(p, mesh_.face_centroid(f));
    mid_eval_[2 * f] = make_eval(p, mid);
    if (n >= 0) {
      face_eval_[2 * f + 1] = make_eval(n, mesh_.face_centroid(f));
      mid_eval_[2 * f + 1] = make_eval(n, mid);
    }
  }
  std::vector<Real> value;
  std::vector<Vec3> gradient;
  point_offset_.push_back(0);
  for (Index c = 0; c < mesh_.n_cells(); ++c) {
    beta_rec_->weights_at(c, mesh_.cell_centroid(c), value, gradient);
    centroid_gradient_.insert(centroid_gradient_.end(), gradient.begin(), gradient.end());
    point_offset_.push_back(static_cast<Index>(centroid_gradient_.size()));
  }
  point_delta_.resize(centroid_gradient_.size());

  // Cell shear strain: least-squares fit of gamma.a_f = g_f over the cell's faces, weighted by
  // face length; a_f = e_f where the face strain exists, the outward normal on load/free faces.
  for (Index c = 0; c < mesh_.n_cells(); ++c) {
    Mat3 M = Mat3::Zero();
    auto faces = mesh_.cell_faces(c);
    std::vector<Vec3> a(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const Index f = faces[i];
      const bool strain = !mesh_.is_boundary(f) || patch_bc(f).prescribes_deflection();
      a[i] = strain ? face_e_[f] : mesh_.face_area(f).normalized();
      M += mesh_.face_area(f).norm() * a[i] * a[i].transpose();
    }
    M(2, 2) = 1;
    if (M.topLeftCorner<2, 2>().determinant() <= 1e-12 * M.topLeftCorner<2, 2>().squaredNorm())
      throw MeshError(fmt::format("plate: cell {} cannot fit a shear strain from its faces", c));
    const Mat3 Minv = M.inverse();
    for (std::size_t i = 0; i < faces.size(); ++i)
      strain_weights_.push_back({faces[i], Minv * a[i] * mesh_.face_area(faces[i]).norm()});
    strain_offset_.push_back(static_cast<Index>(strain_weights_.size()));
  }

  build_membrane_weights();
  assemble_stiffness();
  homogeneous_data_ = !pressure_ && std::all_of(boundaries_.begin(), boundaries_.end(),
                                                [](const PlateBoundary& bc) { return !bc.value; });
}

void PlateOperator::build_membrane_weights() {
  membrane_offset_.assign(1, 0);
  membrane_weights_.clear();
  const Mat3 N0 = section_.membrane_force();
  if (N0.cwiseAbs().maxCoeff() == 0) return;
  std::vector<Real> value;
  std::vector<Vec3> gradient;
  // grad_factor grad p_c(x_f).a + value_factor p_c(x_f), p_c(x) = w_c + sum_j v_j (w_j - w_c),
  // grad p_c(x) = sum_j g_j (w_j - w_c): weight grad_factor g_j.a + value_factor v_j on w_j,
  // value_factor minus their sum on w_c.
  auto add_side = [&](Index c, const Vec3& x, Real grad_factor, Real value_factor, const Vec3& a) {
    w_rec_->weights_at(c, x, value, gradient);
    auto points = w_rec_->points(c);
    Real own = value_factor;
    for (std::size_t j = 0; j < points.size(); ++j) {
      const Real k = grad_factor * gradient[j].dot(a) + value_factor * value[j];
      own -= k;
      if (points[j].kind == StencilPoint::Kind::Cell)
        membrane_weights_.push_back({points[j].cell, -1, k});
      else if (points[j].kind == StencilPoint::Kind::BoundaryValue)
        membrane_weights_.push_back({-1, points[j].face, k});
      else
        throw std::logic_error("plate: mirror stencil points are not supported");
    }
    membrane_weights_.push_back({c, -1, own});
  };
  for (Index f = 0; f < mesh_.n_faces(); ++f) {
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    const Vec3& xf = mesh_.face_centroid(f);
    const Vec3 a = N0 * mesh_.face_area(f);
    const Real jump = face_e_[f].dot(a) / face_d_[f];
    if (n >= 0) {
      add_side(p, xf, 0.5, -jump, a);
      add_side(n, xf, 0.5, jump, a);
    } else if (boundaries_[mesh_.face_patch(f)].prescribes_deflection()) {
      add_side(p, xf, 1.0, -jump, a);
      membrane_weights_.push_back({-1, f, jump});
    }
    membrane_offset_.push_back(static_cast<Index>(membrane_weights_.size()));
  }
}

PlateOperator::Eval PlateOperator::make_eval(Index c, const Vec3& x) {
  beta_rec_->weights_at(c, x, value_scratch_, gradient_scratch_);
  Eval s;
  s.cell = c;
  s.begin = static_cast<Index>(eval_value_.size());
  eval_value_.insert(eval_value_.end(), value_scratch_.begin(), value_scratch_.end());
  eval_gradient_.insert(eval_gradient_.end(), gradient_scratch_.begin(), gradient_scratch_.end());
  s.end = static_cast<Index>(eval_value_.size());
  return s;
}

Vec3 PlateOperator::bc_value(const PlateBoundary& bc, const Vec3& x, Real t) const {
  return bc.kind == Kind::Clamped || bc.kind == Kind::Free ? Vec3::Zero() : bc.at(x, t);
}

void PlateOperator::cell_point_deltas(Index c, Real t, std::span<const Real> y) const {
  const Vec3 beta_c = beta(y, c);
  auto points = beta_rec_->points(c);
  Vec3* delta = point_delta_.data() + point_offset_[c];
  for (std::size_t j = 0; j < points.size(); ++j) {
    const StencilPoint& p = points[j];
    if (p.kind == StencilPoint::Kind::Cell) {
      delta[j] = beta(y, p.cell) - beta_c;
    } else if (p.kind == StencilPoint::Kind::BoundaryValue) {
      const Vec3 v =
          bc_value(boundaries_[mesh_.face_patch(p.face)], mesh_.face_centroid(p.face), t);
      delta[j] = Vec3(v[1], v[2], 0) - beta_c;
    } else {
      throw std::logic_error("plate: mirror stencil points are not supported");
    }
  }
}

void PlateOperator::compute_point_deltas(Real t, std::span<const Real> y) const {
  for (Index c = 0; c < mesh_.n_cells(); ++c) cell_point_deltas(c, t, y);
}

Vec3 PlateOperator::eval_value(const Eval& s, std::span<const Real> y) const {
  Vec3 v = beta(y, s.cell);
  const Vec3* delta = point_delta_.data() + point_offset_[s.cell];
  for (Index j = 0; j < s.end - s.begin; ++j) v += eval_value_[s.begin + j] * delta[j];
  return v;
}

Mat3 PlateOperator::eval_gradient(const Eval& s) const {
  Mat3 g = Mat3::Zero();
  const Vec3* delta = point_delta_.data() + point_offset_[s.cell];
  for (Index j = 0; j < s.end - s.begin; ++j)
    g += delta[j] * eval_gradient_[s.begin + j].transpose();
  return g;
}

Vec3 PlateOperator::face_moment(const Mat3& G, const Vec3& S) const {
  return mu_ * (G * S + G.transpose() * S) + lambda_ * G.trace() * S;
}

Mat3 PlateOperator::moment(const Mat3& G) const {
  Mat3 M = mu_ * (G + G.transpose()) + lambda_ * G.trace() * Mat3::Identity();
  M(2, 2) = 0;
  return M;
}

void PlateOperator::compute_strains(Real t, std::span<const Real> y, std::vector<Real>& gamma_e,
                                    std::vector<Vec3>& gamma_c) const {
  const Index nf = mesh_.n_faces();
  gamma_e.assign(nf, 0.0);
  for (Index f = 0; f < nf; ++f) {
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    const Vec3& e = face_e_[f];
    const Real d = face_d_[f];
    if (n >= 0) {
      const Vec3 mid =
          0.5 * (eval_value(mid_eval_[2 * f], y) + eval_value(mid_eval_[2 * f + 1], y));
      const Vec3 mean = (beta(y, p) + 4 * mid + beta(y, n)) / 6;
      gamma_e[f] = (y[3 * n] - y[3 * p]) / d + mean.dot(e);
      continue;
    }
    const PlateBoundary& bc = boundaries_[mesh_.face_patch(f)];
    if (!bc.prescribes_deflection()) continue;
    const Vec3 v = bc_value(bc, mesh_.face_centroid(f), t);
    Vec3 beta_b(v[1], v[2], 0);
    if (!bc.prescribes_rotation()) {
      const Vec3 extrapolated = eval_value(face_eval_[2 * f], y);
      if (bc.kind == Kind::SimplySupportedHard) {
        const Vec3 tt = tangent(mesh_.face_area(f));
        beta_b = tt * tt.dot(beta_b) + (extrapolated - tt * tt.dot(extrapolated));
      } else {
        beta_b = extrapolated;
      }
    }
    const Vec3 mean = (beta(y, p) + 4 * eval_value(mid_eval_[2 * f], y) + beta_b) / 6;
    gamma_e[f] = (v[0] - y[3 * p]) / d + mean.dot(e);
  }
  gamma_c.assign(mesh_.n_cells(), Vec3::Zero());
  for (Index c = 0; c < mesh_.n_cells(); ++c)
    for (Index k = strain_offset_[c]; k < strain_offset_[c + 1]; ++k) {
      const Index f = strain_weights_[k].face;
      Real g = gamma_e[f];
      if (mesh_.is_boundary(f)) {
        const PlateBoundary& bc = boundaries_[mesh_.face_patch(f)];
        if (!bc.prescribes_deflection()) g = bc_value(bc, mesh_.face_centroid(f), t)[0] / kgh_;
      }
      gamma_c[c] += g * strain_weights_[k].weight;
    }
}

void PlateOperator::internal_residual(Real t, std::span<const Real> y, std::span<Real> r) {
  if (!residual_by_stiffness_ || !homogeneous_data_ || !point_loads_.empty()) {
    reconstructed_residual(t, y, r);
    return;
  }
  // The operator is linear and R(t, 0) = 0, so R(t, y) = K y: one product with the assembled
  // stiffness instead of every reconstruction evaluated again.
  multiply(pattern_, stiffness_values_, y, r);
}

void PlateOperator::reconstructed_residual(Real t, std::span<const Real> y, std::span<Real> r) {
  std::fill(r.begin(), r.end(), 0.0);
  auto add_moment = [&](Index c, const Vec3& m) {
    r[3 * c + kBetaX] += m[0];
    r[3 * c + kBetaY] += m[1];
  };
  compute_point_deltas(t, y);
  compute_strains(t, y, gamma_e_, gamma_c_);
  const std::vector<Real>& gamma_e = gamma_e_;
  const std::vector<Vec3>& gamma_c = gamma_c_;

  for (Index f = 0; f < mesh_.n_faces(); ++f) {
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    const Vec3& S = mesh_.face_area(f);
    const Vec3& xf = mesh_.face_centroid(f);
    const Vec3& e = face_e_[f];
    const Real inv_d = 1.0 / face_d_[f];

    // Bending: face moment M_f S_f.
    const PlateBoundary* bc = n >= 0 ? nullptr : &boundaries_[mesh_.face_patch(f)];
    if (n >= 0) {
      const Eval& sp = face_eval_[2 * f];
      const Eval& sn = face_eval_[2 * f + 1];
      const Vec3 vp = eval_value(sp, y), vn = eval_value(sn, y);
      const Mat3 G =
          0.5 * (eval_gradient(sp) + eval_gradient(sn)) + (vn - vp) * inv_d * e.transpose();
      const Vec3 F = face_moment(G, S);
      add_moment(p, -F);
      add_moment(n, F);
    } else if (bc->prescribes_rotation() || bc->kind == Kind::SimplySupportedHard) {
      const Eval& sp = face_eval_[2 * f];
      const Vec3 v = bc_value(*bc, xf, t), vp = eval_value(sp, y);
      const Vec3 jump = Vec3(v[1], v[2], 0) - vp;
      if (bc->kind == Kind::SimplySupportedHard) {
        // Only the tangential rotation is held; only the twisting moment is a reaction.
        const Vec3 tt = tangent(S);
        const Mat3 T = tt * tt.transpose();
        add_moment(p,
                   -(T * face_moment(eval_gradient(sp) + (T * jump) * inv_d * e.transpose(), S)));
      } else {
        add_moment(p, -face_moment(eval_gradient(sp) + jump * inv_d * e.transpose(), S));
      }
    } else if (bc->kind == Kind::Load) {
      const Vec3 v = bc_value(*bc, xf, t);
      add_moment(p, -Vec3(v[1], v[2], 0) * S.norm());
    }

    // Transverse shear: face force Q_f.S_f, its moment about each centroid.
    Real FQ;
    if (n >= 0 || bc->prescribes_deflection()) {
      const Vec3 gamma_f = n >= 0 ? Vec3(0.5 * (gamma_c[p] + gamma_c[n])) : gamma_c[p];
      FQ = kgh_ * (face_alpha_[f] * gamma_e[f] + gamma_f.dot(face_k_[f]));
    } else {
      FQ = bc_value(*bc, xf, t)[0] * S.norm();
    }
    r[3 * p + kW] -= FQ;
    add_moment(p, (xf - mesh_.cell_centroid(p)) * FQ);
    if (n >= 0) {
      r[3 * n + kW] += FQ;
      add_moment(n, -(xf - mesh_.cell_centroid(n)) * FQ);
    }
  }
  // Membrane force of the residual stress on the slope.
  for (Index f = 0; f + 1 < static_cast<Index>(membrane_offset_.size()); ++f) {
    Real F = 0;
    for (Index k = membrane_offset_[f]; k < membrane_offset_[f + 1]; ++k) {
      const MembraneWeight& m = membrane_weights_[k];
      F += m.weight * (m.cell >= 0 ? y[3 * m.cell + kW]
                                   : bc_value(boundaries_[mesh_.face_patch(m.face)],
                                              mesh_.face_centroid(m.face), t)[0]);
    }
    r[3 * mesh_.face_owner(f) + kW] -= F;
    if (mesh_.face_neighbour(f) >= 0) r[3 * mesh_.face_neighbour(f) + kW] += F;
  }
  if (pressure_)
    for (Index c = 0; c < mesh_.n_cells(); ++c)
      r[3 * c + kW] -= pressure_(mesh_.cell_centroid(c), t) * mesh_.cell_volume(c);
  for (const auto& [c, load] : point_loads_) {
    const Vec3 f = load(t);
    for (int k = 0; k < 3; ++k) r[3 * c + k] -= f[k];
  }
}

void PlateOperator::add_point_load(Index cell, std::function<Vec3(Real t)> value) {
  if (cell < 0 || cell >= mesh_.n_cells())
    throw std::out_of_range(
        fmt::format("plate point load on cell {} of {}", cell, mesh_.n_cells()));
  point_loads_.emplace_back(cell, std::move(value));
}

// ---- Jacobian ------------------------------------------------------------------------------

void PlateOperator::value_terms(const Eval& s, Real factor, const Mat3& map,
                                std::vector<VectorTerm>& out) const {
  // p_c(x) = beta_c + sum_j v_j (beta_j - beta_c); boundary values are constants.
  const Mat3 sel = map * rotation_selector();
  auto points = beta_rec_->points(s.cell);
  Real sum = 0;
  for (Index j = 0; j < s.end - s.begin; ++j) {
    const Real v = eval_value_[s.begin + j];
    sum += v;
    if (points[j].kind == StencilPoint::Kind::Cell)
      out.push_back({points[j].cell, factor * v * sel});
  }
  out.push_back({s.cell, factor * (1 - sum) * sel});
}

void PlateOperator::bending_terms(const Eval& s, Real grad_factor, Real value_factor,
                                  std::vector<BendingTerm>& out) const {
  // grad_factor grad p(x) + value_factor p(x) e^T, p(x) = beta_c + sum_j (beta_j - beta_c) v_j,
  // grad p(x) = sum_j (beta_j - beta_c) g_j; merged per cell (boundary values are constants).
  auto term = [&](Index cell) -> BendingTerm& {
    for (BendingTerm& t : out)
      if (t.cell == cell) return t;
    return out.emplace_back(BendingTerm{cell, Vec3::Zero(), 0.0});
  };
  auto points = beta_rec_->points(s.cell);
  Vec3 grad_sum = Vec3::Zero();
  Real value_sum = 0;
  for (Index j = 0; j < s.end - s.begin; ++j) {
    const Vec3& g = eval_gradient_[s.begin + j];
    const Real v = eval_value_[s.begin + j];
    grad_sum += g;
    value_sum += v;
    if (points[j].kind == StencilPoint::Kind::Cell) {
      BendingTerm& t = term(points[j].cell);
      t.h += grad_factor * g;
      t.value += value_factor * v;
    }
  }
  BendingTerm& t = term(s.cell);
  t.h -= grad_factor * grad_sum;
  t.value += value_factor * (1 - value_sum);
}

void PlateOperator::strain_terms(Index f, std::vector<ScalarTerm>& out) const {
  const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
  const Vec3& e = face_e_[f];
  const Real inv_d = 1.0 / face_d_[f];
  const Mat3 sel = rotation_selector();
  std::vector<VectorTerm> mean;  // Simpson's mean of beta along the segment
  out.push_back({p, Vec3(-inv_d, 0, 0)});
  mean.push_back({p, sel / 6});
  if (n >= 0) {
    out.push_back({n, Vec3(inv_d, 0, 0)});
    mean.push_back({n, sel / 6});
    value_terms(mid_eval_[2 * f], 1.0 / 3, Mat3::Identity(), mean);
    value_terms(mid_eval_[2 * f + 1], 1.0 / 3, Mat3::Identity(), mean);
  } else {
    const PlateBoundary& bc = boundaries_[mesh_.face_patch(f)];
    value_terms(mid_eval_[2 * f], 4.0 / 6, Mat3::Identity(), mean);
    if (bc.kind == Kind::SimplySupportedHard) {
      const Vec3 tt = tangent(mesh_.face_area(f));
      value_terms(face_eval_[2 * f], 1.0 / 6, Mat3(Mat3::Identity() - tt * tt.transpose()), mean);
    } else if (bc.kind == Kind::SimplySupportedSoft) {
      value_terms(face_eval_[2 * f], 1.0 / 6, Mat3::Identity(), mean);
    }
  }
  for (const VectorTerm& m : mean) out.push_back({m.cell, m.T.transpose() * e});
}

void PlateOperator::assemble_stiffness() {
  const Index nc = mesh_.n_cells();
  // Block sums per row cell, (column cell, 3 x 3) with a linear search: a row couples ~25
  // cells, and a map or a global sort of the contributions costs more than the physics.
  std::vector<std::vector<std::pair<Index, Mat3>>> rows(nc);
  auto add = [&](Index row, Index col, const Mat3& b) {
    auto& r = rows[row];
    for (auto& [c, sum] : r)
      if (c == col) {
        sum += b;
        return;
      }
    r.emplace_back(col, b);
  };
  const Mat3 I = Mat3::Identity(), sel_t = rotation_selector().transpose();
  auto has_strain = [&](Index f) {
    return !mesh_.is_boundary(f) || boundaries_[mesh_.face_patch(f)].prescribes_deflection();
  };

  std::vector<BendingTerm> bterms;
  std::vector<ScalarTerm> sterms, tmp, merged;
  const Mat3 sel = rotation_selector();
  for (Index f = 0; f < mesh_.n_faces(); ++f) {
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    const Vec3& S = mesh_.face_area(f);
    const Vec3& e = face_e_[f];
    const Real inv_d = 1.0 / face_d_[f];

    // Bending: G_f = sum over cells of (sel y_cell) h^T + value (out sel y_cell) e^T.
    bterms.clear();
    Mat3 out = I;
    if (n >= 0) {
      bending_terms(face_eval_[2 * f], 0.5, -inv_d, bterms);
      bending_terms(face_eval_[2 * f + 1], 0.5, inv_d, bterms);
    } else {
      const PlateBoundary& bc = boundaries_[mesh_.face_patch(f)];
      if (bc.prescribes_rotation()) {
        bending_terms(face_eval_[2 * f], 1.0, -inv_d, bterms);
      } else if (bc.kind == Kind::SimplySupportedHard) {
        const Vec3 tt = tangent(S);
        out = tt * tt.transpose();
        bending_terms(face_eval_[2 * f], 1.0, -inv_d, bterms);
      }
    }
    // F = mu (G S + G^T S) + lambda tr(G) S with G = a h^T:
    // dF/da = mu (h.S) I + mu h S^T + lambda S h^T (linear in h).
    auto dF = [&](const Vec3& h) -> Mat3 {
      return mu_ * h.dot(S) * I + mu_ * h * S.transpose() + lambda_ * S * h.transpose();
    };
    if (!bterms.empty()) {
      const Mat3 row_map = sel_t * out;
      const Mat3 value_block = row_map * dF(e) * out * sel;
      for (const BendingTerm& t : bterms) {
        const Mat3 block = row_map * dF(t.h) * sel + t.value * value_block;
        add(p, t.cell, -block);
        if (n >= 0) add(n, t.cell, block);
      }
    }

    // Shear force Q_f.S_f = kGh (alpha gamma_e + gamma_f.k).
    if (!has_strain(f)) continue;
    sterms.clear();
    strain_terms(f, tmp);
    for (const ScalarTerm& s : tmp) sterms.push_back({s.cell, kgh_ * face_alpha_[f] * s.a});
    tmp.clear();
    if (face_k_[f].norm() > 1e-12 * S.norm()) {
      const Real share = n >= 0 ? 0.5 : 1.0;
      for (Index c : {p, n}) {
        if (c < 0) continue;
        for (Index k = strain_offset_[c]; k < strain_offset_[c + 1]; ++k) {
          const Index g = strain_weights_[k].face;
          if (!has_strain(g)) continue;  // prescribed shear: a constant
          const Real w = kgh_ * share * strain_weights_[k].weight.dot(face_k_[f]);
          strain_terms(g, tmp);
          for (const ScalarTerm& s : tmp) sterms.push_back({s.cell, w * s.a});
          tmp.clear();
        }
      }
    }
    const Vec3 lever_p = mesh_.face_centroid(f) - mesh_.cell_centroid(p);
    const Vec3 up(-1, lever_p.x(), lever_p.y());
    Vec3 un = Vec3::Zero();
    if (n >= 0) {
      const Vec3 lever_n = mesh_.face_centroid(f) - mesh_.cell_centroid(n);
      un = Vec3(1, -lever_n.x(), -lever_n.y());
    }
    merged.clear();  // one block per cell
    for (const ScalarTerm& s : sterms) {
      bool found = false;
      for (ScalarTerm& m : merged)
        if (m.cell == s.cell) {
          m.a += s.a;
          found = true;
          break;
        }
      if (!found) merged.push_back(s);
    }
    for (const ScalarTerm& s : merged) {
      add(p, s.cell, up * s.a.transpose());
      if (n >= 0) add(n, s.cell, un * s.a.transpose());
    }
  }

  for (Index f = 0; f + 1 < static_cast<Index>(membrane_offset_.size()); ++f) {
    const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
    for (Index k = membrane_offset_[f]; k < membrane_offset_[f + 1]; ++k) {
      const MembraneWeight& m = membrane_weights_[k];
      if (m.cell < 0) continue;  // prescribed w: a constant
      Mat3 block = Mat3::Zero();
      block(kW, kW) = m.weight;
      add(p, m.cell, -block);
      if (n >= 0) add(n, m.cell, block);
    }
  }

  // Keep the structurally nonzero scalar entries (the w row and column of a bending block are
  // zero; the operator is linear, so an entry that is zero here is zero for every y) and every
  // diagonal entry: 30 % fewer entries for KLU than full 3 x 3 blocks.
  pattern_ = CsrPattern{};
  stiffness_values_.clear();
  for (Index c = 0; c < nc; ++c) {
    auto& r = rows[c];
    bool has_diagonal_block = false;
    for (const auto& entry : r) has_diagonal_block |= entry.first == c;
    if (!has_diagonal_block) r.emplace_back(c, Mat3::Zero());
    std::sort(r.begin(), r.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (int i = 0; i < 3; ++i) {
      for (const auto& [col_cell, block] : r)
        for (int j = 0; j < 3; ++j) {
          if (block(i, j) == 0 && !(col_cell == c && i == j)) continue;
          pattern_.col_idx.push_back(3 * col_cell + j);
          stiffness_values_.push_back(block(i, j));
        }
      pattern_.row_ptr.push_back(pattern_.nnz());
    }
  }
}

void PlateOperator::stiffness(Real, std::span<const Real>, std::span<Real> values) {
  std::copy(stiffness_values_.begin(), stiffness_values_.end(), values.begin());
}

std::vector<Real> PlateOperator::mass_diagonal() const {
  std::vector<Real> m(size());
  for (Index c = 0; c < mesh_.n_cells(); ++c) {
    const Real A = mesh_.cell_volume(c);
    m[3 * c + kW] = section_.mass_per_area() * A;
    m[3 * c + kBetaX] = m[3 * c + kBetaY] = section_.rotary_inertia() * A;
  }
  return m;
}

std::vector<bool> PlateOperator::rotation_components() const {
  std::vector<bool> mask(size(), true);
  for (Index c = 0; c < mesh_.n_cells(); ++c) mask[3 * c + kW] = false;
  return mask;
}

// ---- post-processing -----------------------------------------------------------------------

std::vector<Mat3> PlateOperator::rotation_gradients(Real t, std::span<const Real> y) const {
  compute_point_deltas(t, y);
  std::vector<Mat3> grad(mesh_.n_cells(), Mat3::Zero());
  for (Index c = 0; c < mesh_.n_cells(); ++c)
    for (Index k = point_offset_[c]; k < point_offset_[c + 1]; ++k)
      grad[c] += point_delta_[k] * centroid_gradient_[k].transpose();
  return grad;
}

Mat3 PlateOperator::rotation_gradient_at(Index c, const Vec3& x, Real t,
                                         std::span<const Real> y) const {
  cell_point_deltas(c, t, y);
  std::vector<Real> value;
  std::vector<Vec3> gradient;
  beta_rec_->weights_at(c, x, value, gradient);
  Mat3 G = Mat3::Zero();
  const Vec3* delta = point_delta_.data() + point_offset_[c];
  for (std::size_t j = 0; j < gradient.size(); ++j) G += delta[j] * gradient[j].transpose();
  return G;
}

std::vector<Vec3> PlateOperator::shear_forces(Real t, std::span<const Real> y) const {
  compute_point_deltas(t, y);
  std::vector<Real> gamma_e;
  std::vector<Vec3> gamma_c;
  compute_strains(t, y, gamma_e, gamma_c);
  for (Vec3& g : gamma_c) g *= kgh_;
  return gamma_c;
}

Real PlateOperator::deflection_at(Index c, const Vec3& x, Real t, std::span<const Real> y) const {
  std::vector<DofWeight> terms;
  const Real constant = deflection_weights(c, x, t, terms);
  return weighted_sum(terms, y, constant);
}

Real PlateOperator::deflection_weights(Index c, const Vec3& x, Real t,
                                       std::vector<DofWeight>& terms) const {
  std::vector<Real> value;
  std::vector<Vec3> gradient;
  w_rec_->weights_at(c, x, value, gradient);
  auto points = w_rec_->points(c);
  terms.clear();
  Real constant = 0, own = 1;
  for (std::size_t j = 0; j < points.size(); ++j) {
    const StencilPoint& p = points[j];
    own -= value[j];
    if (p.kind == StencilPoint::Kind::Cell)
      terms.push_back({3 * p.cell + kW, value[j]});
    else
      constant += value[j] * bc_value(boundaries_[mesh_.face_patch(p.face)],
                                      mesh_.face_centroid(p.face), t)[0];
  }
  terms.push_back({3 * c + kW, own});
  return constant;
}

// ---- for operators built on the plate ------------------------------------------------------

std::vector<PlateOperator::CellWeight> PlateOperator::centroid_gradient_weights(Index c) const {
  // G_c = sum_j (beta_j - beta_c) g_j^T over the stencil points (boundary values constant).
  std::vector<CellWeight> out;
  auto points = beta_rec_->points(c);
  Vec3 sum = Vec3::Zero();
  for (std::size_t j = 0; j < points.size(); ++j) {
    const Vec3& g = centroid_gradient_[point_offset_[c] + j];
    sum += g;
    if (points[j].kind == StencilPoint::Kind::Cell) out.push_back({points[j].cell, g});
  }
  out.push_back({c, -sum});
  return out;
}

std::vector<PlateOperator::SlopeWeight> PlateOperator::face_slope_weights(Index f) const {
  // build_membrane_weights() with the force direction a = N0 S_f left out: the same face
  // gradient, interior grad w_f = (grad p_P + grad p_N)(x_f)/2 + (p_N - p_P)(x_f) e/|d|,
  // w given grad w_f = grad p_P(x_f) + (w_b - p_P(x_f)) e/|d|.
  std::vector<SlopeWeight> out;
  const Index p = mesh_.face_owner(f), n = mesh_.face_neighbour(f);
  if (n < 0 && !boundaries_[mesh_.face_patch(f)].prescribes_deflection()) return out;
  const Vec3& xf = mesh_.face_centroid(f);
  const Vec3 jump = face_e_[f] / face_d_[f];
  std::vector<Real> value;
  std::vector<Vec3> gradient;
  auto add_side = [&](Index c, Real grad_factor, const Vec3& value_factor) {
    w_rec_->weights_at(c, xf, value, gradient);
    auto points = w_rec_->points(c);
    Vec3 own = value_factor;
    for (std::size_t j = 0; j < points.size(); ++j) {
      const Vec3 k = grad_factor * gradient[j] + value_factor * value[j];
      own -= k;
      if (points[j].kind == StencilPoint::Kind::Cell)
        out.push_back({points[j].cell, -1, k});
      else if (points[j].kind == StencilPoint::Kind::BoundaryValue)
        out.push_back({-1, points[j].face, k});
      else
        throw std::logic_error("plate: mirror stencil points are not supported");
    }
    out.push_back({c, -1, own});
  };
  if (n >= 0) {
    add_side(p, 0.5, -jump);
    add_side(n, 0.5, jump);
  } else {
    add_side(p, 1.0, -jump);
    out.push_back({-1, f, jump});
  }
  return out;
}

std::vector<PlateOperator::CellBlock> PlateOperator::shear_force_weights(Index c) const {
  // gamma_c = sum_k weight_k g_f over the cell's faces, g_f = sum (a . y_cell) for a face with
  // a strain (strain_terms), a constant on load/free faces.
  std::vector<CellBlock> out;
  std::vector<ScalarTerm> terms;
  for (Index k = strain_offset_[c]; k < strain_offset_[c + 1]; ++k) {
    const Index f = strain_weights_[k].face;
    if (mesh_.is_boundary(f) && !boundaries_[mesh_.face_patch(f)].prescribes_deflection()) continue;
    terms.clear();
    strain_terms(f, terms);
    for (const ScalarTerm& s : terms) {
      const Mat3 block = kgh_ * strain_weights_[k].weight * s.a.transpose();
      auto it = std::find_if(out.begin(), out.end(),
                             [&](const CellBlock& b) { return b.cell == s.cell; });
      if (it == out.end())
        out.push_back({s.cell, block});
      else
        it->T += block;
    }
  }
  std::sort(out.begin(), out.end(),
            [](const CellBlock& a, const CellBlock& b) { return a.cell < b.cell; });
  return out;
}

}  // namespace rfmems

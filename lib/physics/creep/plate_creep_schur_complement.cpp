#include "physics/creep/plate_creep_schur_complement.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace rfmems {

namespace {
// kappa = (G_xx, G_yy, (G_xy + G_yx)/2) with G = sum_s beta_s w_s^T: the 3 x 2 map from
// (beta_x, beta_y) of cell s.
Eigen::Matrix<Real, 3, 2> curvature_map(const Vec3& w) {
  Eigen::Matrix<Real, 3, 2> L;
  L << w.x(), 0, 0, w.y(), 0.5 * w.y(), 0.5 * w.x();
  return L;
}
}  // namespace

PlateCreepSchurComplement::PlateCreepSchurComplement(const PlateCreepSystem& system)
    : system_(system) {
  const Index n_cells = system.n_cells(), ns = 3 * n_cells;
  const CsrPattern& structural = system.structural_pattern();  // K's (with the hold's stencils)
  const bool relaxes = system.relaxes_membrane();
  std::vector<std::vector<Index>> rows(ns);
  for (Index row = 0; row < ns; ++row)
    rows[row].assign(structural.col_idx.begin() + structural.row_ptr[row],
                     structural.col_idx.begin() + structural.row_ptr[row + 1]);
  // The relaxed membrane force: the y-y block of J (K and the relaxation's w-w part), and
  // P_m D^-1 G's w rows <- the rotations of the face cells' curvature stencils.
  const CsrPattern& full = system.pattern_;
  if (relaxes) {
    for (Index row = 0; row < ns; ++row)
      for (Index p = full.row_ptr[row]; p < full.row_ptr[row + 1]; ++p)
        if (full.col_idx[p] < ns) rows[row].push_back(full.col_idx[p]);
    for (const auto& m : system.membrane_faces_)
      for (Index row : {m.owner, m.neighbour})
        if (row >= 0)
          for (Index c : {m.owner, m.neighbour})
            if (c >= 0)
              for (const auto& w : system.curvature_weights_[c])
                for (int l = 1; l <= 2; ++l) rows[3 * row].push_back(3 * w.cell + l);
  }
  for (const auto& b : system.source_)
    for (const auto& w : system.curvature_weights_[b.col])
      for (int a = 1; a <= 2; ++a)
        for (int l = 1; l <= 2; ++l) rows[3 * b.row + a].push_back(3 * w.cell + l);
  for (auto& cols : rows) {
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
    pattern_.col_idx.insert(pattern_.col_idx.end(), cols.begin(), cols.end());
    pattern_.row_ptr.push_back(pattern_.nnz());
  }
  for (Index row = 0; row < ns; ++row)
    for (Index p = structural.row_ptr[row]; p < structural.row_ptr[row + 1]; ++p)
      plate_position_.push_back(pattern_.find(row, structural.col_idx[p]));
  if (relaxes) {
    for (Index row = 0; row < ns; ++row)
      for (Index p = full.row_ptr[row]; p < full.row_ptr[row + 1]; ++p)
        if (full.col_idx[p] < ns)
          tangent_position_.push_back({p, pattern_.find(row, full.col_idx[p])});
    for (const auto& m : system.membrane_faces_)
      for (Index c : {m.owner, m.neighbour})
        if (c >= 0)
          for (const auto& w : system.curvature_weights_[c])
            for (int l = 1; l <= 2; ++l) {
              membrane_position_.push_back(pattern_.find(3 * m.owner, 3 * w.cell + l));
              membrane_position_.push_back(
                  m.neighbour >= 0 ? pattern_.find(3 * m.neighbour, 3 * w.cell + l) : -1);
            }
    membrane_z_.resize(n_cells);
  }
  for (const auto& b : system.source_) {
    coupling_offset_.push_back(static_cast<Index>(coupling_position_.size()));
    for (const auto& w : system.curvature_weights_[b.col])
      for (int a = 1; a <= 2; ++a)
        for (int l = 1; l <= 2; ++l)
          coupling_position_.push_back(pattern_.find(3 * b.row + a, 3 * w.cell + l));
  }
  coupling_offset_.push_back(static_cast<Index>(coupling_position_.size()));
  values_.resize(pattern_.nnz());
  d_inverse_.resize(n_cells * system.n_points());
  e_.resize(d_inverse_.size());
  h_.resize(n_cells);
}

void PlateCreepSchurComplement::setup(Real t, Real c_j, std::span<const Real> state) {
  const PlateCreepSystem& sys = system_;
  const Index n_cells = sys.n_cells(), np = sys.n_points();
  const std::vector<Vec3> kappa = sys.curvatures(t, state);
  for (Index k = 0; k < n_cells; ++k) {
    Eigen::Matrix3d weighted = Eigen::Matrix3d::Zero();  // sum_i w_i z_i [E_ki]_{eps_p}
    Eigen::Matrix3d membrane = Eigen::Matrix3d::Zero();  // sum_i w_i [E_ki]_{eps_p}
    for (Index i = 0; i < np; ++i) {
      const auto d = sys.point_rate_jacobian(state, k, i, kappa[k], Vec3::Zero());
      Mat4 D = c_j * Mat4::Identity();
      D.leftCols<3>() -= d.d_eps_p;
      D.col(3) -= d.d_eps_eff;
      const Eigen::PartialPivLU<Mat4> lu(D);
      Mat4& d_inv = d_inverse_[k * np + i];
      d_inv = lu.inverse();
      if (!d_inv.allFinite()) throw RecoverableError("plate creep Schur complement: singular D");
      e_[k * np + i] = d_inv * d.d_kappa;
      weighted += (sys.quadrature_.weight[i] * sys.quadrature_.z[i]) * e_[k * np + i].topRows<3>();
      membrane += sys.quadrature_.weight[i] * e_[k * np + i].topRows<3>();
    }
    h_[k] = -sys.C_ * weighted;
    if (!membrane_z_.empty()) membrane_z_[k] = membrane;
  }
  // S = K - sum_{r,k} B_rk H_k L_k.
  std::fill(values_.begin(), values_.end(), 0.0);
  if (sys.relaxes_membrane()) {
    // K + the relaxation's w-w part: the y-y block of J at the state.
    tangent_.resize(sys.structural_nnz_);
    sys.structural_rows(t, state, tangent_);
    for (const auto& [from, to] : tangent_position_) values_[to] += tangent_[from];
    // - P_m D^-1 G: the w row of a face cell gets +-a_c (C^T b_f)^T Z_c L_c (see the header).
    state_.assign(state.begin(), state.end());
    t_ = t;
    const Index* position = membrane_position_.data();
    for (const auto& m : sys.membrane_faces_) {
      const Vec3 g = sys.face_slope(t, state, m);
      const Vec3& S = sys.plate_.mesh().face_area(m.face);
      const Vec3 b(g.x() * S.x(), g.y() * S.y(), g.x() * S.y() + g.y() * S.x());
      const Eigen::RowVector3d bc = (sys.C_.transpose() * b).transpose();
      const Real a = m.neighbour >= 0 ? 0.5 : 1.0;
      for (Index c : {m.owner, m.neighbour}) {
        if (c < 0) continue;
        const Eigen::RowVector3d v = a * bc * membrane_z_[c];
        for (const auto& w : sys.curvature_weights_[c]) {
          const Eigen::RowVector2d s = v * curvature_map(w.weight);
          for (int l = 0; l < 2; ++l) {
            values_[position[0]] += s[l];
            if (position[1] >= 0) values_[position[1]] -= s[l];
            position += 2;
          }
        }
      }
    }
  } else {
    sys.structural_tangent(state, tangent_);
    for (std::size_t p = 0; p < tangent_.size(); ++p) values_[plate_position_[p]] += tangent_[p];
  }
  for (std::size_t b = 0; b < sys.source_.size(); ++b) {
    const auto& block = sys.source_[b];
    const Eigen::Matrix<Real, 2, 3> bh = block.B * h_[block.col];
    const Index* position = coupling_position_.data() + coupling_offset_[b];
    for (const auto& w : sys.curvature_weights_[block.col]) {
      const Eigen::Matrix2d s = bh * curvature_map(w.weight);
      for (int a = 0; a < 2; ++a)
        for (int l = 0; l < 2; ++l) values_[*position++] -= s(a, l);
    }
  }
  if (lu_ && refactor_tolerance_ > 0 && lagged_factors_suffice()) return;
  if (lu_)
    lu_->refactor(values_);
  else
    lu_ = std::make_unique<KluFactorization>(pattern_, values_, KluOrdering::Colamd);
  factored_values_ = values_;
  ++factorizations_;
}

bool PlateCreepSchurComplement::lagged_factors_suffice() {
  // ||S_old^-1 (S - S_old)||, estimated by four power iterations from a fixed vector: the
  // lagged factors precondition S to I + S_old^-1 (S - S_old), which GMRES handles in a few
  // iterations while that is small. (A relative change of S's entries is no such measure:
  // near a singular S a change of 1e-3 in the entries can change S^-1 completely.)
  const Index n = pattern_.n_rows();
  std::vector<Real> x(n), y(n);
  for (Index k = 0; k < n; ++k) x[k] = (k % 3 == 0 ? 1.0 : -1.0) / std::sqrt(Real(n));
  Real estimate = 0;
  for (int iteration = 0; iteration < 4; ++iteration) {
    for (Index row = 0; row < n; ++row) {
      Real sum = 0;
      for (Index p = pattern_.row_ptr[row]; p < pattern_.row_ptr[row + 1]; ++p)
        sum += (values_[p] - factored_values_[p]) * x[pattern_.col_idx[p]];
      y[row] = sum;
    }
    lu_->solve(y);
    Real norm = 0;
    for (Real v : y) norm += v * v;
    norm = std::sqrt(norm);
    estimate = norm;  // x has unit norm
    if (!(norm > 0)) break;
    for (Index k = 0; k < n; ++k) x[k] = y[k] / norm;
  }
  last_lag_estimate_ = estimate;
  return estimate <= refactor_tolerance_;
}

void PlateCreepSchurComplement::solve(std::span<const Real> r, std::span<Real> z) {
  const PlateCreepSystem& sys = system_;
  const Index n_cells = sys.n_cells(), np = sys.n_points(), ns = sys.structural_size();
  // z_q' = D^-1 r_q, and the plastic moment of z_q' per cell (P z_q' = sum B_rk M(k)).
  moment_.assign(3 * n_cells, 0.0);
  for (Index k = 0; k < n_cells; ++k) {
    Eigen::Vector3d m = Eigen::Vector3d::Zero();
    for (Index i = 0; i < np; ++i) {
      const Index q = sys.creep_index(k, i, 0);
      const Eigen::Vector4d zq = d_inverse_[k * np + i] * Eigen::Vector4d::Map(r.data() + q);
      Eigen::Vector4d::Map(z.data() + q) = zq;
      m += (sys.quadrature_.weight[i] * sys.quadrature_.z[i]) * zq.head<3>();
    }
    Eigen::Vector3d::Map(moment_.data() + 3 * k) = sys.C_ * m;
  }
  // z_y = S^-1 (r_y - P z_q').
  rhs_.assign(r.begin(), r.begin() + ns);
  for (const auto& block : sys.source_) {
    const Eigen::Vector2d s = block.B * Eigen::Vector3d::Map(moment_.data() + 3 * block.col);
    rhs_[3 * block.row + 1] -= s[0];
    rhs_[3 * block.row + 2] -= s[1];
  }
  if (sys.relaxes_membrane()) {  // - P_m z_q': the relaxation applied to z_q' at the state
    relaxation_.assign(ns, 0.0);
    sys.add_membrane_relaxation(t_, state_, z, relaxation_);
    for (Index k = 0; k < ns; ++k) rhs_[k] -= relaxation_[k];
  }
  lu_->solve(rhs_);
  std::copy(rhs_.begin(), rhs_.end(), z.begin());
  // z_q = z_q' - D^-1 G z_y = z_q' + E (L z_y).
  for (Index k = 0; k < n_cells; ++k) {
    Eigen::Vector3d dk = Eigen::Vector3d::Zero();
    for (const auto& w : sys.curvature_weights_[k])
      dk += curvature_map(w.weight) * Eigen::Vector2d(rhs_[3 * w.cell + 1], rhs_[3 * w.cell + 2]);
    for (Index i = 0; i < np; ++i)
      Eigen::Vector4d::Map(z.data() + sys.creep_index(k, i, 0)) += e_[k * np + i] * dk;
  }
}

}  // namespace rfmems

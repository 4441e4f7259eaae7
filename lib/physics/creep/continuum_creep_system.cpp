#include "physics/creep/continuum_creep_system.hpp"

#include <algorithm>
#include <map>

#include "core/error.hpp"

namespace rfmems {

using Kind = ElasticityBoundary::Kind;

namespace {
// Voigt order of symmetric tensors here: xx, yy, zz, xy, yz, xz.
constexpr std::pair<int, int> kVoigt[6] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
}  // namespace

ContinuumCreepSystem::ContinuumCreepSystem(ElasticityOperator& elasticity, const CreepLaw& law,
                                           int source_reconstruction_degree)
    : elasticity_(elasticity),
      law_(law),
      n_cells_(elasticity.mesh().n_cells()),
      dim_(elasticity.dim()),
      hypothesis_(elasticity.dim() == 3 ? Hypothesis::ThreeD
                  : elasticity.material().hypothesis == Hypothesis::PlaneStress
                      ? Hypothesis::PlaneStress
                      : Hypothesis::PlaneStrain),
      mu_(elasticity.material().mu()),
      lambda_(elasticity.material().lambda()) {
  law_.validate();
  switch (hypothesis_) {
    case Hypothesis::PlaneStress:
      components_ = {{0, 0}, {1, 1}, {0, 1}};
      break;
    case Hypothesis::PlaneStrain:
      components_ = {{0, 0}, {1, 1}, {0, 1}, {2, 2}};
      break;
    case Hypothesis::ThreeD:
      components_.assign(std::begin(kVoigt), std::end(kVoigt));
      break;
  }
  n_plastic_ = static_cast<int>(components_.size());
  plastic_stress_.setZero();
  for (int k = 0; k < n_plastic_; ++k)
    plastic_stress_.col(k) = voigt(hooke(unit_tensor(components_[k].first, components_[k].second)));

  sigma0_ = elasticity.material().residual_stress;
  relaxes_prestress_ = sigma0_.cwiseAbs().maxCoeff() > 0;
  for (int k = 0; k < n_plastic_; ++k)
    component_stress_.push_back(hooke(unit_tensor(components_[k].first, components_[k].second)));

  build_plastic_source(source_reconstruction_degree);
  build_stress_weights();
  build_prestress_faces();
  build_pattern();
  set_linear_solver(LinearSolver::Krylov);
}

Mat3 ContinuumCreepSystem::unit_tensor(int i, int j) {
  Mat3 m = Mat3::Zero();
  m(i, j) = m(j, i) = 1;
  return m;
}

ContinuumCreepSystem::Vec6 ContinuumCreepSystem::voigt(const Mat3& s) {
  Vec6 v;
  for (int m = 0; m < 6; ++m) v[m] = s(kVoigt[m].first, kVoigt[m].second);
  return v;
}

Mat3 ContinuumCreepSystem::hooke(const Mat3& strain) const {
  Mat3 identity = Mat3::Identity();
  if (hypothesis_ == Hypothesis::PlaneStress) identity(2, 2) = 0;
  return 2 * mu_ * strain + lambda_ * strain.trace() * identity;
}

void ContinuumCreepSystem::build_plastic_source(int degree) {
  const Mesh& mesh = elasticity_.mesh();
  const auto& boundaries = elasticity_.boundaries();
  std::unique_ptr<PolynomialReconstruction> rec;
  if (degree > 0)
    rec = std::make_unique<PolynomialReconstruction>(
        mesh, [](Index) { return BoundaryPoint::None; }, degree);
  std::map<std::pair<Index, Index>, Eigen::Matrix<Real, 3, 6>> blocks;
  std::vector<std::pair<Index, Real>> weights;
  // sigma_p at x from cell's reconstruction: sigma_p,cell + sum_j v_j (sigma_p,j - sigma_p,cell).
  auto add_weights = [&](Index cell, const Vec3& x, Real factor) {
    if (!rec) {  // degree 0: the cell value itself
      weights.push_back({cell, factor});
      return;
    }
    rec->append_value_weights(cell, x, factor, weights);
  };
  for (Index f = 0; f < mesh.n_faces(); ++f) {
    const Index p = mesh.face_owner(f), n = mesh.face_neighbour(f);
    const Vec3& S = mesh.face_area(f);
    Mat3 projection = Mat3::Identity();
    if (n < 0) {
      const Kind kind = boundaries[mesh.face_patch(f)].kind;
      if (kind == Kind::Traction) continue;  // the total traction is prescribed
      if (kind == Kind::Symmetry) {
        const Vec3 u = S.normalized();
        projection = u * u.transpose();  // only the normal force is transmitted
      }
    }
    weights.clear();
    if (n >= 0) {
      add_weights(p, mesh.face_centroid(f), 0.5);
      add_weights(n, mesh.face_centroid(f), 0.5);
    } else {
      add_weights(p, mesh.face_centroid(f), 1.0);
    }
    Eigen::Matrix<Real, 3, 6> traction = Eigen::Matrix<Real, 3, 6>::Zero();  // P sigma_p S
    for (int k = 0; k < n_plastic_; ++k)
      traction.col(k) =
          projection * hooke(unit_tensor(components_[k].first, components_[k].second)) * S;
    for (const auto& [k, w] : weights) {
      auto add = [&](Index row, Real sign) {
        auto [it, inserted] = blocks.try_emplace({row, k}, sign * w * traction);
        if (!inserted) it->second += sign * w * traction;
      };
      add(p, 1.0);
      if (n >= 0) add(n, -1.0);
    }
  }
  source_.clear();
  for (const auto& [key, B] : blocks) source_.push_back({key.first, key.second, B});
}

void ContinuumCreepSystem::build_prestress_faces() {
  prestress_faces_.clear();
  gradient_terms_.clear();
  if (!relaxes_prestress_) return;
  const Mesh& mesh = elasticity_.mesh();
  for (Index f = 0; f < mesh.n_faces(); ++f) {
    const Index n = mesh.face_neighbour(f);
    Mat3 projection = Mat3::Identity();
    if (n < 0) {
      const Kind kind = elasticity_.boundaries()[mesh.face_patch(f)].kind;
      if (kind == Kind::Traction) continue;  // no face gradient: the traction is prescribed
      if (kind == Kind::Symmetry) {
        const Vec3 u = mesh.face_area(f).normalized();
        projection = u * u.transpose();
      }
    }
    const std::vector<ElasticityOperator::GradientTerm> terms = elasticity_.face_gradient_terms(f);
    const Index begin = static_cast<Index>(gradient_terms_.size());
    gradient_terms_.insert(gradient_terms_.end(), terms.begin(), terms.end());
    prestress_faces_.push_back(
        {f, mesh.face_owner(f), n, projection, begin, static_cast<Index>(gradient_terms_.size())});
  }
}

void ContinuumCreepSystem::build_stress_weights() {
  stress_weights_.assign(n_cells_, {});
  for (Index c = 0; c < n_cells_; ++c) {
    std::map<Index, Eigen::Matrix<Real, 6, 3>> merged;
    for (const auto& term : elasticity_.centroid_gradient_terms(c)) {
      auto [it, inserted] = merged.try_emplace(term.cell, Eigen::Matrix<Real, 6, 3>::Zero());
      for (int a = 0; a < dim_; ++a) {
        const Mat3 dG = term.map.col(a) * term.weight.transpose();
        it->second.col(a) += voigt(hooke(0.5 * (dG + dG.transpose())));
      }
    }
    for (const auto& [cell, S] : merged) stress_weights_[c].push_back({cell, S});
  }
}

void ContinuumCreepSystem::build_pattern() {
  const CsrPattern& stiffness = elasticity_.stiffness_pattern();
  const Index ns = structural_size();
  std::vector<std::vector<Index>> source_cols(n_cells_);
  for (const SourceBlock& b : source_) source_cols[b.row].push_back(b.col);
  // The relaxed prestress: u rows of each face cell <- u of the face gradient's terms and the
  // plastic strains of the face's cells.
  std::vector<std::vector<Index>> prestress_cols(n_cells_);
  for (const PrestressFace& pf : prestress_faces_)
    for (Index row : {pf.owner, pf.neighbour}) {
      if (row < 0) continue;
      for (Index k = pf.begin; k < pf.end; ++k)
        for (int b = 0; b < dim_; ++b)
          prestress_cols[row].push_back(dim_ * gradient_terms_[k].cell + b);
      for (Index c : {pf.owner, pf.neighbour})
        if (c >= 0)
          for (int j = 0; j < n_plastic_; ++j) prestress_cols[row].push_back(creep_index(c, j));
    }

  pattern_ = CsrPattern{};
  std::vector<Index> cols;
  for (Index row = 0; row < ns; ++row) {
    cols.assign(stiffness.col_idx.begin() + stiffness.row_ptr[row],
                stiffness.col_idx.begin() + stiffness.row_ptr[row + 1]);
    for (Index k : source_cols[row / dim_])
      for (int j = 0; j < n_plastic_; ++j) cols.push_back(creep_index(k, j));
    cols.insert(cols.end(), prestress_cols[row / dim_].begin(), prestress_cols[row / dim_].end());
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
    pattern_.col_idx.insert(pattern_.col_idx.end(), cols.begin(), cols.end());
    pattern_.row_ptr.push_back(pattern_.nnz());
  }
  structural_nnz_ = pattern_.nnz();
  // The relaxation's value positions, in structural_rows' order.
  relaxation_position_.clear();
  for (const PrestressFace& pf : prestress_faces_) {
    auto add = [&](int a, Index col) {
      relaxation_position_.push_back(pattern_.find(dim_ * pf.owner + a, col));
      relaxation_position_.push_back(pf.neighbour >= 0 ? pattern_.find(dim_ * pf.neighbour + a, col)
                                                       : -1);
    };
    for (Index k = pf.begin; k < pf.end; ++k)
      for (int a = 0; a < dim_; ++a)
        for (int b = 0; b < dim_; ++b) add(a, dim_ * gradient_terms_[k].cell + b);
    for (Index c : {pf.owner, pf.neighbour})
      if (c >= 0)
        for (int j = 0; j < n_plastic_; ++j)
          for (int a = 0; a < dim_; ++a) add(a, creep_index(c, j));
  }
  // The u-u block (equilibrate's tangent with the relaxation).
  relaxed_block_.set_pattern(pattern_, relaxes_prestress_ ? ns : 0);
  for (Index c = 0; c < n_cells_; ++c)
    for (int j = 0; j < n_components(); ++j) {
      for (const StressWeight& w : stress_weights_[c])
        for (int a = 0; a < dim_; ++a) pattern_.col_idx.push_back(dim_ * w.cell + a);
      for (int l = 0; l < n_components(); ++l) pattern_.col_idx.push_back(creep_index(c, l));
      pattern_.row_ptr.push_back(pattern_.nnz());
    }

  // The constant u rows: elastic stiffness and dR_u/dq = B.
  structural_values_.assign(structural_nnz_, 0.0);
  const std::vector<Real> zero(elasticity_.size(), 0.0);
  stiffness_values_.resize(stiffness.nnz());
  elasticity_.stiffness(0, zero, stiffness_values_);
  for (Index row = 0; row < ns; ++row)
    for (Index p = stiffness.row_ptr[row]; p < stiffness.row_ptr[row + 1]; ++p)
      structural_values_[pattern_.find(row, stiffness.col_idx[p])] += stiffness_values_[p];
  for (const SourceBlock& b : source_)
    for (int a = 0; a < dim_; ++a)
      for (int j = 0; j < n_plastic_; ++j)
        structural_values_[pattern_.find(dim_ * b.row + a, creep_index(b.col, j))] += b.B(a, j);
}

void ContinuumCreepSystem::set_creep_stress_mask(const std::array<bool, 6>& keep) {
  for (int m = 0; m < 6; ++m) creep_stress_mask_[m] = keep[m] ? 1.0 : 0.0;
}

Mat3 ContinuumCreepSystem::creep_stress(const Mat3& sigma) const {
  Mat3 s = sigma;
  for (int m = 0; m < 6; ++m)
    if (creep_stress_mask_[m] == 0) {
      const auto [i, j] = kVoigt[m];
      s(i, j) = s(j, i) = 0;
    }
  return s;
}

std::vector<Real> ContinuumCreepSystem::differential_components() const {
  std::vector<Real> id(size(), 1.0);
  std::fill(id.begin(), id.begin() + structural_size(), 0.0);
  return id;
}

Mat3 ContinuumCreepSystem::stress_plastic_strain(std::span<const Real> state, Index c) const {
  Mat3 e = Mat3::Zero();
  for (int k = 0; k < n_plastic_; ++k) {
    const auto [i, j] = components_[k];
    e(i, j) = e(j, i) = state[creep_index(c, k)];
  }
  return e;
}

Mat3 ContinuumCreepSystem::plastic_strain(std::span<const Real> state, Index c) const {
  Mat3 e = stress_plastic_strain(state, c);
  if (hypothesis_ == Hypothesis::PlaneStress) e(2, 2) = -(e(0, 0) + e(1, 1));
  return e;
}

Mat3 ContinuumCreepSystem::cell_stress(std::span<const Real> state, Index c, const Mat3& G) const {
  const Mat3 s = hooke(0.5 * (G + G.transpose()) - stress_plastic_strain(state, c));
  return relaxes_prestress_ ? Mat3(sigma0_ + s) : s;
}

std::vector<Mat3> ContinuumCreepSystem::prestresses(std::span<const Real> state) const {
  std::vector<Mat3> s(n_cells_);
  for (Index c = 0; c < n_cells_; ++c) s[c] = sigma0_ - hooke(stress_plastic_strain(state, c));
  return s;
}

void ContinuumCreepSystem::add_prestress_relaxation(Real t, std::span<const Real> gradient_state,
                                                    std::span<const Real> strain_state,
                                                    std::span<Real> r) const {
  if (prestress_faces_.empty()) return;
  const std::vector<Mat3> G =
      elasticity_.face_gradients(t, gradient_state.first(structural_size()));
  std::vector<Mat3> sp(n_cells_);
  for (Index c = 0; c < n_cells_; ++c) sp[c] = hooke(stress_plastic_strain(strain_state, c));
  const Mesh& mesh = elasticity_.mesh();
  for (const PrestressFace& pf : prestress_faces_) {
    const Mat3 dsigma =
        pf.neighbour >= 0 ? Mat3(-0.5 * (sp[pf.owner] + sp[pf.neighbour])) : Mat3(-sp[pf.owner]);
    const Vec3 F = pf.projection * (G[pf.face] * (dsigma * mesh.face_area(pf.face)));
    for (int a = 0; a < dim_; ++a) {
      r[dim_ * pf.owner + a] -= F[a];
      if (pf.neighbour >= 0) r[dim_ * pf.neighbour + a] += F[a];
    }
  }
}

void ContinuumCreepSystem::structural_rows(Real t, std::span<const Real> y,
                                           std::span<Real> values) const {
  std::copy(structural_values_.begin(), structural_values_.end(), values.begin());
  if (prestress_faces_.empty()) return;
  // F = P G_f (dsigma_f S_f): dF/du_k = (h_k . dsigma_f S_f) P T_k,
  // dF/d eps_p,j(c) = -a_c P G_f (C E_j S_f); row owner -F, row neighbour +F.
  const std::vector<Mat3> G = elasticity_.face_gradients(t, y.first(structural_size()));
  std::vector<Mat3> sp(n_cells_);
  for (Index c = 0; c < n_cells_; ++c) sp[c] = hooke(stress_plastic_strain(y, c));
  const Mesh& mesh = elasticity_.mesh();
  const Index* position = relaxation_position_.data();
  auto add = [&](Real d) {
    values[position[0]] -= d;
    if (position[1] >= 0) values[position[1]] += d;
    position += 2;
  };
  for (const PrestressFace& pf : prestress_faces_) {
    const Real a_c = pf.neighbour >= 0 ? 0.5 : 1.0;
    const Mat3 dsigma =
        pf.neighbour >= 0 ? Mat3(-0.5 * (sp[pf.owner] + sp[pf.neighbour])) : Mat3(-sp[pf.owner]);
    const Vec3& S = mesh.face_area(pf.face);
    const Vec3 dsigma_S = dsigma * S;
    for (Index k = pf.begin; k < pf.end; ++k) {
      const ElasticityOperator::GradientTerm& term = gradient_terms_[k];
      const Mat3 block = term.weight.dot(dsigma_S) * pf.projection * term.map;
      for (int a = 0; a < dim_; ++a)
        for (int b = 0; b < dim_; ++b) add(block(a, b));
    }
    for (Index c : {pf.owner, pf.neighbour})
      if (c >= 0)
        for (int j = 0; j < n_plastic_; ++j) {
          const Vec3 d = -a_c * (pf.projection * (G[pf.face] * (component_stress_[j] * S)));
          for (int a = 0; a < dim_; ++a) add(d[a]);
        }
  }
}

SparseLu& ContinuumCreepSystem::structural_factors(Real t, std::span<const Real> state) {
  if (relaxes_prestress_) {
    jacobian_scratch_.resize(structural_nnz_);
    structural_rows(t, state, jacobian_scratch_);
    return relaxed_block_.factorize(jacobian_scratch_);
  }
  if (!stiffness_lu_)
    stiffness_lu_ = std::make_unique<SparseLu>(elasticity_.stiffness_pattern(), stiffness_values_);
  return *stiffness_lu_;
}

void ContinuumCreepSystem::set_linear_solver(LinearSolver solver) {
  linear_solver_ = solver;
  preconditioner_.reset();
  if (solver != LinearSolver::Direct)
    preconditioner_ =
        std::make_unique<ContinuumCreepPreconditioner>(pattern_, structural_size(), n_components());
}

void ContinuumCreepSystem::preconditioner_setup(Real t, Real c_j, std::span<const Real> y,
                                                std::span<const Real> yp) {
  jacobian(t, c_j, y, yp, preconditioner_->jacobian_values());
  preconditioner_->setup();
  tangent_factors_ = &structural_factors(t, y);
}

void ContinuumCreepSystem::preconditioner_solve(std::span<const Real> r, std::span<Real> z) {
  preconditioner_->solve(r, z, [this](std::span<Real> x) { tangent_factors_->solve(x); });
}

std::vector<Mat3> ContinuumCreepSystem::cell_stresses(Real t, std::span<const Real> state) const {
  const std::vector<Mat3> G = elasticity_.cell_gradients(t, state.first(structural_size()));
  std::vector<Mat3> s(n_cells_);
  for (Index c = 0; c < n_cells_; ++c) s[c] = cell_stress(state, c, G[c]);
  return s;
}

ContinuumCreepSystem::RateVector ContinuumCreepSystem::rate_vector(const CreepRate& r) const {
  RateVector v(n_components());
  for (int k = 0; k < n_plastic_; ++k)
    v[k] = r.strain_rate(components_[k].first, components_[k].second);
  v[n_plastic_] = r.effective_rate;
  return v;
}

void ContinuumCreepSystem::rate_derivatives(const Mat3& sigma, Real eps_eff, RateJacobian& d_sigma,
                                            RateVector& d_eps_eff) const {
  d_sigma.resize(n_components(), 6);
  for (int m = 0; m < 6; ++m)
    d_sigma.col(m) = rate_vector(law_.rate_stress_derivative(
        sigma, eps_eff, unit_tensor(kVoigt[m].first, kVoigt[m].second)));
  d_eps_eff = rate_vector(law_.rate_hardening_derivative(sigma, eps_eff));
}

void ContinuumCreepSystem::add_plastic_source(std::span<const Real> state,
                                              std::span<Real> r) const {
  Eigen::Matrix<Real, 6, 1> q;
  for (const SourceBlock& b : source_) {
    q.setZero();
    for (int j = 0; j < n_plastic_; ++j) q[j] = state[creep_index(b.col, j)];
    const Vec3 s = b.B * q;
    for (int a = 0; a < dim_; ++a) r[dim_ * b.row + a] += s[a];
  }
}

void ContinuumCreepSystem::creep_rates(Real t, std::span<const Real> state, std::span<Real> rates) {
  const std::vector<Mat3> G = elasticity_.cell_gradients(t, state.first(structural_size()));
  const Index ns = structural_size();
  for (Index c = 0; c < n_cells_; ++c) {
    const Index q = creep_index(c, 0);
    const RateVector g =
        rate_vector(law_.rate(creep_stress(cell_stress(state, c, G[c])), state[q + n_plastic_]));
    for (int j = 0; j < n_components(); ++j) rates[q - ns + j] = g[j];
  }
}

void ContinuumCreepSystem::residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                                    std::span<Real> r) {
  const Index ns = structural_size();
  elasticity_.internal_residual(t, y.first(ns), r.first(ns));
  add_plastic_source(y, r);
  add_prestress_relaxation(t, y, y, r);
  std::span<Real> rq = r.subspan(ns);
  creep_rates(t, y, rq);
  for (Index k = 0; k < size() - ns; ++k) rq[k] = yp[ns + k] - rq[k];
}

void ContinuumCreepSystem::jacobian(Real t, Real c_j, std::span<const Real> y,
                                    std::span<const Real>, std::span<Real> values) {
  structural_rows(t, y, values);
  const std::vector<Mat3> G = elasticity_.cell_gradients(t, y.first(structural_size()));
  RateJacobian d_sigma;
  RateVector d_eps_eff;
  const int nc = n_components();
  for (Index c = 0; c < n_cells_; ++c) {
    const Index q = creep_index(c, 0);
    rate_derivatives(creep_stress(cell_stress(y, c, G[c])), y[q + n_plastic_], d_sigma, d_eps_eff);
    for (int m = 0; m < 6; ++m) d_sigma.col(m) *= creep_stress_mask_[m];
    // dsigma/d eps_p = -plastic_stress_, so dF_q/d eps_p = c_j I + d_sigma plastic_stress_.
    const RateJacobian d_plastic = d_sigma * plastic_stress_.leftCols(n_plastic_);
    for (int j = 0; j < nc; ++j) {
      Real* row = values.data() + pattern_.row_ptr[q + j];
      for (const StressWeight& w : stress_weights_[c]) {
        const Eigen::Matrix<Real, 1, 3> d = -d_sigma.row(j) * w.S;
        for (int a = 0; a < dim_; ++a) *row++ = d[a];
      }
      for (int l = 0; l < n_plastic_; ++l) *row++ = (j == l ? c_j : 0.0) + d_plastic(j, l);
      *row++ = (j == n_plastic_ ? c_j : 0.0) - d_eps_eff[j];
    }
  }
}

void ContinuumCreepSystem::equilibrate(Real t, std::span<Real> state) {
  // The elastic operator is linear, and for fixed q so is the relaxation term: one Newton step
  // on the factorised tangent is exact.
  const Index ns = structural_size();
  scratch_.assign(ns, 0.0);
  elasticity_.internal_residual(t, state.first(ns), scratch_);
  add_plastic_source(state, scratch_);
  add_prestress_relaxation(t, state, state, scratch_);
  structural_factors(t, state).solve_refined(scratch_);
  for (Index k = 0; k < ns; ++k) state[k] -= scratch_[k];
}

void ContinuumCreepSystem::initial_state(Real t, std::vector<Real>& state,
                                         std::vector<Real>& state_dot) {
  const Index ns = structural_size();
  if (static_cast<Index>(state.size()) != size()) state.assign(size(), 0.0);
  equilibrate(t, state);
  state_dot.assign(size(), 0.0);
  creep_rates(t, state, std::span<Real>(state_dot).subspan(ns));
  // T u' + (dR/dq) q' = 0 (T: the tangent), the sources linear in q (the relaxation at the
  // state's face gradients): apply them to q'.
  scratch_.assign(ns, 0.0);
  add_plastic_source(state_dot, scratch_);
  add_prestress_relaxation(t, state, state_dot, scratch_);
  structural_factors(t, state).solve_refined(scratch_);
  for (Index k = 0; k < ns; ++k) state_dot[k] = -scratch_[k];
}

}  // namespace rfmems

#include "solvers/distributed_linearization.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace rfmems {

DistributedLinearization::DistributedLinearization(DistributedSystem& system,
                                                   bool with_derivative_terms,
                                                   Preconditioner preconditioner)
    : system_(system),
      with_derivative_terms_(with_derivative_terms),
      schwarz_(preconditioner == Preconditioner::RestrictedAdditiveSchwarz),
      multigrid_(preconditioner == Preconditioner::AlgebraicMultigrid ||
                 preconditioner == Preconditioner::SchurAlgebraicMultigrid) {
  if (schwarz_ && (with_derivative_terms_ || !system_.overlap_pattern()))
    throw SolverError("additive Schwarz: the system has no overlapping static subdomain matrix");
  if (preconditioner == Preconditioner::AlgebraicMultigrid && with_derivative_terms_)
    throw SolverError("algebraic multigrid: a transient needs its Schur variant");
  if (schwarz_) overlap_values_.resize(system_.overlap_pattern()->nnz());
  if (preconditioner == Preconditioner::SchurAdditiveSchwarz ||
      preconditioner == Preconditioner::SchurAlgebraicMultigrid) {
    structure_ = system_.second_order();
    if (!structure_ || !with_derivative_terms_ ||
        (!multigrid_ && !structure_->overlap_stiffness_pattern()))
      throw SolverError("Schur preconditioner: the system has no structural matrix");
    // The Schur complement's rows: all local rows (Schwarz) or the owned ones (multigrid).
    const CsrPattern& p =
        multigrid_ ? structure_->stiffness_pattern() : *structure_->overlap_stiffness_pattern();
    (multigrid_ ? owned_stiffness_ : overlap_values_).resize(p.nnz());
    overlap_diagonal_.resize(p.n_rows());
    for (Index i = 0; i < p.n_rows(); ++i) overlap_diagonal_[i] = p.find(i, i);
    owned_mass_ = structure_->mass_diagonal();
    overlap_mass_ = multigrid_ ? owned_mass_ : structure_->overlap_mass_diagonal();
    schur_work_.resize(structure_->local_columns());
    if (structure_->damping_time() > 0) damping_work_.resize(structure_->local_columns());
  }
  matrix_free_ = preconditioner == Preconditioner::AlgebraicMultigrid && system_.matrix_free();
  const CsrPattern& full =
      matrix_free_ ? system_.preconditioner_pattern() : system_.jacobian_pattern();
  const Index n = system_.owned_size();
  if (preconditioner == Preconditioner::BlockJacobi) {
    for (Index i = 0; i < n; ++i) {
      for (Index e = full.row_ptr[i]; e < full.row_ptr[i + 1]; ++e)
        if (full.col_idx[e] < n) {
          block_pattern_.col_idx.push_back(full.col_idx[e]);
          block_source_.push_back(e);
        }
      block_pattern_.row_ptr.push_back(block_pattern_.nnz());
    }
    block_values_.resize(block_pattern_.nnz());
  }
  a_.resize(full.nnz());
  if (with_derivative_terms_) b_.resize(full.nnz());
  column_work_.resize(system_.local_columns());
}

DistributedLinearization::~DistributedLinearization() = default;

void DistributedLinearization::setup(Real t, Real c_j, std::span<const Real> y,
                                     std::span<const Real> yp) {
  if (matrix_free_) {
    system_.preconditioner_jacobian(t, y, a_);
    setup_time_ = t;
    setup_state_.assign(y.begin(), y.end());
  } else {
    system_.jacobian(t, 0.0, y, yp, a_);
  }
  if (with_derivative_terms_) {
    system_.jacobian(t, 1.0, y, yp, b_);
    for (std::size_t e = 0; e < b_.size(); ++e) b_[e] -= a_[e];
  }
  for (std::size_t k = 0; k < block_source_.size(); ++k) {
    const Index e = block_source_[k];
    block_values_[k] = with_derivative_terms_ ? a_[e] + c_j * b_[e] : a_[e];
  }
  ++setups_;
  if (schwarz_) system_.overlap_jacobian(t, c_j, y, yp, overlap_values_);  // collective
  if (structure_) {  // (1 + c beta) K + c^2 M of its rows (beta: the damping C = beta K)
    std::vector<Real>& values = multigrid_ ? owned_stiffness_ : overlap_values_;
    const auto y_structure = y.subspan(0, structure_->owned_size());
    if (multigrid_)
      structure_->stiffness(t, y_structure, values);
    else
      structure_->overlap_stiffness(t, y_structure, values);
    schur_c_ = c_j;
    if (const Real beta = structure_->damping_time(); beta > 0) {
      overlap_stiffness_ = values;  // K, for the right side's beta K r_y
      for (Real& value : values) value *= 1 + c_j * beta;
    }
    for (std::size_t i = 0; i < overlap_diagonal_.size(); ++i)
      values[overlap_diagonal_[i]] += c_j * c_j * overlap_mass_[i];
  }
  if (multigrid_) {  // collective, also on a rank without rows
    const bool schur = structure_ != nullptr;
    if (!amg_) {
      Index first_row = 0;
      std::vector<Index> columns =
          schur
              ? global_column_numbers(structure_->communicator(), structure_->owned_size(),
                                      structure_->local_columns(), first_row,
                                      [this](std::span<Real> x) { structure_->exchange_ghosts(x); })
              : global_column_numbers(system_.communicator(), system_.owned_size(),
                                      system_.local_columns(), first_row,
                                      [this](std::span<Real> x) { system_.exchange_ghosts(x); });
      const CsrPattern& pattern = schur          ? structure_->stiffness_pattern()
                                  : matrix_free_ ? system_.preconditioner_pattern()
                                                 : system_.jacobian_pattern();
      AmgOptions options;
      options.unknowns_per_cell =
          schur ? structure_->unknowns_per_cell() : system_.unknowns_per_cell();
      amg_ = std::make_unique<BoomerAmg>(system_.communicator(), pattern, std::move(columns),
                                         first_row, options);
    }
    amg_->setup(schur ? owned_stiffness_ : a_);
    return;
  }
  if (system_.owned_size() == 0) return;  // an empty part has nothing to factorise
  const CsrPattern& pattern = schwarz_     ? *system_.overlap_pattern()
                              : structure_ ? *structure_->overlap_stiffness_pattern()
                                           : block_pattern_;
  const std::vector<Real>& values = schwarz_ || structure_ ? overlap_values_ : block_values_;
  if (lu_)
    lu_->refactor(values);
  else
    lu_ = std::make_unique<KluFactorization>(pattern, values);
}

Real DistributedLinearization::krylov_tolerance_factor() const {
  return (schwarz_ || structure_) && !multigrid_ ? 5e-4 : 5e-7;
}

AmgStats DistributedLinearization::multigrid_stats() const {
  return amg_ ? amg_->stats() : AmgStats{};
}

DistributedLinearization::Preconditioner DistributedLinearization::best_for(
    DistributedSystem& system, bool with_derivative_terms, Family family) {
  DistributedSecondOrderOperator* op = system.second_order();
  if (family == Family::BlockJacobi) return Preconditioner::BlockJacobi;
  if (family == Family::Multigrid)
    return !with_derivative_terms ? Preconditioner::AlgebraicMultigrid
           : op                   ? Preconditioner::SchurAlgebraicMultigrid
                                  : Preconditioner::BlockJacobi;
  if (!with_derivative_terms)
    return system.overlap_pattern() ? Preconditioner::RestrictedAdditiveSchwarz
                                    : Preconditioner::BlockJacobi;
  return op && op->overlap_stiffness_pattern() ? Preconditioner::SchurAdditiveSchwarz
                                               : Preconditioner::BlockJacobi;
}

void DistributedLinearization::apply(Real c_j, std::span<const Real> v, std::span<Real> jv) {
  const Index n = system_.owned_size();
  if (matrix_free_) {
    system_.jacobian_product(setup_time_, setup_state_, v.subspan(0, n), jv);
    return;
  }
  std::copy(v.begin(), v.begin() + n, column_work_.begin());
  system_.exchange_ghosts(column_work_);
  const CsrPattern& full = system_.jacobian_pattern();
  for (Index i = 0; i < n; ++i) {
    Real sum = 0;
    for (Index e = full.row_ptr[i]; e < full.row_ptr[i + 1]; ++e) {
      const Real value = with_derivative_terms_ ? a_[e] + c_j * b_[e] : a_[e];
      sum += value * column_work_[full.col_idx[e]];
    }
    jv[i] = sum;
  }
}

void DistributedLinearization::absolute_product(std::span<const Real> y, std::span<Real> out) {
  const Index n = system_.owned_size();
  for (Index i = 0; i < n; ++i) column_work_[i] = std::abs(y[i]);
  system_.exchange_ghosts(column_work_);
  const CsrPattern& pattern =
      matrix_free_ ? system_.preconditioner_pattern() : system_.jacobian_pattern();
  for (Index i = 0; i < n; ++i) {
    Real sum = 0;
    for (Index e = pattern.row_ptr[i]; e < pattern.row_ptr[i + 1]; ++e)
      sum += std::abs(a_[e]) * column_work_[pattern.col_idx[e]];
    out[i] = sum;
  }
}

void DistributedLinearization::precondition(std::span<const Real> r, std::span<Real> z) {
  const Index n = system_.owned_size();
  if (structure_) {
    // (K + c^2 M) dy = r_v + c M r_y on the overlap, then dv = c dy - r_y. With damping
    // C = beta K: ((1 + c beta) K + c^2 M) dy = r_v + (c M + beta K) r_y.
    const Index m = structure_->owned_size();
    for (Index i = 0; i < m; ++i) schur_work_[i] = r[m + i] + schur_c_ * owned_mass_[i] * r[i];
    if (const Real beta = structure_->damping_time(); beta > 0) {
      std::copy(r.begin(), r.begin() + m, damping_work_.begin());
      structure_->exchange_ghosts(damping_work_);
      const CsrPattern& p =
          multigrid_ ? structure_->stiffness_pattern() : *structure_->overlap_stiffness_pattern();
      for (Index i = 0; i < m; ++i)  // the owned rows come first in the overlap
        for (Index e = p.row_ptr[i]; e < p.row_ptr[i + 1]; ++e)
          schur_work_[i] += beta * overlap_stiffness_[e] * damping_work_[p.col_idx[e]];
    }
    if (multigrid_) {
      amg_->apply(schur_work_, schur_work_);
    } else {
      structure_->exchange_ghosts(schur_work_);
      if (lu_) lu_->solve(schur_work_);
    }
    for (Index i = 0; i < m; ++i) {
      const Real dy = schur_work_[i];
      z[m + i] = schur_c_ * dy - r[i];  // r[i] read before z[i] is written (z may be r)
      z[i] = dy;
    }
    return;
  }
  if (multigrid_) {
    amg_->apply(r, z);
    return;
  }
  if (!schwarz_) {
    if (r.data() != z.data()) std::copy(r.begin(), r.begin() + n, z.begin());
    if (lu_) lu_->solve(z);
    return;
  }
  std::copy(r.begin(), r.begin() + n, column_work_.begin());
  system_.exchange_ghosts(column_work_);  // R_d r: the overlap's entries from their owners
  if (lu_) lu_->solve(column_work_);
  std::copy(column_work_.begin(), column_work_.begin() + n, z.begin());  // R_0^T
}

}  // namespace rfmems

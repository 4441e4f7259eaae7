#include "parallel/distributed_local_operator.hpp"

#include <algorithm>

namespace rfmems {

DistributedLocalOperator::DistributedLocalOperator(const Mesh& global, const Communicator& comm,
                                                   int ghost_layers, int block,
                                                   const Factory& build)
    : comm_(comm), block_(block), n_global_(global.n_cells()) {
  mesh_ = std::make_unique<DistributedMesh>(distribute_mesh(global, comm, ghost_layers));
  n_owned_ = mesh_->local.mesh.n_owned_cells();
  if (n_owned_ > 0) local_ = build(mesh_->local);
  damping_time_ = comm_.max(local_ ? local_->damping_time() : 0.0);  // collective
  if (n_owned_ == 0) return;  // an empty part (more ranks than cells): no rows, no columns
  // Owned cells come first, so their rows are the first rows of the local pattern.
  const CsrPattern& full = local_->stiffness_pattern();
  const Index rows = owned_size();
  owned_pattern_.row_ptr.assign(full.row_ptr.begin(), full.row_ptr.begin() + rows + 1);
  owned_pattern_.col_idx.assign(full.col_idx.begin(), full.col_idx.begin() + full.row_ptr[rows]);
  u_local_.resize(local_->size());
  r_local_.resize(local_->size());
  k_local_.resize(full.nnz());
}

void DistributedLocalOperator::load(std::span<const Real> u) {
  std::copy(u.begin(), u.begin() + owned_size(), u_local_.begin());
  mesh_->exchange.exchange(u_local_, block_);
}

void DistributedLocalOperator::internal_residual(Real t, std::span<const Real> u,
                                                 std::span<Real> r) {
  load(u);  // collective: every rank exchanges, also one without cells
  if (!local_) return;
  local_->internal_residual(t, u_local_, r_local_);
  std::copy(r_local_.begin(), r_local_.begin() + owned_size(), r.begin());
}

void DistributedLocalOperator::add_damping_force(Real t, std::span<const Real> v,
                                                 std::span<Real> r) {
  load(v);  // collective
  if (!local_) return;
  std::fill(r_local_.begin(), r_local_.end(), 0.0);
  local_->add_damping_force(t, u_local_, r_local_);
  for (Index i = 0; i < owned_size(); ++i) r[i] += r_local_[i];
}

void DistributedLocalOperator::stiffness(Real t, std::span<const Real> u, std::span<Real> values) {
  load(u);
  if (!local_) return;
  local_->stiffness(t, u_local_, k_local_);
  std::copy(k_local_.begin(), k_local_.begin() + owned_pattern_.nnz(), values.begin());
}

void DistributedLocalOperator::overlap_stiffness(Real t, std::span<const Real> u,
                                                 std::span<Real> values) {
  load(u);
  if (local_) local_->stiffness(t, u_local_, values);
}

std::vector<Real> DistributedLocalOperator::mass_diagonal() const {
  if (!local_) return {};
  std::vector<Real> m = local_->mass_diagonal();
  m.resize(owned_size());
  return m;
}

void DistributedLocalOperator::exchange_ghosts(std::span<Real> x) const {
  mesh_->exchange.exchange(x, block_);
}

std::vector<Real> DistributedLocalOperator::gather_to_root(std::span<const Real> owned) const {
  return rfmems::gather_to_root(comm_, mesh_->local, owned, block_, n_global_);
}

std::vector<Real> DistributedLocalOperator::owned_part(std::span<const Real> global) const {
  std::vector<Real> owned(owned_size());
  for (Index c = 0; c < n_owned_; ++c)
    std::copy(global.begin() + mesh_->local.global_cell[c] * block_,
              global.begin() + (mesh_->local.global_cell[c] + 1) * block_,
              owned.begin() + c * block_);
  return owned;
}

}  // namespace rfmems

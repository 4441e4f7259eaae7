#include "physics/elasticity/distributed_elasticity.hpp"

#include <algorithm>

namespace rfmems {

DistributedElasticity::DistributedElasticity(const ElasticityOperator& global,
                                             const Communicator& comm)
    : comm_(comm), dim_(global.dim()), n_global_(global.mesh().n_cells()) {
  mesh_ = std::make_unique<DistributedMesh>(distribute_mesh(global.mesh(), comm, kGhostLayers));
  const Mesh& local = mesh_->local.mesh;
  n_owned_ = local.n_owned_cells();
  if (n_owned_ == 0) return;  // an empty part (more ranks than cells): no rows, no columns
  // The same condition on each physical patch (by name: the local mesh numbers its patches
  // in its own order). The cut through the last ghost layer is clamped: only the last
  // layer's rows and reconstructions see it (a cell of layer 3 has no face on the cut), and
  // it keeps the local matrix nonsingular where a part floats free of the physical clamps.
  std::vector<ElasticityBoundary> boundaries;
  for (const Patch& p : local.patches()) {
    const int g = global.mesh().find_patch(p.name);
    boundaries.push_back(g >= 0 ? global.boundaries()[g]
                                : ElasticityBoundary{ElasticityBoundary::Kind::Fixed, {}});
  }
  local_ = std::make_unique<ElasticityOperator>(local, global.material(), std::move(boundaries),
                                                global.body_force(),
                                                global.requested_reconstruction_degree());
  // Owned cells come first, so their rows are the first rows of the local pattern.
  const CsrPattern& full = local_->stiffness_pattern();
  const Index rows = owned_size();
  owned_pattern_.row_ptr.assign(full.row_ptr.begin(), full.row_ptr.begin() + rows + 1);
  owned_pattern_.col_idx.assign(full.col_idx.begin(), full.col_idx.begin() + full.row_ptr[rows]);
  u_local_.resize(local_->size());
  r_local_.resize(local_->size());
  k_local_.resize(full.nnz());
}

void DistributedElasticity::load(std::span<const Real> u) {
  std::copy(u.begin(), u.begin() + owned_size(), u_local_.begin());
  mesh_->exchange.exchange(u_local_, dim_);
}

void DistributedElasticity::internal_residual(Real t, std::span<const Real> u, std::span<Real> r) {
  load(u);  // collective: every rank exchanges, also one without cells
  if (!local_) return;
  local_->internal_residual(t, u_local_, r_local_);
  std::copy(r_local_.begin(), r_local_.begin() + owned_size(), r.begin());
}

void DistributedElasticity::stiffness(Real t, std::span<const Real> u, std::span<Real> values) {
  load(u);
  if (!local_) return;
  local_->stiffness(t, u_local_, k_local_);
  std::copy(k_local_.begin(), k_local_.begin() + owned_pattern_.nnz(), values.begin());
}

void DistributedElasticity::overlap_stiffness(Real t, std::span<const Real> u,
                                              std::span<Real> values) {
  load(u);
  if (local_) local_->stiffness(t, u_local_, values);
}

std::vector<Real> DistributedElasticity::mass_diagonal() const {
  if (!local_) return {};
  std::vector<Real> m = local_->mass_diagonal();
  m.resize(owned_size());
  return m;
}

void DistributedElasticity::exchange_ghosts(std::span<Real> x) const {
  mesh_->exchange.exchange(x, dim_);
}

std::vector<Real> DistributedElasticity::gather_to_root(std::span<const Real> owned) const {
  return rfmems::gather_to_root(comm_, mesh_->local, owned, dim_, n_global_);
}

std::vector<Real> DistributedElasticity::owned_part(std::span<const Real> global) const {
  std::vector<Real> owned(owned_size());
  for (Index c = 0; c < n_owned_; ++c)
    std::copy(global.begin() + mesh_->local.global_cell[c] * dim_,
              global.begin() + (mesh_->local.global_cell[c] + 1) * dim_, owned.begin() + c * dim_);
  return owned;
}

}  // namespace rfmems

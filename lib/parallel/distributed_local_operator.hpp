// A serial structural operator (SecondOrderOperator, `block` unknowns per cell, cell-major)
// run on each rank's local mesh (owned cells, then ghost layers; parallel/distributed_mesh.hpp)
// as a DistributedSecondOrderOperator: the owned rows of its residual and Jacobian, ghosts
// refreshed (GhostExchange) before every evaluation, the whole local matrix as the
// overlapping subdomain of an additive Schwarz preconditioner.
//
// Exact (owned rows = the serial operator's, to round-off) when the ghost layers cover the
// operator's stencil: an owned row may use the reconstructions of its face neighbours, whose
// stencils reach the operator's ring depth. The operators say how many layers they need
// (physics/elasticity/distributed_elasticity.hpp, physics/plate/distributed_plate.hpp), and
// test/mpi/test_distributed_structure.cpp checks the rows.
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "parallel/distributed_mesh.hpp"
#include "parallel/distributed_system.hpp"

namespace rfmems {

class DistributedLocalOperator : public DistributedSecondOrderOperator {
 public:
  // Builds this rank's operator on its local mesh (called once, only on ranks with cells).
  using Factory = std::function<std::unique_ptr<SecondOrderOperator>(const LocalMesh& local)>;

  // Collective: partitions `global` over comm with `ghost_layers` layers.
  DistributedLocalOperator(const Mesh& global, const Communicator& comm, int ghost_layers,
                           int block, const Factory& build);

  const Communicator& communicator() const override { return comm_; }
  Index owned_size() const override { return n_owned_ * block_; }
  Index local_columns() const override { return local_ ? local_->size() : 0; }
  Index global_size() const override { return n_global_ * block_; }
  void internal_residual(Real t, std::span<const Real> u, std::span<Real> r) override;
  const CsrPattern& stiffness_pattern() const override { return owned_pattern_; }
  void stiffness(Real t, std::span<const Real> u, std::span<Real> values) override;
  std::vector<Real> mass_diagonal() const override;
  void exchange_ghosts(std::span<Real> x) const override;
  const CsrPattern* overlap_stiffness_pattern() const override {
    return local_ ? &local_->stiffness_pattern() : &owned_pattern_;
  }
  void overlap_stiffness(Real t, std::span<const Real> u, std::span<Real> values) override;
  std::vector<Real> overlap_mass_diagonal() const override {
    return local_ ? local_->mass_diagonal() : std::vector<Real>{};
  }
  Real damping_time() const override { return damping_time_; }
  void add_damping_force(Real t, std::span<const Real> v, std::span<Real> r) override;
  std::vector<Real> gather_to_root(std::span<const Real> owned) const override;
  std::vector<Real> owned_part(std::span<const Real> global) const override;
  int unknowns_per_cell() const override { return block_; }

  const DistributedMesh& distributed_mesh() const { return *mesh_; }

 private:
  // Owned values into u_local_, ghosts from their owners (collective).
  void load(std::span<const Real> u);

  Communicator comm_;
  int block_;
  Index n_owned_ = 0, n_global_ = 0;
  Real damping_time_ = 0;                  // the local operator's, the same on every rank
  std::unique_ptr<DistributedMesh> mesh_;  // on the heap: local_ keeps a reference to it
  std::unique_ptr<SecondOrderOperator> local_;
  CsrPattern owned_pattern_;
  std::vector<Real> u_local_, r_local_, k_local_;
};

}  // namespace rfmems

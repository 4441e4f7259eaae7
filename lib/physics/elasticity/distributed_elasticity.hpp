// The FV elasticity operator on a distributed mesh (issue 7): each rank owns the cells of
// its METIS part and evaluates their rows of M u'' + R(t, u) = 0.
//
// It wraps the serial ElasticityOperator built on the rank's local mesh (owned cells, then
// kGhostLayers layers of ghosts; the faces leaving the last layer form a free "processor"
// patch, clamped: u = 0 there) rather than rewriting it. That is exact: an owned cell's row sums
// the forces of its faces, each from the reconstructions of the cell and of its face neighbour (a
// ghost of layer 1 at most), and a reconstruction's stencil reaches three rings (cubic, near free
// boundaries; fv/polynomial_reconstruction.hpp), so with four layers every stencil an owned
// row uses is the serial one. Only the order of the points inside a stencil (and so the
// round-off of its least-squares fit) differs: owned rows of the residual and of the
// Jacobian equal the serial ones to round-off (test/mpi/test_distributed_structure.cpp).
// The outer ghost rows are wrong (truncated stencils, the clamped cut) and never used in the
// residual; they make the local matrix a nonsingular subdomain problem, the block of the
// restricted additive Schwarz preconditioner (solvers/distributed_linearization.hpp).
//
// Ghost values are refreshed (GhostExchange) before every residual and Jacobian.
#pragma once
#include <memory>
#include <vector>

#include "parallel/distributed_mesh.hpp"
#include "parallel/distributed_system.hpp"
#include "physics/elasticity/elasticity_operator.hpp"

namespace rfmems {

class DistributedElasticity : public DistributedSecondOrderOperator {
 public:
  // The layers the widest (cubic) stencil needs: a face neighbour's three rings.
  static constexpr int kGhostLayers = 4;

  // Collective: partitions global.mesh() over comm and builds this rank's part of the same
  // operator (material, boundary conditions, body force, reconstruction degree).
  DistributedElasticity(const ElasticityOperator& global, const Communicator& comm);

  const Communicator& communicator() const override { return comm_; }
  Index owned_size() const override { return n_owned_ * dim_; }
  Index local_columns() const override { return local_ ? local_->size() : 0; }
  Index global_size() const override { return n_global_ * dim_; }
  void internal_residual(Real t, std::span<const Real> u, std::span<Real> r) override;
  const CsrPattern& stiffness_pattern() const override { return owned_pattern_; }
  void stiffness(Real t, std::span<const Real> u, std::span<Real> values) override;
  std::vector<Real> mass_diagonal() const override;
  void exchange_ghosts(std::span<Real> x) const override;
  // The local operator's whole matrix: the subdomain with its ghost overlap, clamped at the
  // cut (the "processor" patch is Fixed at zero, which only the last ghost layer's rows see).
  const CsrPattern* overlap_stiffness_pattern() const override {
    return local_ ? &local_->stiffness_pattern() : &owned_pattern_;
  }
  void overlap_stiffness(Real t, std::span<const Real> u, std::span<Real> values) override;
  std::vector<Real> overlap_mass_diagonal() const override {
    return local_ ? local_->mass_diagonal() : std::vector<Real>{};
  }
  std::vector<Real> gather_to_root(std::span<const Real> owned) const override;
  std::vector<Real> owned_part(std::span<const Real> global) const override;

  const DistributedMesh& distributed_mesh() const { return *mesh_; }

 private:
  // Owned values into u_local_, ghosts from their owners.
  void load(std::span<const Real> u);

  Communicator comm_;
  int dim_;
  Index n_owned_ = 0, n_global_ = 0;
  std::unique_ptr<DistributedMesh> mesh_;  // on the heap: local_ keeps a reference to it
  std::unique_ptr<ElasticityOperator> local_;
  CsrPattern owned_pattern_;
  std::vector<Real> u_local_, r_local_, k_local_;
};

}  // namespace rfmems

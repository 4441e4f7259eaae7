// The FV elasticity operator on a distributed mesh: each rank owns the cells of
// its METIS part and evaluates their rows of M u'' + R(t, u) = 0.
//
// It runs the serial ElasticityOperator on the rank's local mesh (owned cells, then
// kGhostLayers layers of ghosts; the faces leaving the last layer form a "processor" patch,
// clamped: u = 0 there; parallel/distributed_local_operator.hpp) rather than rewriting it.
// That is exact: an owned cell's row sums the forces of its faces, each from the
// reconstructions of the cell and of its face neighbour (a ghost of layer 1 at most), and a
// reconstruction's stencil reaches three rings (cubic, near free boundaries;
// fv/polynomial_reconstruction.hpp), so with four layers every stencil an owned row uses is
// the serial one. Only the order of the points inside a stencil (and so the round-off of its
// least-squares fit) differs: owned rows of the residual and of the Jacobian equal the serial
// ones to round-off (test/mpi/test_distributed_structure.cpp). The outer ghost rows are wrong
// (truncated stencils, the clamped cut) and never used in the residual; they make the local
// matrix a nonsingular subdomain problem, the block of the restricted additive Schwarz
// preconditioner (solvers/distributed_linearization.hpp). The clamp is seen only by the last
// layer's rows and reconstructions (a cell of layer 3 has no face on the cut).
#pragma once
#include "parallel/distributed_local_operator.hpp"
#include "physics/elasticity/elasticity_operator.hpp"

namespace rfmems {

class DistributedElasticity : public DistributedLocalOperator {
 public:
  // The layers the widest (cubic) stencil needs: a face neighbour's three rings.
  static constexpr int kGhostLayers = 4;

  // Collective: partitions global.mesh() over comm and builds this rank's part of the same
  // operator (material, boundary conditions, body force, reconstruction degree).
  DistributedElasticity(const ElasticityOperator& global, const Communicator& comm);
};

}  // namespace rfmems

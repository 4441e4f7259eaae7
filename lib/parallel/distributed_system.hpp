// The operator contracts of core/system_operator.hpp for unknowns distributed over the ranks
// of a communicator: each rank holds the unknowns of the cells it owns (owned first, in its
// local order) and evaluates the residual rows of those unknowns; the Jacobian rows it
// provides reach its ghost columns too (local numbering: owned columns [0, n_owned), then
// the ghosts' columns), and exchange_ghosts() fills a column vector's ghost part from the
// owners. That is all a Krylov solver needs: a distributed matrix-vector product (exchange,
// then the owned rows) and a rank-local block (owned rows x owned columns) to precondition
// with (lib/solvers/distributed_linearization.hpp).
//
// No MPI here: ghost exchanges go through parallel/ghost_exchange.hpp.
#pragma once
#include <span>
#include <vector>

#include "core/system_operator.hpp"
#include "parallel/communicator.hpp"

namespace rfmems {

class DistributedSecondOrderOperator;

// F(t, y, y') = 0 with y distributed (SUNDIALS' IDA and KINSOL on N_Vector_Parallel).
class DistributedSystem {
 public:
  virtual ~DistributedSystem() = default;
  virtual const Communicator& communicator() const = 0;
  // Unknowns this rank owns, and the columns its Jacobian rows reach (owned + ghost).
  virtual Index owned_size() const = 0;
  virtual Index local_columns() const = 0;
  // 1 for differential components, 0 for algebraic ones (owned unknowns).
  virtual std::vector<Real> differential_components() const = 0;
  // The owned rows of F from the owned unknowns (the system exchanges its ghosts itself).
  // Collective: every rank calls it together.
  virtual void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                        std::span<Real> r) = 0;
  // Owned rows x local columns of dF/dy + c_j dF/dy' at the owned state (collective).
  virtual const CsrPattern& jacobian_pattern() const = 0;
  virtual void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                        std::span<Real> values) = 0;
  // x has local_columns() entries, the owned ones set: fills the ghost ones (collective).
  virtual void exchange_ghosts(std::span<Real> x) const = 0;

  // Optional: the rank's overlapping subdomain problem, all local rows (owned and ghost) x
  // local columns, square and nonsingular, for an additive Schwarz preconditioner. nullptr:
  // none (block Jacobi on the owned block only).
  virtual const CsrPattern* overlap_pattern() const { return nullptr; }
  virtual void overlap_jacobian(Real /*t*/, Real /*c_j*/, std::span<const Real> /*y*/,
                                std::span<const Real> /*yp*/, std::span<Real> /*values*/) {}
  // Optional: the structural operator of a first-order system [y' - v; M v' + R] (state
  // [y; v]), for preconditioners that eliminate v; nullptr otherwise.
  virtual DistributedSecondOrderOperator* second_order() { return nullptr; }
  // Unknowns per cell, interleaved (cell-major), for preconditioners that treat a system of
  // PDEs unknown by unknown (algebraic multigrid).
  virtual int unknowns_per_cell() const { return 1; }

  // Optional, for structures too large to store their Jacobian: the product
  // jv = (dF/dy + c_j dF/dy') v on the owned rows without the matrix, and a sparser matrix
  // close to the Jacobian to build the preconditioner from (owned rows x local columns; a
  // compact discretisation of the same equations). With it the Krylov solvers never call
  // jacobian(). Static systems only (c_j = 0).
  virtual bool matrix_free() const { return false; }
  virtual void jacobian_product(Real /*t*/, std::span<const Real> /*y*/,
                                std::span<const Real> /*v*/, std::span<Real> /*jv*/) {}
  virtual const CsrPattern& preconditioner_pattern() const { return jacobian_pattern(); }
  virtual void preconditioner_jacobian(Real /*t*/, std::span<const Real> /*y*/,
                                       std::span<Real> /*values*/) {}
};

// M y'' + R(t, y) = 0 with y distributed (the structure's operators on a distributed mesh):
// the distributed counterpart of SecondOrderOperator, adapted to DistributedSystem by
// parallel/distributed_structural_systems.hpp.
class DistributedSecondOrderOperator {
 public:
  virtual ~DistributedSecondOrderOperator() = default;
  virtual const Communicator& communicator() const = 0;
  virtual Index owned_size() const = 0;
  virtual Index local_columns() const = 0;
  virtual Index global_size() const = 0;
  // Owned rows of R (collective).
  virtual void internal_residual(Real t, std::span<const Real> y, std::span<Real> r) = 0;
  // Owned rows x local columns of dR/dy (collective).
  virtual const CsrPattern& stiffness_pattern() const = 0;
  virtual void stiffness(Real t, std::span<const Real> y, std::span<Real> values) = 0;
  // Owned entries of the lumped mass.
  virtual std::vector<Real> mass_diagonal() const = 0;
  virtual void exchange_ghosts(std::span<Real> x) const = 0;
  // Optional: dR/dy of the overlapping subdomain (all local rows x local columns; see
  // DistributedSystem::overlap_pattern), nullptr if none.
  virtual const CsrPattern* overlap_stiffness_pattern() const { return nullptr; }
  virtual void overlap_stiffness(Real /*t*/, std::span<const Real> /*y*/,
                                 std::span<Real> /*values*/) {}
  // The lumped mass of all local rows (owned and ghost), with overlap_stiffness_pattern().
  virtual std::vector<Real> overlap_mass_diagonal() const { return {}; }
  // Optional damping C = beta K, as SecondOrderOperator's (the same beta on every rank):
  // owned rows r += C v (collective).
  virtual Real damping_time() const { return 0; }
  virtual void add_damping_force(Real /*t*/, std::span<const Real> /*v*/, std::span<Real> /*r*/) {}
  // The owned values of every rank in global order on the root (empty elsewhere), and the
  // reverse: the owned part of a global vector known on every rank.
  virtual std::vector<Real> gather_to_root(std::span<const Real> owned) const = 0;
  virtual std::vector<Real> owned_part(std::span<const Real> global) const = 0;
  // Unknowns per cell, interleaved (cell-major), as DistributedSystem's.
  virtual int unknowns_per_cell() const { return 1; }
  // Optional, as DistributedSystem's: kv = dR/dy v without the matrix (owned rows, collective)
  // and the compact matrix to precondition with (owned rows x local columns).
  virtual bool matrix_free() const { return false; }
  virtual void stiffness_product(Real /*t*/, std::span<const Real> /*y*/,
                                 std::span<const Real> /*v*/, std::span<Real> /*kv*/) {}
  virtual const CsrPattern& preconditioner_pattern() const { return stiffness_pattern(); }
  virtual void preconditioner_stiffness(Real /*t*/, std::span<const Real> /*y*/,
                                        std::span<Real> /*values*/) {}
};

}  // namespace rfmems

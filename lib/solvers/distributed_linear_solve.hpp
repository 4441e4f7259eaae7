// A linear system A x = b with its rows distributed over the ranks (the immersed
// electrostatics under MPI), solved by right-preconditioned restarted GMRES (SUNDIALS SPGMR,
// modified Gram-Schmidt) on N_Vector_Parallel with the preconditioners of
// distributed_linearization.hpp: restricted additive Schwarz with KLU on the rank's
// overlapping subdomain matrix (owned + ghost rows) when one is given, else block Jacobi on
// the owned block. The matrix is wrapped as a DistributedSystem whose Jacobian is A, so the
// Krylov machinery is the one the distributed structure uses, not a second copy.
//
// Stopping test: ||b - A x||_2 <= relative_tolerance ||b||_2 (right preconditioning leaves
// the residual GMRES minimises unpreconditioned).
#pragma once
#include <memory>
#include <span>
#include <vector>

#include "core/system_operator.hpp"
#include "parallel/communicator.hpp"
#include "parallel/ghost_exchange.hpp"

namespace rfmems {

// This rank's rows. Local columns: the owned unknowns [0, n_owned), then the ghosts, whose
// values `exchange` fetches from their owners.
struct DistributedMatrix {
  Index n_owned = 0;
  Index n_local = 0;  // owned + ghosts
  const GhostExchange* exchange = nullptr;
  CsrPattern pattern;  // owned rows x local columns
  std::vector<Real> values;
  // Optional (empty: block Jacobi): the overlapping subdomain, all local rows x local
  // columns, the ghost rows truncated to the local columns.
  CsrPattern overlap_pattern;
  std::vector<Real> overlap_values;
};

struct DistributedLinearOptions {
  Real relative_tolerance = 1e-13;
  int krylov_dimension = 100;
  int max_restarts = 20;
  bool overlap = true;  // restricted additive Schwarz where the matrix has an overlap
  // Classical Gram-Schmidt (one global reduction per iteration, N_VDotProdMulti) rather than
  // modified (one per basis vector: k reductions at iteration k).
  bool classical_gram_schmidt = true;
};

struct DistributedLinearStats {
  long iterations = 0;         // GMRES iterations (the same on every rank)
  Real relative_residual = 0;  // ||b - A x||_2 / ||b||_2 at exit
};

class DistributedLinearSolver {
 public:
  // `matrix` must outlive the solver; its patterns are fixed for the solver's life, its
  // values may change before each factor(). Collective.
  DistributedLinearSolver(const Communicator& comm, const DistributedMatrix& matrix,
                          const DistributedLinearOptions& options = {});
  ~DistributedLinearSolver();
  DistributedLinearSolver(const DistributedLinearSolver&) = delete;
  DistributedLinearSolver& operator=(const DistributedLinearSolver&) = delete;

  bool schwarz() const;
  // Takes the matrix's current values into the product and the preconditioner (KLU: the
  // first call analyses, later ones refactor). Collective.
  void factor();
  // x: the owned unknowns, on entry the initial guess. SolverError if GMRES does not reach
  // the tolerance. Collective.
  DistributedLinearStats solve(std::span<const Real> b, std::span<Real> x);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rfmems

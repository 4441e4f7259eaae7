// The linear algebra of Newton-Krylov on a DistributedSystem: the exact distributed
// Jacobian-vector product and a block-Jacobi preconditioner whose blocks are the rank-local
// Jacobians (owned rows x owned columns) factorised by KLU.
//
// setup() evaluates dF/dy (and, for transients, dF/dy') at the Newton iterate and factorises
// the owned block of dF/dy + c_j dF/dy'. apply() multiplies by the Jacobian at that iterate
// for any c_j: the systems here are affine in c_j (dF/dy' does not depend on it), so
// J(c_j) = A + c_j B with A = J(0), B = J(1) - A exactly (to one rounding). Between setups
// the product uses the last setup's A: exact for the linear structure, a modified (lagged)
// Newton for a nonlinear one.
//
// Block Jacobi drops the couplings between parts: on P ranks the Krylov solver has to
// recover them, so its iterations grow with P (docs/mpi.md, "Distributed structure"). One rank: the
// block is the whole Jacobian and one iteration solves exactly.
//
// Restricted additive Schwarz (Cai & Sarkis 1999), where the system offers its overlapping
// subdomain matrix (DistributedSystem::overlap_pattern): z = R_0^T A_d^-1 R_d r, i.e. r's
// ghost entries fetched from their owners, the subdomain problem (owned + ghost rows, KLU)
// solved, the owned part kept. One ghost exchange more per application; the overlap carries
// the coupling between parts that block Jacobi drops.
//
// For a first-order structural system [y' - v; M v' + R] (DistributedSystem::second_order)
// with J = [c I, -I; K, c M], eliminating dv = c dy - r_y leaves (K + c^2 M) dy = r_v + c M r_y:
// the Schur variant solves that by restricted additive Schwarz on the structure's overlap
// (K and M of the local rows, c of the last setup) and recovers dv. With the structure's
// damping C = beta K (J's v block c M + beta K) it is ((1 + c beta) K + c^2 M) dy =
// r_v + (c M + beta K) r_y.
//
// Algebraic multigrid (solvers/boomer_amg.hpp) in place of the subdomain LU: one BoomerAMG
// V-cycle on the whole distributed matrix (owned rows x every column, in global numbers),
// of J for a static system and of the Schur complement (1 + c beta) K + c^2 M for a
// structural first-order one. Its cost per application and its memory grow in proportion to
// the unknowns, where the LU's fill grows faster (the large structures: docs/scale.md), and
// its quality does not fall with the number of ranks. A matrix-free static system
// (DistributedSystem::matrix_free) is multiplied by without its Jacobian, and the multigrid is
// built from its compact preconditioner matrix instead.
#pragma once
#include <memory>
#include <span>
#include <vector>

#include "parallel/distributed_system.hpp"
#include "solvers/boomer_amg.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

class DistributedLinearization {
 public:
  enum class Preconditioner {
    BlockJacobi,
    RestrictedAdditiveSchwarz,
    SchurAdditiveSchwarz,
    AlgebraicMultigrid,
    SchurAlgebraicMultigrid
  };
  // with_derivative_terms: evaluate dF/dy' too (IDA); false: c_j is always 0 (KINSOL).
  // RestrictedAdditiveSchwarz needs system.overlap_pattern() and c_j = 0, SchurAdditiveSchwarz
  // a second_order() operator with an overlap_stiffness_pattern(), AlgebraicMultigrid c_j = 0,
  // SchurAlgebraicMultigrid a second_order() operator (else SolverError).
  DistributedLinearization(DistributedSystem& system, bool with_derivative_terms,
                           Preconditioner preconditioner = Preconditioner::BlockJacobi);
  ~DistributedLinearization();

  // Collective.
  void setup(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp);
  // jv = (dF/dy + c_j dF/dy') v on the owned rows (collective: exchanges v's ghosts).
  void apply(Real c_j, std::span<const Real> v, std::span<Real> jv);
  // z = P^-1 r with P the owned block at the last setup (rank-local; collective with the
  // additive Schwarz preconditioner).
  void precondition(std::span<const Real> r, std::span<Real> z);
  // out = |A| |y| on the owned rows, A = dF/dy of the last setup (collective): the size of
  // the terms that cancel in F at y, for its round-off floor (solvers/kinsol_solver.hpp).
  // Matrix-free, A is the compact preconditioner matrix, whose entries discretise the same
  // equations at the same scale.
  void absolute_product(std::span<const Real> y, std::span<Real> out);
  long setups() const { return setups_; }
  // The Krylov tolerance factor (IDA's eps_lin, IdaOptions::krylov_tolerance_factor) that keeps
  // the correction's error, up to ||(P^-1 J)^-1|| times the preconditioned residual, beneath
  // IDA's Newton tolerance with this preconditioner: 5e-4 with the overlap (the Schwarz
  // variants), 5e-7 with block Jacobi, which drops the parts' coupling (measured on the
  // cantilever with and without damping, 2 and 3 ranks: the serial step count and answer, where
  // SUNDIALS' 0.05 gave up to 6e-2 off; docs/mpi.md, "Krylov tolerance"), and 5e-7 with
  // multigrid, whose cycle on the damped slender beam's Schur complement is weak (5e-4: 100
  // steps against the serial 75).
  Real krylov_tolerance_factor() const;
  // What a solver asks for; best_for() picks the family's variant for the system.
  enum class Family { BlockJacobi, Schwarz, Multigrid };
  // Schwarz: the strongest the system offers (Schur Schwarz, Schwarz, block Jacobi);
  // Multigrid: algebraic multigrid, Schur or not (block Jacobi for a transient without a
  // structural operator); BlockJacobi: block Jacobi.
  static Preconditioner best_for(DistributedSystem& system, bool with_derivative_terms,
                                 Family family = Family::Schwarz);
  // The hierarchy of the last setup (multigrid only; collective).
  AmgStats multigrid_stats() const;

 private:
  DistributedSystem& system_;
  bool with_derivative_terms_;
  bool schwarz_;
  DistributedSecondOrderOperator* structure_ = nullptr;  // the Schur variant's
  std::vector<Real> overlap_values_, owned_mass_, overlap_mass_, schur_work_;
  std::vector<Real> overlap_stiffness_, damping_work_;  // with damping: K, and r_y with ghosts
  std::vector<Index> overlap_diagonal_;
  Real schur_c_ = 0;
  std::vector<Real> a_, b_;  // J(0) and J(1) - J(0) on jacobian_pattern()
  // Matrix-free: a_ is the preconditioner matrix; the product is at the last setup's state.
  bool matrix_free_ = false;
  Real setup_time_ = 0;
  std::vector<Real> setup_state_;
  CsrPattern block_pattern_;
  std::vector<Index> block_source_;  // entry of jacobian_pattern() for each block entry
  std::vector<Real> block_values_, column_work_;
  std::unique_ptr<KluFactorization> lu_;
  bool multigrid_ = false;
  std::unique_ptr<BoomerAmg> amg_;
  std::vector<Real> owned_stiffness_;  // the Schur multigrid's K, then its matrix
  long setups_ = 0;
};

}  // namespace rfmems

// The preconditioner of a continuum creep system's Newton systems for IDA's GMRES, with no
// factorisation of the full Jacobian. The Jacobian of the semi-explicit DAE (creep_system.hpp)
// in its blocks,
//
//   J = dF/dy + c_j dF/dy' = [ T  B ]   u rows: the structural tangent T (the stiffness K; with
//                            [ E  D ]   a relaxing prestress its u-u block) and B, the plastic
//                                       source's dependence on the creep states
//                                       q rows: E = -dg/du (the creep law through the cell's
//                                       stress), D = c_j I - dg/dq, block diagonal: one
//                                       square block of the cell's creep states per cell,
//
// has the exact inverse by eliminating q through the Schur complement S = T - B D^-1 E. The
// preconditioner keeps T for S (block Gauss-Seidel):
//
//   z_u = T^-1 (r_u - B D^-1 r_q),   z_q = D^-1 (r_q - E z_u),
//
// exact but for B D^-1 E: the creep's share of the step's tangent, the creep rate's stress
// sensitivity (n eps_dot / sigma for a power law of exponent n) times C over c_j, against C.
// It is small while one step's creep strain increment n h eps_dot is small against the elastic
// strain (the 500 h strip of the creep benchmark: below 1e-3), so GMRES needs a few iterations
// a Newton step. T^-1 is the caller's structural solve: the sparse LU of T (factorised once
// when T is constant), or a multigrid V-cycle of it.
#pragma once
#include <functional>
#include <span>
#include <vector>

#include "core/system_operator.hpp"

namespace rfmems {

class ContinuumCreepPreconditioner {
 public:
  // x = T^-1 x (in place), approximately or exactly.
  using StructuralSolve = std::function<void(std::span<Real>)>;

  // pattern: the system's Jacobian pattern, the structural unknowns first (structural_size
  // rows, their columns sorted), then n_components creep states per cell, cell after cell.
  ContinuumCreepPreconditioner(const CsrPattern& pattern, Index structural_size, int n_components);

  // Where the caller writes the Jacobian's values at the step (in the pattern's order) before
  // setup(); T's own set-up is the caller's.
  std::span<Real> jacobian_values() { return values_; }
  // Inverts the D blocks.
  void setup();
  // z = P^-1 r (r and z may alias).
  void solve(std::span<const Real> r, std::span<Real> z, const StructuralSolve& structural);

 private:
  // x_q = D^-1 x_q, cell by cell.
  void apply_block_inverse(std::span<Real> xq) const;

  const CsrPattern& pattern_;
  Index ns_;
  int nc_;
  Index n_cells_;
  std::vector<Index> first_creep_column_;  // per u row: its first entry in a q column
  std::vector<Real> values_;               // J
  std::vector<Real> block_inverse_;        // D^-1, nc x nc per cell (row-major)
  std::vector<Real> rq_, zu_;
};

}  // namespace rfmems

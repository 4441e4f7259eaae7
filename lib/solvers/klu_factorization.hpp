// A sparse LU factorisation with SuiteSparse KLU, factorised once and reused for many solves
// (the segregated baseline and the "one factorisation" cost floor of the benchmarks).
#pragma once
#include <span>
#include <vector>

#include "core/system_operator.hpp"

namespace rfmems {

// Fill-reducing ordering of the symbolic analysis: AMD (KLU's default) on A + A^T, or COLAMD
// on the columns (less fill for matrices whose rows reach far, e.g. the plate creep Schur
// complement: 1.32e6 vs 1.37e6 entries in L and a 1.6x faster refactor on 81 x 21 cells), or
// METIS nested dissection of A + A^T (large 2D grids: the 240k-unknown Stokes saddle point of
// bench_stokes_damping factorises in 32 CPU s against AMD's 142 s, L + U 5.2e7 entries).
// BySize: AMD below 1000 unknowns, nested dissection above (measured on the bordered
// quasi-static system of a plate switch, bench/bench_quasi_static_trace.cpp: 5.2e4 against
// 7.4e4 entries at 481 unknowns, 4.3e6 against 9.3e6 at 7681; docs/pull-in.md).
enum class KluOrdering { Amd, Colamd, NestedDissection, BySize };

// What kind of system is factorised, which sets the scaling and when refactor() keeps the pivot
// sequence of the last factorisation with fresh pivoting:
//   Uniform: unknowns and equations of one kind; KLU's own scaling; pivots kept while KLU's
//     cheap reciprocal condition estimate min|U_ii| / max|U_ii| stays above 1e-12.
//   MixedUnits: unknowns and equations of different units (a plate's deflections and rotations
//     bordered by a voltage); each row divided by its largest entry (KLU scales the columns of
//     what it factorises, the transpose), and pivots kept while the estimate stays within a
//     factor 1e3 of its value at the fresh pivoting: scale-free, where an absolute floor would
//     pivot afresh at every refactorisation.
enum class KluSystem { Uniform, MixedUnits };

// The nested-dissection order (METIS_NodeND) of the graph of A + A^T for the CSR pattern of A:
// order[k] is the unknown eliminated k-th. Dense nodes (degree above 10 sqrt(n), AMD's rule: the
// voltage of a bordered system, coupled to every unknown) are left out of the graph and ordered
// last: a hub joined to every node leaves METIS no small separator. KluOrdering::
// NestedDissection's order, and UMFPACK's with UmfpackOrdering::SymmetricNestedDissection.
std::vector<Index> nested_dissection_order(const CsrPattern& pattern);

class KluFactorization {
 public:
  // Factorises the CSR matrix (pattern, values). Throws SolverError if singular.
  KluFactorization(const CsrPattern& pattern, std::span<const Real> values,
                   KluOrdering ordering = KluOrdering::Amd, KluSystem system = KluSystem::Uniform);
  ~KluFactorization();
  KluFactorization(const KluFactorization&) = delete;
  KluFactorization& operator=(const KluFactorization&) = delete;
  // Solves A x = b in place.
  void solve(std::span<Real> b);
  // New values on the same pattern (e.g. the geometry moved): keeps the symbolic analysis
  // (ordering) and the pivot sequence (klu_refactor); if the reused pivots give a poor
  // reciprocal condition estimate it factorises again with fresh pivoting, still reusing the
  // symbolic analysis. Throws SolverError if singular.
  void refactor(std::span<const Real> values);

  // Factorisations with fresh pivoting (the first included) and refactorisations that kept the
  // pivots; the entries of L + U (the fill).
  long fresh_factorizations() const;
  long refactorizations() const;
  long factor_entries() const;

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace rfmems

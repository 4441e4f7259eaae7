// Algebraic multigrid as a preconditioner: hypre's BoomerAMG (Henson & Yang 2002; Yang,
// "Parallel algebraic multigrid methods", 2006), one V-cycle from a zero guess per
// application, on a matrix whose rows are distributed over the ranks of a communicator.
//
// Why hypre and not PETSc's GAMG: the structure's Krylov solvers are SUNDIALS' (SPGMR in
// KINSOL and IDA) on SUNDIALS' MPI vector, so only a preconditioner is needed, and BoomerAMG
// is one through a small C interface (IJ matrix and vector, one solver object) with no
// object system or options database to adopt; it is MPI-native, in Debian (libhypre-dev),
// and treats systems of PDEs (several unknowns per cell) by the "unknown" approach: the
// strength of connection and the interpolation between like unknowns only (Stuben 2001),
// which is what elasticity and the plate need.
//
// The matrix need not be symmetric (the finite-volume stiffness is not): the V-cycle uses
// Gauss-Seidel smoothing (l1-hybrid, Baker et al. 2011), HMIS coarsening and extended+i
// interpolation truncated to 4 entries a row (De Sterck, Yang & Heys 2006), the settings
// hypre recommends for 3D problems on many ranks; it is a fixed linear operator, so plain
// (not flexible) GMRES can use it. Interpolating the rigid-body modes as well (hypre's GM-2
// variant with nodal coarsening) did not lower the iterations on the stocky 3D box (73 either
// way), but does on thin bodies: AmgOptions::rigid_body_points.
//
// hypre needs MPI initialised (rfmems' drivers and MPI tests construct an MpiSession); the
// serial communicator of a program without MPI is refused with a SolverError.
#pragma once
#include <memory>
#include <span>
#include <vector>

#include "core/system_operator.hpp"
#include "parallel/communicator.hpp"

namespace rfmems {

struct AmgOptions {
  // Unknowns per cell, interleaved (cell-major): the number of functions of a system of PDEs.
  int unknowns_per_cell = 1;
  // Strength of connection: hypre's advice for 3D problems, kept in 2D (0.25, its 2D advice,
  // took 15 times the iterations on the plane-stress cantilever).
  Real strong_threshold = 0.5;
  // Interpolation truncation (entries per row of P; 0: none).
  int max_interpolation_entries = 4;
  // Levels of aggressive coarsening at the top of the hierarchy: one halves the operator
  // complexity of the 3D box (2.04 against 3.21 on 160 x 16 x 16) for a few more iterations.
  int aggressive_levels = 1;
  // Elasticity of thin structures: the centroids of this rank's cells (one per
  // unknowns_per_cell rows, which are then the displacement components; empty: not used). The
  // interpolation then also fits the rigid-body rotations about the centroids' mean (hypre's
  // GM variant 2 on nodal coarsening, Baker, Kolev & Yang, Numer. Linear Algebra Appl. 17
  // (2010) 495), and aggressive_levels is ignored (with one aggressive level the rotations
  // saved a quarter of the iterations instead of three quarters, in a one-off trial).
  // Unknown-based interpolation reproduces translations but not rotations, the bending modes of
  // a thin body: the 3D strip of L/h = 60 (bench_amg_rigid_body_modes) took 1089 GMRES
  // iterations on 240 x 12 x 3 cells without, 294 with.
  std::vector<Vec3> rigid_body_points;
};

struct AmgStats {
  int levels = 0;
  // (sum of the non-zeros of every level's matrix) / (the finest's): the hierarchy's memory
  // and the V-cycle's cost relative to one matrix-vector product.
  Real operator_complexity = 0;
};

class BoomerAmg {
 public:
  // pattern: this rank's rows x its local columns; global_columns[j]: the global number of
  // local column j; this rank's rows are the global rows [first_row, first_row + n_rows).
  // The pattern is fixed for the object's life. Collective.
  BoomerAmg(const Communicator& comm, const CsrPattern& pattern, std::vector<Index> global_columns,
            Index first_row, const AmgOptions& options);
  // The whole matrix on this rank alone (its columns numbered as its rows).
  BoomerAmg(const CsrPattern& pattern, const AmgOptions& options);
  ~BoomerAmg();
  BoomerAmg(const BoomerAmg&) = delete;
  BoomerAmg& operator=(const BoomerAmg&) = delete;

  // Builds the hierarchy of the matrix with these values (in pattern order). Collective.
  void setup(std::span<const Real> values);
  // z = one V-cycle on A z = r from z = 0 (owned rows). r and z may alias. Collective.
  void apply(std::span<const Real> r, std::span<Real> z);
  // Collective.
  AmgStats stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The global numbers of a distributed system's local columns: the owned rows are numbered
// consecutively rank after rank, and each ghost column takes its owner's number through the
// system's own ghost exchange (`exchange` fills the ghost entries of a local-column vector).
template <class Exchange>
std::vector<Index> global_column_numbers(const Communicator& comm, Index n_owned, Index n_local,
                                         Index& first_row, const Exchange& exchange) {
  first_row = comm.exclusive_sum(n_owned);
  std::vector<Real> numbers(n_local, 0.0);  // exact in a double below 2^53
  for (Index i = 0; i < n_owned; ++i) numbers[i] = static_cast<Real>(first_row + i);
  exchange(std::span<Real>(numbers));
  return std::vector<Index>(numbers.begin(), numbers.end());
}

}  // namespace rfmems

// Electrostatics on the background mesh with an immersed conductor (thesis ch. 6:
// "the electrostatic field is solved on the background mesh"):
//
//   div(eps grad phi) = 0   on the FLUID cells,
//   phi = V_body            on the body's surface (an equipotential, through the IB faces),
//   per outer patch: phi = V or phi = field(x) (PotentialBoundary::potential), or zero flux.
//
// Cell-centred FV with the two-point flux F = eps |S| (phi_b - phi_P) / d_n on the interior and
// outer faces of a FLUID cell (d_n the normal distance from the centroid to the neighbour's
// centroid or to the face), so the background must be K-orthogonal (Cartesian, as the
// thesis's): there is no non-orthogonal correction. On an IB face the flux is
// eps |S| n . grad P(x_f), P the IB interpolation's least-squares fit (ib_interpolation.hpp)
// through the FLUID cell potentials and V_body at the wall points (or, as an option, the
// two-point difference to the fit's value P(x_f)). Those rows are implicit (the fit's weights go
// into the matrix), so one sparse LU solve (KLU) gives phi.
// The LU is kept between calls: while the matrix's sparsity pattern is unchanged (the FLUID
// set and the IB stencils change only on a re-marking that changes cell classes or stencils;
// a moving beam changes mostly the values) KLU refactors numerically on the kept symbolic
// analysis and pivot sequence (klu_refactor); a new pattern gets a fresh analysis.
// Exact for a field linear in the gap (a wide beam over a ground plane: the parallel-plate
// solution), since the interpolation and the two-point flux are exact for linear fields.
//
// Outputs: the flux into the body through each IB face (= the charge there, sigma |S|, since
// eps dphi/dn along the normal into the body is the surface charge of the conductor), the
// total charge, and the Maxwell force on the conductor per IB face, t = eps E_n^2 / 2 along the
// normal out of the body (the conductor is pulled into the field), ready for ForceTransfer.
// Reuses PotentialBoundary and the permittivity of lib/physics/electrostatics.
//
// Under MPI (distribute(comm)): the background is partitioned once, at the first
// solve's marking (background_partition.hpp, as the gas's); every rank marks and fits from the
// same global data (the caller's), assembles the rows of the FLUID cells it owns (global
// columns: the fits reach FLUID cells a few rings away, those are ghosts) and the ghost rows
// truncated to its columns (the overlap), and one GMRES solve with restricted additive
// Schwarz (KLU on the overlap, refactored while the pattern holds) gives the owned potential
// (solvers/distributed_linear_solve.hpp), to ||b - A phi||_2 <= 1e-13 ||b||_2 by default.
// The owned parts are then summed into the whole potential on every rank, and each rank
// computes every IB face's charge from it: the outputs are the same vectors on every rank, so
// the force transfer and the structure stay redundant. The initial guess is the last
// potential (a moving beam changes it little between solves).
#pragma once
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/system_operator.hpp"
#include "core/types.hpp"
#include "ibm/cell_marking.hpp"
#include "ibm/ib_interpolation.hpp"
#include "mesh/mesh.hpp"
#include "parallel/communicator.hpp"
#include "physics/electrostatics/electrostatic_boundary.hpp"
#include "solvers/distributed_linear_solve.hpp"

namespace rfmems {

// The flux through an IB face: the gradient of the interpolation's fit at the face
// (second order; the default), or the two-point difference (phi_f - phi_P) / d (first order
// at the face). Degree-0 faces (no gradient) always use the two-point difference.
enum class IbFaceFlux { FitGradient, TwoPoint };

// Factorisation per solve: Reuse keeps the symbolic analysis (and pivots) while the pattern is
// unchanged; Fresh analyses and factorises every call (the reference to check Reuse against).
enum class LuReuse { Reuse, Fresh };

class KluFactorization;

class ImmersedElectrostatics {
 public:
  // One boundary per background patch (Potential or ZeroFlux; InputError otherwise).
  ImmersedElectrostatics(const Mesh& background, std::map<std::string, PotentialBoundary> patches,
                         Real permittivity = kVacuumPermittivity,
                         IbFaceFlux ib_flux = IbFaceFlux::FitGradient,
                         LuReuse lu_reuse = LuReuse::Reuse);
  ~ImmersedElectrostatics();
  ImmersedElectrostatics(ImmersedElectrostatics&&) noexcept;

  // Solves on the FLUID cells of `marking` with the body at potential body_potential, the IB
  // faces' values from `interpolation` (built on the same marking).
  void solve(const CellMarking& marking, const IbInterpolation& interpolation, Real body_potential);

  // Per background cell (NaN outside the fluid).
  std::span<const Real> potential() const { return potential_; }
  // Per IB face (interpolation order): eps dphi/dn |S|, n into the body [C/m].
  std::span<const Real> ib_face_charge() const { return ib_face_charge_; }
  Real body_charge() const;
  // Per IB face: the electrostatic force on the body through that face [N/m].
  std::vector<Vec3> ib_face_forces() const;
  // Solves that analysed a new pattern (symbolic + numeric) and that refactored on the kept one.
  long analyses() const { return analyses_; }
  long refactorizations() const { return refactorizations_; }
  // Drops the kept LU; later solves follow `reuse`.
  void set_lu_reuse(LuReuse reuse);

  // The ranks the solve is distributed over (collective from then on: every rank of comm
  // calls solve together, with the same marking and fits); the serial communicator (the
  // default) keeps the KLU path. Drops what the previous path kept.
  void distribute(const Communicator& comm, const DistributedLinearOptions& options = {});
  bool distributed() const { return !comm_.is_serial(); }
  // Distributed: the last solve's GMRES statistics and the iterations of all solves.
  const DistributedLinearStats& last_krylov() const { return last_krylov_; }
  long krylov_iterations() const { return krylov_iterations_; }

 private:
  struct Distributed;
  bool uses_gradient(const IbInterpolation& ib, Index k) const;
  // Row of FLUID cell P: emit(background cell, coefficient) per matrix entry, in the serial
  // assembly order; returns the row's right-hand side.
  template <class Emit>
  Real assemble_row(Index P, const CellMarking& marking, const IbInterpolation& ib,
                    std::span<const Index> ib_of_face, Real body_potential, Emit&& emit) const;
  void solve_serial(const CellMarking& marking, const IbInterpolation& ib,
                    std::span<const Index> ib_of_face, Real body_potential);
  void solve_distributed(const CellMarking& marking, const IbInterpolation& ib,
                         std::span<const Index> ib_of_face, Real body_potential);
  const Mesh& mesh_;
  Real permittivity_;
  IbFaceFlux ib_flux_;
  std::vector<PotentialBoundary> boundary_;  // per patch
  std::vector<Real> potential_, ib_face_charge_;
  std::vector<Vec3> ib_face_normal_;
  std::vector<Real> ib_face_area_;
  LuReuse lu_reuse_;
  CsrPattern pattern_;  // of lu_
  std::unique_ptr<KluFactorization> lu_;
  long analyses_ = 0, refactorizations_ = 0;
  Communicator comm_ = Communicator::serial();
  DistributedLinearOptions krylov_options_;
  std::unique_ptr<Distributed> distributed_;
  DistributedLinearStats last_krylov_;
  long krylov_iterations_ = 0;
};

}  // namespace rfmems

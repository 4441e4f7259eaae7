// Cell-centred FV electrostatics in the gap of an RF MEMS switch (thesis secs. 2.3-2.5):
//
//     div(eps grad phi) = -rho     in the gap (2D, unit depth, or 3D); eps uniform,
//
// with per-patch boundary conditions (electrostatic_boundary.hpp). Unknowns: phi per cell,
// plus the potential of each floating conductor (its row: total charge = Q).
//
// Face flux F_f = eps grad phi . S_f (outward from the owner P) on a possibly skewed,
// moving mesh. With p_c the least-squares polynomial of cell c (fv/polynomial_reconstruction,
// degree 1 or 2; Dirichlet faces carry their value, zero-flux faces a mirror image):
//
//   interior  F_f = eps |S| [ n . (grad p_P + grad p_N)(x_f) / 2 + (p_N(x_f) - p_P(x_f)) / d_n ]
//   boundary  F_f = eps |S| [ n . grad p_P(x_f)                  + (phi_b    - p_P(x_f)) / d_n ]
//
// with n = S/|S| and d_n the normal distance between the centroids (boundary: centroid to
// face). Written as (phi_N - phi_P)/d_n plus corrections, this is the two-point flux along
// the normal distance plus a non-orthogonal (and skewness) correction from the cell
// gradients, kept implicit: the matrix holds the whole reconstruction stencil, so one
// factorisation solves the linear problem exactly and no deferred-correction iterations are
// needed. Exact for linear phi on any mesh (degree >= 1); the face flux is second-order for
// degree 2 (every term is evaluated at the face centroid), first-order for degree 1 on
// irregular meshes. On an orthogonal uniform mesh with degree 1 it reduces to the two-point
// flux. Degree 0 gives the uncorrected two-point flux (for comparison only).
//
// The matrix is factorised with KLU; when the geometry moves and the sparsity pattern is
// unchanged the symbolic analysis is reused (KluFactorization::refactor).
//
// Outputs on a patch (the moving electrode = the beam's bottom face):
//   sigma = eps dphi/dn = F_f / |S_f|  (n out of the gap: the charge on the conductor),
//   E on the face: normal part -dphi/dn n from the flux; tangential part 0 on a conductor
//   (equipotential: constant potential or floating), else from grad p_P(x_f),
//   traction on the body beyond the face (Maxwell stress): t = -eps (E (E.n) - |E|^2/2 n),
//   which on a conductor is t = -eps |E|^2/2 n: the conductor is pulled into the gap.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/system_operator.hpp"
#include "mesh/mesh.hpp"
#include "physics/electrostatics/electrostatic_boundary.hpp"

namespace rfmems {

class PolynomialReconstruction;
class KluFactorization;

struct ElectrostaticsOptions {
  Real permittivity = kVacuumPermittivity;  // F/m
  // Least-squares reconstruction degree of the face gradient: 2 (default), 1, or 0 (plain
  // two-point flux, no non-orthogonal correction).
  int reconstruction_degree = 2;
};

// Charge and electrostatic load on the faces of one patch (boundary face order).
struct SurfaceLoad {
  std::vector<Index> faces;
  std::vector<Real> charge_density;  // sigma [C/m^2]
  std::vector<Vec3> field;           // E at the face [V/m]
  std::vector<Vec3> traction;        // on the body beyond the face [Pa]
  Vec3 force = Vec3::Zero();         // sum t |S| [N] (2D: N per metre of depth)
  Real charge = 0;                   // sum sigma |S| [C] (2D: C/m)
};

struct ElectrostaticSolveStats {
  Index n_unknowns = 0, nnz = 0;
  bool symbolic_reused = false;  // the last solve refactorised on the previous pattern
  double assembly_seconds = 0, factor_seconds = 0, solve_seconds = 0;
};

class ElectrostaticSolver {
 public:
  // One boundary per mesh patch (InputError on a missing or unknown patch); at least one
  // patch must hold a potential.
  ElectrostaticSolver(const Mesh& mesh, std::map<std::string, PotentialBoundary> boundaries,
                      ElectrostaticsOptions options = {});
  ~ElectrostaticSolver();
  ElectrostaticSolver(const ElectrostaticSolver&) = delete;
  ElectrostaticSolver& operator=(const ElectrostaticSolver&) = delete;

  // Assembles on the mesh's current geometry (call again after the mesh moved) and solves.
  // charge_density: rho(x) [C/m^3] (midpoint rule per cell); empty = Laplace.
  void solve(const std::function<Real(const Vec3&)>& charge_density = {});

  std::span<const Real> potential() const;  // per cell [V]
  // The potential of a conductor patch: the prescribed V, or the solved floating potential.
  Real patch_potential(const std::string& patch) const;
  // eps grad phi . S_f outward from the owner of face f [C] (2D: C/m).
  Real face_flux(Index f) const { return face_flux_.at(f); }
  SurfaceLoad surface_load(const std::string& patch) const;
  const ElectrostaticSolveStats& stats() const { return stats_; }

 private:
  struct Form;
  void add_point_value(Form& form, Index point_face, Index point_cell, bool is_face,
                       Real coefficient) const;
  void add_reconstruction(Form& form, Index c, const Vec3& x, Real value_coefficient,
                          const Vec3& gradient_coefficient) const;
  Real boundary_value(Index f) const;
  Vec3 reconstructed_gradient(Index c, const Vec3& x) const;
  int patch_of(const std::string& name) const;

  const Mesh& mesh_;
  ElectrostaticsOptions options_;
  std::vector<PotentialBoundary> boundary_;  // per patch
  std::vector<Index> floating_unknown_;      // per patch: unknown index, or -1
  Index n_unknowns_ = 0;
  std::unique_ptr<PolynomialReconstruction> reconstruction_;
  std::vector<Real> solution_;
  std::vector<Real> face_flux_;
  CsrPattern pattern_;
  std::unique_ptr<KluFactorization> lu_;
  ElectrostaticSolveStats stats_;
};

}  // namespace rfmems

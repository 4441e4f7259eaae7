// Cell-centred finite-volume linear elasticity (thesis ch. 2; Demirdzic & Muzaferija 1994),
// 2D (plane stress / plane strain) and 3D:
//
//   rho u'' = div sigma + b,   sigma = mu (grad u + grad u^T) + lambda tr(grad u) I.
//
// Unknowns: the displacement at cell centroids, interleaved (cell * dim + component).
// Cell balance: M u'' + R(t, u) = 0 with M = rho V and R_P = -sum_f sigma_f S_f - b V.
// Face gradient from the polynomial reconstructions p_P, p_N of both cells (cubic by default,
// see fv/polynomial_reconstruction.hpp):
//   interior:  G_f = (grad p_P + grad p_N)(x_f)/2 + (p_N(x_f) - p_P(x_f)) e^T / |d|
//   fixed:     G_f = grad p_P(x_f) + (u_b - p_P(x_f)) e^T / |d|
//   symmetry:  G_f = grad p_P(x_f) - (n n^T p_P(x_f)) e^T / |d|, force projected on n
//              (mirror images of the cell enter the reconstructions)
//   traction:  the force is the prescribed traction times the face area.
// The jump term is the compact "primary" coupling (u_N - u_P)/|d| plus its high-order
// correction; with linear reconstruction this is the classical scheme of the thesis.
//
// Residual stress (material.residual_stress, physics/structure/residual_stress.hpp): the face
// force is the first Piola-Kirchhoff traction to first order, sigma_f S + G_f sigma0 S, where
// sigma0 S itself (in equilibrium) is left out: the geometric stiffness of the prestress.
//
// Jacobian: the full linearisation of the stress tensor (thesis "Formulation 2"): the
// transpose and trace terms and the reconstruction stencils all enter dR/du exactly, so a
// linear static problem converges in one Newton step.
//
// Large deformations (set_geometric_nonlinearity; model.geometric_nonlinearity): total
// Lagrangian on the reference mesh, F = I + G, the Green-Lagrange strain E = (F^T F - I)/2 and
// the St Venant-Kirchhoff second Piola-Kirchhoff stress S = lambda tr(E) I + 2 mu E (in plane
// stress with the reduced lambda*, which for this material is exact: S_zz = 0 fixes E_zz). The
// face force is the first Piola-Kirchhoff traction on the reference face, P S_f = F S S_f, plus
// the prestress's G sigma0 S_f as above; loads are dead (tractions per reference area, body
// forces per reference volume). With G_f = a h^T for the unknowns a of one stencil term,
//   d(P S_f)/da = (h.(S + sigma0) S_f) I + lambda (F S_f)(F h)^T + mu (h.S_f) F F^T
//                 + mu (F h)(F S_f)^T
// (at G = 0 the linear block). The Kelvin-Voigt damping keeps the stiffness at rest.
#pragma once
#include <memory>
#include <vector>

#include "core/linear_functional.hpp"
#include "core/system_operator.hpp"
#include "fv/block_sparsity.hpp"
#include "fv/polynomial_reconstruction.hpp"
#include "materials/linear_elastic.hpp"
#include "mesh/mesh.hpp"
#include "physics/elasticity/elasticity_boundary.hpp"

namespace rfmems {

class ElasticityOperator : public SecondOrderOperator {
 public:
  // boundaries[p] applies to mesh patch p. body_force is per unit volume (may be empty).
  // reconstruction_degree: 1 (linear, the thesis's scheme), 2 or 3; 0 picks the default for
  // the mesh: cubic in 2D (removes the bending error of thin parts), quadratic in 3D (the 3D
  // cubic stencils admit a near-singular bending mode on hexahedral beams, measured on 60x6x6).
  ElasticityOperator(const Mesh& mesh, const LinearElastic& material,
                     std::vector<ElasticityBoundary> boundaries, VectorField body_force = {},
                     int reconstruction_degree = 0);
  // The degree used when 0 is asked for.
  static int default_reconstruction_degree(int dim) { return dim == 2 ? 3 : 2; }

  Index size() const override { return mesh_.n_cells() * dim_; }
  int dim() const { return dim_; }
  // The unknown of displacement component d of a cell (the layout: u_x, u_y[, u_z] per cell),
  // and the one across a gap below the body: its last component (u_y in a plane, u_z in 3D).
  Index unknown(Index cell, int d) const { return cell * dim_ + d; }
  Index gap_unknown(Index cell) const { return unknown(cell, dim_ - 1); }
  const Mesh& mesh() const { return mesh_; }
  const LinearElastic& material() const { return material_; }
  const std::vector<ElasticityBoundary>& boundaries() const { return boundaries_; }
  const VectorField& body_force() const { return body_force_; }
  // The degree asked for (0: the default), to build the same operator on another mesh.
  int requested_reconstruction_degree() const { return requested_degree_; }

  void internal_residual(Real t, std::span<const Real> u, std::span<Real> r) override;
  // Built on first use (a matrix-free solve never builds it).
  const CsrPattern& stiffness_pattern() const override { return sparsity().pattern(); }
  void stiffness(Real t, std::span<const Real> u, std::span<Real> values) override;
  std::vector<Real> mass_diagonal() const override;

  // Kelvin-Voigt damping sigma = C : (eps + beta eps'), i.e. C = beta K (the stiffness at
  // homogeneous boundary data). Its purpose here is numerical: the cell-centred stiffness is
  // not symmetric, and near clamped and free faces a few of its grid-scale modes form complex
  // pairs that grow (docs/immersed_switch.md, "Grid damping"); beta damps them at a rate beta
  // omega^2 / 2, while the bending modes, 1e2-1e4 times slower, keep damping ratios beta omega / 2
  // of 1e-5 (the switches' meshes) to 4e-4 (a coarse 3D beam).
  Real damping_time() const override { return damping_time_; }
  // Large deformations (see above); off by default.
  void set_geometric_nonlinearity(bool on) { nonlinear_ = on; }
  bool geometric_nonlinearity() const { return nonlinear_; }
  void set_damping_time(Real beta) { damping_time_ = beta; }
  void add_damping_force(Real t, std::span<const Real> v, std::span<Real> r) override;
  // K v: the residual's homogeneous part, where R is affine in u (small deformations).
  bool has_stiffness_product() const override { return !nonlinear_; }
  void stiffness_product(Real t, std::span<const Real> u, std::span<const Real> v,
                         std::span<Real> kv) override;
  // The beta that gives damping ratio zeta at the grid's highest frequency omega_h = 2 c_p /
  // h_min (P-wave speed c_p = sqrt((lambda + 2 mu) / rho), h_min the smallest distance between
  // neighbouring centroids): beta = 2 zeta / omega_h. 0 without a density.
  Real grid_damping_time(Real zeta) const;

  // Least-squares displacement gradient of every cell.
  std::vector<Mat3> cell_gradients(Real t, std::span<const Real> u) const;
  // Displacement at point x from the nearest cell's linear reconstruction.
  Vec3 displacement_at(Index cell, const Vec3& x, std::span<const Real> u,
                       const std::vector<Mat3>& gradients) const;
  // displacement_at's component k as a linear functional of the unknowns (a tip deflection
  // that a run reports, controls and finds the velocity of): prescribed boundary values, which
  // enter only cells next to a Dirichlet patch, are taken as 0, as at a clamp.
  LinearFunctional displacement_functional(Index cell, const Vec3& x, int component) const;

  // The centroid gradient of cell_gradients() as a linear map of the unknowns (for analytic
  // Jacobians of terms that use the cell's strain, e.g. creep):
  //   G_c = G_b(t) + sum_terms (map u_cell) weight^T,
  // G_b from prescribed boundary values (independent of u); map is I, or the reflection of a
  // mirror image across a symmetry face. A cell may appear in several terms.
  struct GradientTerm {
    Index cell;
    Mat3 map;
    Vec3 weight;
  };
  std::vector<GradientTerm> centroid_gradient_terms(Index c) const;
  // The face gradients G_f of the face forces (see above) of every face at the state (zero on
  // traction faces, which have none), and one face's as a linear map of the unknowns:
  //   G_f = G_b(t) + sum_terms (map u_cell) weight^T
  // (empty on a traction face). For terms whose prestress is not sigma0 (the creep relaxation
  // of the residual stress). Small deformations.
  std::vector<Mat3> face_gradients(Real t, std::span<const Real> u) const;
  std::vector<GradientTerm> face_gradient_terms(Index f) const;

  // The implicit "primary" part of each displacement component (segregated formulation):
  // kappa (e.S)/|d| per face, Dirichlet faces on the diagonal, symmetry faces on the
  // diagonal of the normal component. Returns (pattern, values) of component k.
  void primary_matrix(int k, Real kappa, CsrPattern& pattern, std::vector<Real>& values) const;

 private:
  struct Term {
    Index cell;
    Mat3 T;  // acts on u_cell
    Vec3 h;  // G_f += (T u_cell) h^T
  };
  // Evaluation weights of one cell's reconstruction at one face centroid.
  struct FaceSide {
    Index cell;
    Index begin, end;  // into side_value_ / side_gradient_, parallel to the cell's points
  };
  const FaceSide& side(Index f, int which) const { return sides_[2 * f + which]; }
  // Value of a stencil point and the matrix that maps its source cell's u to it.
  Vec3 point_value(const StencilPoint& p, Real t, std::span<const Real> u) const;
  Mat3 point_map(const StencilPoint& p) const;
  // Fills point_delta_ with v_j - u_c for every stencil point of every cell (homogeneous:
  // prescribed boundary values taken as 0).
  void compute_point_deltas(Real t, std::span<const Real> u, bool homogeneous = false) const;
  // r += scale * R(t, u); homogeneous: without boundary data, tractions and body force (K u).
  void add_internal_forces(Real t, std::span<const Real> u, bool homogeneous, Real scale,
                           std::span<Real> r) const;
  // p_c(x_f) and grad p_c(x_f) for one face side (after compute_point_deltas).
  void evaluate_side(const FaceSide& s, std::span<const Real> u, Vec3& value, Mat3& gradient) const;
  // Linear terms of G_f from one side: grad_factor * grad p + value_factor * value_map p e^T.
  void append_side_terms(const FaceSide& s, Real grad_factor, Real value_factor,
                         const Mat3& value_map, const Vec3& e, std::vector<Term>& terms) const;
  Vec3 cell_u(std::span<const Real> u, Index c) const;
  // The Jacobian's block sparsity: each cell's stencil is the cells its face forces use.
  const BlockSparsity& sparsity() const;
  // Face force sigma_f S_f + G sigma0 S_f for face f given the face gradient; with large
  // deformations (and not homogeneous) F S S_f + G sigma0 S_f.
  Vec3 face_force(const Mat3& G, const Vec3& S, bool homogeneous = false) const;
  // The Green-Lagrange strain's second Piola-Kirchhoff stress of a displacement gradient.
  Mat3 second_piola_kirchhoff(const Mat3& G) const;
  // The face gradient G_f of boundary or interior face f (after compute_point_deltas); false
  // for a traction face, which has none.
  bool face_gradient(Index f, Real t, std::span<const Real> u, bool homogeneous, Mat3& G) const;

  const Mesh& mesh_;
  LinearElastic material_;
  std::vector<ElasticityBoundary> boundaries_;
  VectorField body_force_;
  int dim_;
  int requested_degree_;
  Real mu_, lambda_;
  std::unique_ptr<PolynomialReconstruction> reconstruction_;
  mutable std::unique_ptr<BlockSparsity> sparsity_;
  std::vector<FaceSide> sides_;  // two per face (the second unused on boundaries)
  std::vector<Real> side_value_;
  std::vector<Vec3> side_gradient_;
  std::vector<Index> point_offset_;        // per cell, into its stencil points (and deltas)
  mutable std::vector<Vec3> point_delta_;  // scratch: v_j - u_c
  std::vector<Vec3> centroid_gradient_;    // parallel to the stencil points
  std::vector<Vec3> face_e_;               // unit vector P -> N (or P -> face centroid)
  std::vector<Real> face_d_;               // |d|
  Real damping_time_ = 0;                  // beta of the Kelvin-Voigt damping
  bool nonlinear_ = false;                 // large deformations
};

}  // namespace rfmems

// Cell-centred finite-volume linear elasticity (thesis ch. 2; Demirdzic & Muzaferija 1994),
// 2D (plane stress / plane strain) and 3D:
//
//   rho u'' = div sigma + b,   sigma = mu (grad u + grad u^T) + lambda tr(grad u) I.
//
// Unknowns: the displacement at cell centroids, interleaved (cell * dim + component).
// Cell balance: M u'' + R(t, u) = 0 with M = rho V and R_P = -sum_f sigma_f S_f - b V.
// Face gradient: G_f = Gbar (I - e e^T) + (u_N - u_P)/|d| e^T, Gbar interpolated from
// least-squares cell gradients: the compact difference along the centroid line (the primary
// part) plus the non-orthogonal (secondary) part. On a fixed or symmetry face the normal
// derivative is 2 (u_b - u_P)/|d| - G_P e (second order; G_P is a quadratic fit there).
//
// Jacobian: the full linearisation of the stress tensor (thesis "Formulation 2"): the
// transpose and trace terms and the secondary gradients all enter dR/du through the stencil
// of the least-squares gradients (both cells of a face and their face neighbours), so a linear
// static problem converges in one Newton step.
#pragma once
#include <memory>
#include <vector>

#include "core/system_operator.hpp"
#include "fv/block_sparsity.hpp"
#include "fv/least_squares_gradient.hpp"
#include "materials/linear_elastic.hpp"
#include "mesh/mesh.hpp"
#include "physics/elasticity/elasticity_boundary.hpp"

namespace rfmems {

class ElasticityOperator : public SecondOrderOperator {
 public:
  // boundaries[p] applies to mesh patch p. body_force is per unit volume (may be empty).
  ElasticityOperator(const Mesh& mesh, const LinearElastic& material,
                     std::vector<ElasticityBoundary> boundaries, VectorField body_force = {});

  Index size() const override { return mesh_.n_cells() * dim_; }
  int dim() const { return dim_; }
  const Mesh& mesh() const { return mesh_; }
  const LinearElastic& material() const { return material_; }

  void internal_residual(Real t, std::span<const Real> u, std::span<Real> r) override;
  const CsrPattern& stiffness_pattern() const override { return sparsity_->pattern(); }
  void stiffness(Real t, std::span<const Real> u, std::span<Real> values) override;
  std::vector<Real> mass_diagonal() const override;

  // Least-squares displacement gradient of every cell.
  std::vector<Mat3> cell_gradients(Real t, std::span<const Real> u) const;
  // Displacement at point x from the nearest cell's linear reconstruction.
  Vec3 displacement_at(Index cell, const Vec3& x, std::span<const Real> u,
                       const std::vector<Mat3>& gradients) const;

  // The implicit "primary" part of each displacement component (segregated formulation):
  // kappa (e.S)/|d| per face, Dirichlet faces on the diagonal, symmetry faces on the
  // diagonal of the normal component. Returns (pattern, values) of component k.
  void primary_matrix(int k, Real kappa, CsrPattern& pattern, std::vector<Real>& values) const;

 private:
  struct Term {
    Index cell;
    Mat3 T;   // acts on u_cell
    Vec3 h;   // G_f += (T u_cell) h^T
  };
  // Linear terms of the gradient of cell c (without the constant Dirichlet part).
  void append_cell_gradient_terms(Index c, const Mat3& project, Real scale,
                                  std::vector<Term>& terms) const;
  Vec3 boundary_value(Index f, Real t, std::span<const Real> u) const;
  Vec3 cell_u(std::span<const Real> u, Index c) const;
  // Face force sigma_f S_f for face f given the face gradient.
  Vec3 face_force(const Mat3& G, const Vec3& S) const;

  const Mesh& mesh_;
  LinearElastic material_;
  std::vector<ElasticityBoundary> boundaries_;
  VectorField body_force_;
  int dim_;
  Real mu_, lambda_;
  std::unique_ptr<LeastSquaresGradient> gradient_;
  std::unique_ptr<BlockSparsity> sparsity_;
  std::vector<Real> owner_weight_;  // interior faces
  std::vector<Vec3> face_e_;        // unit vector P -> N (or P -> face centroid on a boundary)
  std::vector<Real> face_d_;        // |d|
};

}  // namespace rfmems

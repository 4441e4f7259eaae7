// Linear least-squares cell gradients (Barth; Mavriplis 2003), in stencil form:
//
//   grad(phi)_P = sum_j g_j (phi_j - phi_P),   g_j = w_j M^{-1} d_j,   M = sum_j w_j d_j d_j^T,
//
// with d_j = x_j - x_P and inverse-distance-squared weights w_j = 1/|d_j|^2. The neighbours j
// are the face-neighbour cells and the boundary faces whose values the physics supplies
// (Dirichlet, symmetry); boundary faces left out (traction) are extrapolated implicitly, which
// leaves the fit unchanged. Storing g_j lets an operator both evaluate the gradient and
// differentiate it exactly (the analytic Jacobian).
//
// Cells that touch the boundary use a quadratic fit over two rings of neighbours instead:
// their linear stencil is one-sided, which makes the gradient only first-order accurate
// there; in bending this error acts as a spurious couple at free edges that grows like
// (cell length / thickness)^2. The quadratic fit keeps the gradient exact for quadratic
// fields (pure bending) and the stencil form unchanged.
#pragma once
#include <functional>
#include <span>
#include <vector>

#include "mesh/mesh.hpp"

namespace rfmems {

struct GradientNeighbour {
  Index face;  // the face crossed to reach the neighbour
  Index cell;  // neighbour cell, or -1 for a boundary-face value (then `face` is that face)
  Vec3 weight; // g_j
};

class LeastSquaresGradient {
 public:
  // uses_boundary_face(f) tells whether boundary face f carries a value for the fit.
  LeastSquaresGradient(const Mesh& mesh, const std::function<bool(Index)>& uses_boundary_face);
  std::span<const GradientNeighbour> neighbours(Index c) const {
    return {list_.data() + offsets_[c], static_cast<std::size_t>(offsets_[c + 1] - offsets_[c])};
  }
  // Sum of the weights of cell c (the coefficient of -phi_P).
  const Vec3& weight_sum(Index c) const { return weight_sum_[c]; }

 private:
  std::vector<Index> offsets_{0};
  std::vector<GradientNeighbour> list_;
  std::vector<Vec3> weight_sum_;
};

// Linear interpolation weight of the owner at an interior face: the face value is
// lambda phi_P + (1 - lambda) phi_N, lambda from the projection of x_f on the centroid line.
Real owner_interpolation_weight(const Mesh& mesh, Index f);

}  // namespace rfmems

// The von Karman plate: the Mindlin-Reissner plate (plate_operator.hpp) with moderately large
// deflections, its mid-surface free to stretch (Timoshenko & Woinowsky-Krieger, Theory of
// Plates and Shells, ch. 13; von Karman 1910). The in-plane displacements u = (u, v) join the
// unknowns, and with the membrane strain and force
//
//   eps = sym(grad u) + 1/2 grad w (x) grad w
//   N   = N0 + A : eps,   A : eps = E h / (1 - nu^2) [(1 - nu) eps + nu tr(eps) I]
//
// (N0 = h sigma0, the residual stress the plate operator already carries) the balances become
//
//   rho h u''  = div N                                 (in-plane)
//   rho h w''  = div Q + div(N grad w) + q             (transverse)
//
// with the bending and shear of the plate operator unchanged (small rotations of the normal).
// Discretised on the same cells, face by face:
//   R_u += -sum_f (A : eps_f) S_f,        R_w += -sum_f ((A : eps_f) grad w_f) . S_f
// (the N0 parts are the plate operator's: N0 S_f sums to zero over a closed cell, and
// N0 grad w is its geometric stiffness). The face gradients of u and w both come from one
// polynomial reconstruction (the plate's degree) with the face formula of the plate operator:
//   interior: grad phi_f = (grad p_P + grad p_N)(x_f)/2 + (p_N(x_f) - p_P(x_f)) e/|d|
//   given:    grad phi_f = grad p_P(x_f) + (phi_b - p_P(x_f)) e/|d|
// so grad phi_f is a fixed linear map of the cell values, built once.
//
// Boundary conditions: an edge that holds the deflection (clamped, simply supported,
// displacement) is immovable in-plane, u = 0, unless it is released in-plane
// (PlateBoundary::in_plane_free); a released, free or loaded edge carries no membrane force,
// N n = 0 (which is why the residual stress must vanish across it). The face gradients of w and
// u then come from two reconstructions, each with its own given boundary values.
//
// Unknowns: the plate's (w, beta_x, beta_y) per cell first, as the plate operator numbers them
// (so y[3c] is still w of cell c), then (u, v) per cell: y[3 n + 2c], y[3 n + 2c + 1].
// Mass: rho h A on u and v. In-plane waves (speed sqrt(E/rho)) are far faster than bending
// waves in a thin plate, so like the rotary inertia the in-plane inertia is one a transient or
// a modal analysis may neglect (quasi_static_components()).
//
// Jacobian: exact. With a_k the face-gradient weight of cell k,
//   d(A:eps_f)/dw_k = mu (a_k gw^T + gw a_k^T) + lambda (a_k.gw) I
//   d(A:eps_f)/du_k = mu (e_i a_k^T + a_k e_i^T) + lambda a_k,i I     (component i)
// and d(N gw . S)/dy = (dN gw + N dgw) . S; the plate's own part is constant.
#pragma once
#include <array>
#include <memory>
#include <span>
#include <vector>

#include "physics/plate/plate_operator.hpp"

namespace rfmems {

class VonKarmanPlate : public SecondOrderOperator {
 public:
  // The plate operator supplies the bending, shear, loads and residual stress; it must outlive
  // this operator.
  explicit VonKarmanPlate(PlateOperator& plate);

  Index size() const override { return 5 * mesh_.n_cells(); }
  const PlateOperator& plate() const { return plate_; }
  PlateOperator& plate() { return plate_; }
  // The index of cell c's in-plane displacement component i (0: u, 1: v).
  Index in_plane_index(Index c, int i) const { return 3 * mesh_.n_cells() + 2 * c + i; }

  void internal_residual(Real t, std::span<const Real> y, std::span<Real> r) override;
  const CsrPattern& stiffness_pattern() const override { return pattern_; }
  void stiffness(Real t, std::span<const Real> y, std::span<Real> values) override;
  std::vector<Real> mass_diagonal() const override;
  // The plate's rotations and the in-plane displacements (see above).
  std::vector<bool> quasi_static_components() const;

  // Membrane force A : eps (without N0) per cell from the least-squares average of its faces'
  // values (N_xx, N_yy, N_xy in a Mat3, 2 x 2 used), for output.
  std::vector<Mat3> membrane_forces(Real t, std::span<const Real> y) const;

  // The face gradients, for a model that adds its own membrane force on the same faces (the
  // plate creep system's plastic membrane force). Membrane face k (0 <= k <
  // n_membrane_faces()) is mesh face membrane_face(k): the interior faces and the edges held
  // in-plane. grad w_f = sum over face_weights(k) of w times w of `cell` (>= 0) or the
  // prescribed w at boundary face `face` (cell < 0); grad u_f the same with u (u_b = 0).
  struct GradientWeight {
    Index cell;
    Index face;
    Vec3 w, u;
  };
  struct FaceState {
    Vec3 gw;  // grad w_f
    Mat3 gu;  // grad u_f (rows u, v)
    Mat3 N;   // A : eps_f
  };
  Index n_membrane_faces() const { return static_cast<Index>(faces_.size()); }
  Index membrane_face(Index k) const { return faces_[k]; }
  std::span<const GradientWeight> face_weights(Index k) const {
    return std::span<const GradientWeight>(weights_).subspan(offset_[k],
                                                             offset_[k + 1] - offset_[k]);
  }
  FaceState face_state(Index k, Real t, std::span<const Real> y) const;
  // The prescribed deflection at boundary face `face` at t (0 on clamped and free edges).
  Real boundary_w(Index face, Real t) const;

 private:
  Mat3 membrane(const Mat3& eps) const;

  PlateOperator& plate_;
  const Mesh& mesh_;
  Real mu_, lambda_;  // the membrane's E h / (2 (1 + nu)) and E h nu / (1 - nu^2)
  std::unique_ptr<PolynomialReconstruction> w_rec_, own_u_rec_;  // u's when they differ
  std::vector<Index> offset_{0};
  std::vector<GradientWeight> weights_;
  std::vector<Index> faces_;  // the faces that carry a membrane force

  CsrPattern pattern_;
  std::vector<Index> plate_position_;  // the plate stiffness's entries in pattern_
  // Per face weight (cell >= 0) and side (owner, neighbour): the positions of the 3 x 3 block
  // (rows w, u, v of the side's cell; columns w, u, v of the weight's cell); -1: no neighbour.
  std::vector<std::array<Index, 9>> block_position_;
  std::vector<Index> block_of_weight_;  // 2 per weight, into block_position_
  std::vector<Real> plate_values_;
};

}  // namespace rfmems

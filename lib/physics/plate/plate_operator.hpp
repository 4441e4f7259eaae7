// Cell-centred finite-volume Mindlin-Reissner plate (thesis ch. 3) on a 2D mesh of the
// mid-surface, thickness h implied:
//
//   rho h w''           = div Q + q                     (force along z)
//   rho h^3/12 beta''   = div M - Q                     (moments about the mid-surface)
//   M = D [ (1-nu)/2 (grad beta + grad beta^T) + nu div(beta) I ],   D = E h^3/(12(1-nu^2))
//   Q = k G h gamma,  gamma = grad w + beta                          (k = 5/6 by default)
//
// Kinematics u = z beta_x, v = z beta_y, so the Kirchhoff (thin) limit is beta = -grad w and
// M_xx = -D (w_xx + nu w_yy) is positive for a sagging plate (Timoshenko's sign).
//
// Unknowns per cell, interleaved: y[3c] = w, y[3c+1] = beta_x, y[3c+2] = beta_y.
// Cell balances M y'' + R(t, y) = 0, mass rho h A (w) and rho h^3/12 A (beta):
//   R_w    = -sum_f Q_f.S_f - q A
//   R_beta = -sum_f M_f S_f + sum_f (x_f - x_c) (Q_f.S_f)     (the second sum is  Q_c A)
//
// Bending: the face gradient of beta from the polynomial reconstructions p_P, p_N (cubic by
// default; fv/polynomial_reconstruction.hpp), exactly as in the elasticity operator:
//   interior: G_f = (grad p_P + grad p_N)(x_f)/2 + (p_N(x_f) - p_P(x_f)) e^T/|d|
//   beta prescribed: G_f = grad p_P(x_f) + (beta_b - p_P(x_f)) e^T/|d|
//
// Transverse shear, built so that it cannot lock. The discrete shear strain of a face is the
// mean of gamma.e along the segment P -> N (P -> x_f on a boundary), which for any field is
//   gamma_e = (w_N - w_P)/|d| + mean(beta).e          (the w part is exact: no gradient)
// with mean(beta) by Simpson's rule from beta_P, beta_N and the reconstructed beta at the
// segment midpoint (exact for cubic beta). A field with gamma_e = 0 on every face is a discrete
// Kirchhoff field; the constraint count (one per face, ~2 per cell against 3 unknowns) leaves
// those fields as rich as the deflections themselves, which is what removes locking. The face
// shear force Q_f.S_f = k G h (alpha gamma_e + gamma_f.k_f) splits S_f = alpha e + k_f
// (over-relaxed; k_f = 0 on orthogonal faces), and the tangential part uses the cell shear
// strain gamma_c, a least-squares fit of the face values gamma_e of its faces (and of the
// prescribed Q.n of its load/free faces). The moment source Q_c A is the divergence-consistent
// sum_f (x_f - x_c)(Q_f.S_f), exact for constant Q. So every shear term in every equation is
// a linear combination of the face strains gamma_e: a discrete Kirchhoff field carries no
// shear, and as h -> 0 the face shear forces become the Lagrange multipliers of the
// constraints instead of amplifying their error by (L/h)^2.
//
// Boundary faces (see plate_boundary.hpp): where w is prescribed, gamma_e uses w_b and the
// face rotation beta_b (prescribed, or extrapolated p_P(x_f) for the free components of a
// simple support); where the shear force is prescribed, Q.S = Q_n |S|. Moments: prescribed
// rotations enter the gradient formula above; a hard simple support keeps only the tangential
// component t t^T (M S) (reaction) with M_nn = 0; soft supports, free and loaded edges apply
// the prescribed M n |S|.
//
// Why Simpson: with the trapezoid mean (beta_P + beta_N)/2 the constraint integrates beta with
// an O(d^2) error that shows up as a (d/L)^2/4 error in a cantilever's tip deflection (1 % on
// 5 x 5 cells); Simpson's is exact for the beam-with-shear solution, which the cubic scheme
// then reproduces to round-off. Why the geometric lever x_f - x_c rather than the transpose
// of the constraint (which would make the shear part of K symmetric): measured on the clamped
// square, the transpose is 2-3 times less accurate (1.2636 against 1.2660 on 40 x 40, exact
// 1.2653) and no longer exact for the cantilever; its only gain was dynamic (below).
//
// Dynamics. The rotary inertia gives ~2N thickness-shear modes near sqrt(12 k G/rho)/h
// (5.5e9 rad/s for h = 2 um), undamped: with a step load an adaptive integrator resolves them
// (IDA steps of 1e-11 s); use ReducedInertiaSystem (rotations quasi-static, error O((h/L)^2))
// for adaptive runs, FirstOrderSystem with the full mass for fixed steps. K is not symmetric
// near boundaries (one-sided reconstructions), and with the cubic reconstruction the
// asymmetry splits that thickness-shear cluster into complex pairs growing at ~1e7 /s;
// BDF1/2 damp them for steps above ~1 ns (z = h lambda far outside their instability
// regions), and the quasi-static form has none for clamped and free edges
// (test/study/test_plate_spectrum.cpp). The linear reconstruction has a real spectrum.
//
// Residual stress (physics/structure/residual_stress.hpp): the membrane force N0 = h sigma0 of
// the section acts on the slope of the deflected plate, rho h w'' = div Q + div(N0 grad w) + q:
//   R_w += -sum_f (N0 grad w)_f . S_f
// with the face gradient of w built like that of beta, from the w reconstruction:
//   interior: grad w_f = (grad p_P + grad p_N)(x_f)/2 + (p_N(x_f) - p_P(x_f)) e/|d|
//   w given:  grad w_f = grad p_P(x_f) + (w_b - p_P(x_f)) e/|d|
// Free and loaded edges carry no membrane force (N0 n = 0 there, which the case reader
// requires). It is the plate's geometric stiffness: with a tension N0 = N I the simply
// supported plate's Navier mode of wavenumber k deflects by q_k / (K_k + N k^2), where
// 1/K_k = 1/(D k^4) + 1/(k G h k^2) is its bending and shear flexibility.
//
// Jacobian: the operator is linear, and dR/dy is assembled analytically (every reconstruction
// stencil, the Simpson midpoints, the least-squares shear strain and the non-orthogonal
// correction) once, in the constructor; a linear static plate converges in one Newton step.
// With homogeneous data (no pressure, no point load, every boundary value zero) R(t, 0) = 0, and
// on request (set_residual_by_stiffness) the residual is evaluated as the product K y with that
// matrix; otherwise face by face as above (the same values to round-off;
// test_plate_jacobian.cpp checks both).
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "core/system_operator.hpp"
#include "fv/dof_weight.hpp"
#include "fv/polynomial_reconstruction.hpp"
#include "materials/plate_section.hpp"
#include "mesh/mesh.hpp"
#include "physics/plate/plate_boundary.hpp"

namespace rfmems {

using ScalarField = std::function<Real(const Vec3& x, Real t)>;

class PlateOperator : public SecondOrderOperator {
 public:
  static constexpr int kW = 0, kBetaX = 1, kBetaY = 2;

  // boundaries[p] applies to mesh patch p; pressure q(x, t) per unit area along +z (may be
  // empty). reconstruction_degree: 1 (linear, the thesis's scheme) to 3 (cubic, default).
  PlateOperator(const Mesh& mesh, const PlateSection& section,
                std::vector<PlateBoundary> boundaries, ScalarField pressure = {},
                int reconstruction_degree = 3);

  // A concentrated load on one cell: value(t) = (F_z [N], and the moments [N m] work-conjugate
  // to beta_x and beta_y), added to that cell's balances (a point load at a cell centroid;
  // the scene snaps a load's point to the nearest centroid).
  void add_point_load(Index cell, std::function<Vec3(Real t)> value);

  Index size() const override { return 3 * mesh_.n_cells(); }
  const Mesh& mesh() const { return mesh_; }
  const PlateSection& section() const { return section_; }
  const ScalarField& pressure() const { return pressure_; }
  // The concentrated loads (cell, value(t)) added by add_point_load().
  const std::vector<std::pair<Index, std::function<Vec3(Real)>>>& point_loads() const {
    return point_loads_;
  }
  int reconstruction_degree() const { return reconstruction_degree_; }
  // Evaluate the residual as K y with the assembled stiffness while the data vanish (see the
  // banner): one sparse product instead of every reconstruction (~0.5 ms against ~0.04 ms per
  // residual of the 80 x 8 switch). Its round-off is eps |K| |y|, which for a thin plate lies
  // (L/h)^2 above the face-by-face evaluation's (the shear's large terms cancel after the
  // product rather than before it): for solvers whose tests sit above it (IDA's tolerances,
  // KINSOL with its round-off floor), not for Newton iterated to round-off (the plate creep's
  // equilibrium). Off by default.
  void set_residual_by_stiffness(bool on) { residual_by_stiffness_ = on; }

  void internal_residual(Real t, std::span<const Real> y, std::span<Real> r) override;
  const CsrPattern& stiffness_pattern() const override { return pattern_; }
  void stiffness(Real t, std::span<const Real> y, std::span<Real> values) override;
  std::vector<Real> mass_diagonal() const override;
  // true for the rotation unknowns: the components whose (rotary) inertia
  // ReducedInertiaSystem may neglect (see reduced_inertia_system.hpp).
  std::vector<bool> rotation_components() const;

  // Post-processing.
  // Least-squares gradient of beta at each centroid (row i = d beta_i / dx_j, 2x2 used).
  std::vector<Mat3> rotation_gradients(Real t, std::span<const Real> y) const;
  // Gradient of cell c's reconstruction of beta at x (cubic by default: accurate off-centroid).
  Mat3 rotation_gradient_at(Index c, const Vec3& x, Real t, std::span<const Real> y) const;
  // Moment tensor M(G) of a rotation gradient (2x2 used): M_xx, M_yy, M_xy.
  Mat3 moment(const Mat3& G) const;
  // Transverse shear force Q_c = k G h gamma_c per cell (least-squares fit of the face strains).
  std::vector<Vec3> shear_forces(Real t, std::span<const Real> y) const;
  // Deflection at x from cell c's reconstruction of w (same degree; prescribed w on the
  // supported edges enters it as data).
  Real deflection_at(Index c, const Vec3& x, Real t, std::span<const Real> y) const;
  // deflection_at() as an affine map of the unknowns: w(x) = constant + sum_k weight_k y[dof_k]
  // over the w of the stencil's cells; the constant is the prescribed w of its boundary points
  // at t. Returns the constant. For operators that evaluate w inside a cell (gap quadrature).
  Real deflection_weights(Index c, const Vec3& x, Real t, std::vector<DofWeight>& terms) const;

  // ---- For operators built on the plate (physics/creep) ------------------------------------
  const std::vector<PlateBoundary>& boundaries() const { return boundaries_; }
  // The centroid rotation gradient of rotation_gradients() as a linear map of the unknowns:
  // G_c = G_b + sum_k beta_{cell_k} weight_k^T, where G_b (from prescribed boundary rotations)
  // does not depend on y. For analytic Jacobians of terms that use the curvature.
  struct CellWeight {
    Index cell;
    Vec3 weight;
  };
  std::vector<CellWeight> centroid_gradient_weights(Index c) const;
  // The cell shear force of shear_forces() as a linear map of the unknowns:
  // Q_c = Q_b + sum_k T_k y_k (T_k: rows Q_x, Q_y, 0; columns w, beta_x, beta_y of cell k),
  // Q_b from prescribed boundary values. For analytic Jacobians of terms that use Q_c.
  struct CellBlock {
    Index cell;
    Mat3 T;
  };
  std::vector<CellBlock> shear_force_weights(Index c) const;
  // The face slope grad w_f of the membrane term (see "Residual stress" above) as an affine map
  // of the deflections, whatever the residual stress: grad w_f = sum weight w, w the deflection
  // of `cell` (cell >= 0) or the prescribed deflection of boundary face `face` (cell < 0).
  // Empty on the edges that carry no membrane force (free and loaded). For terms whose
  // membrane force is not h sigma0 (the creep relaxation of the residual stress).
  struct SlopeWeight {
    Index cell;
    Index face;
    Vec3 weight;
  };
  std::vector<SlopeWeight> face_slope_weights(Index f) const;
  // The prescribed deflection of boundary face f at t (0 on a clamped edge).
  Real boundary_deflection(Index f, Real t) const {
    return bc_value(boundaries_[mesh_.face_patch(f)], mesh_.face_centroid(f), t)[0];
  }

 private:
  // Evaluation weights of one cell's beta reconstruction at one point.
  struct Eval {
    Index cell = -1;
    Index begin = 0, end = 0;  // into eval_value_ / eval_gradient_, parallel to the points
  };
  // gamma_c = sum over the cell's faces of weight * g_f (g_f = gamma_e, or Q_n/(kGh)).
  struct StrainWeight {
    Index face;
    Vec3 weight;
  };
  // Linear pieces of the Jacobian: a scalar a.y_cell, or a vector T y_cell.
  struct ScalarTerm {
    Index cell;
    Vec3 a;
  };
  struct VectorTerm {
    Index cell;
    Mat3 T;
  };
  // G_f += (sel y_cell) h^T + value (value_map sel y_cell) e^T, sel y = (beta_x, beta_y, 0)
  struct BendingTerm {
    Index cell;
    Vec3 h;
    Real value;
  };

  Vec3 bc_value(const PlateBoundary& bc, const Vec3& x, Real t) const;
  // R(t, y) face by face from the reconstructions (the equations of the banner).
  void reconstructed_residual(Real t, std::span<const Real> y, std::span<Real> r);
  Vec3 beta(std::span<const Real> y, Index c) const {
    return Vec3(y[3 * c + kBetaX], y[3 * c + kBetaY], 0.0);
  }
  Eval make_eval(Index c, const Vec3& x);
  // Fills point_delta_ (beta_j - beta_c) for one cell's stencil points, or for all cells.
  void cell_point_deltas(Index c, Real t, std::span<const Real> y) const;
  void compute_point_deltas(Real t, std::span<const Real> y) const;
  Vec3 eval_value(const Eval& s, std::span<const Real> y) const;
  Mat3 eval_gradient(const Eval& s) const;
  Vec3 face_moment(const Mat3& G, const Vec3& S) const;
  // Face strains gamma_e (zero, unused, on load and free faces) and cell strains gamma_c.
  void compute_strains(Real t, std::span<const Real> y, std::vector<Real>& gamma_e,
                       std::vector<Vec3>& gamma_c) const;

  // Jacobian helpers (linear terms in the unknowns).
  void value_terms(const Eval& s, Real factor, const Mat3& map, std::vector<VectorTerm>& out) const;
  void bending_terms(const Eval& s, Real grad_factor, Real value_factor,
                     std::vector<BendingTerm>& out) const;
  void strain_terms(Index f, std::vector<ScalarTerm>& out) const;
  void assemble_stiffness();
  // Fills membrane_offset_ / membrane_weights_ (nothing without a residual stress).
  void build_membrane_weights();

  const Mesh& mesh_;
  PlateSection section_;
  std::vector<PlateBoundary> boundaries_;
  ScalarField pressure_;
  int reconstruction_degree_;
  std::vector<std::pair<Index, std::function<Vec3(Real)>>> point_loads_;
  Real mu_, lambda_, kgh_;  // D (1-nu)/2, D nu, k G h
  std::unique_ptr<PolynomialReconstruction> beta_rec_, own_w_rec_;
  const PolynomialReconstruction* w_rec_ = nullptr;  // beta_rec_ when their stencils agree
  std::vector<Real> value_scratch_;                  // of make_eval
  std::vector<Vec3> gradient_scratch_;

  std::vector<Real> eval_value_;
  std::vector<Vec3> eval_gradient_;
  std::vector<Eval> face_eval_;  // two per face at x_f (second unused on boundaries)
  std::vector<Eval> mid_eval_;   // two per face at the segment midpoint
  std::vector<Index> point_offset_;
  mutable std::vector<Vec3> point_delta_;  // beta_j - beta_c per stencil point
  std::vector<Vec3> centroid_gradient_;    // parallel to the stencil points

  std::vector<Vec3> face_e_, face_k_;
  std::vector<Real> face_d_, face_alpha_;
  std::vector<Index> strain_offset_{0};
  std::vector<StrainWeight> strain_weights_;
  mutable std::vector<Real> gamma_e_;  // scratch of internal_residual
  mutable std::vector<Vec3> gamma_c_;

  // The membrane force of face f, (N0 grad w)_f . S_f = sum over [membrane_offset_[f],
  // membrane_offset_[f+1]) of weight times the w of cell (cell >= 0) or the prescribed w of
  // boundary face `face` (cell < 0).
  struct MembraneWeight {
    Index cell;
    Index face;
    Real weight;
  };
  std::vector<Index> membrane_offset_;
  std::vector<MembraneWeight> membrane_weights_;

  CsrPattern pattern_;  // the structurally nonzero entries of dR/dy, and the diagonal
  std::vector<Real> stiffness_values_;
  // No pressure and every boundary value zero: R(t, 0) = 0 without point loads.
  bool homogeneous_data_ = false;
  bool residual_by_stiffness_ = false;
};

}  // namespace rfmems

// The stretching mid-surface of a creeping von Karman plate: what the plate creep system
// (plate_creep_system.hpp) adds to the von Karman plate (physics/plate/von_karman_plate.hpp)
// when the plastic strains enter its membrane.
//
// Membrane strain. The fibre at height z strains eps(z) = eps_m + z kappa, with the von Karman
// membrane strain eps_m = sym grad u + 1/2 grad w (x) grad w. The creep law acts on
//   sigma(z) = sigma0 + C (eps_m + z kappa - eps_p(z))
// at the cell's Simpson points, with the cell's membrane strain
//   eps_m,c = sum_f alpha_cf eps_f,   alpha_cf = |S_f| / sum_g |S_g|
// the area-weighted mean of the face strains eps_f of the von Karman plate over the cell's
// membrane faces (interior faces and edges held in-plane; the mean the plate's output
// membrane_forces takes), so that the membrane stress the creep law sees is the cell's output
// N / h. d eps_f / dw_k = sym(a_k (x) grad w_f), d eps_f / du_k,i = sym(e_i (x) c_k) with the
// plate's face-gradient weights a_k (w) and c_k (u).
//
// Plastic membrane force. The membrane force is
//   N = h sigma0 + A : eps_m - C P,   P = int eps_p dz  (Simpson's rule)
// The von Karman plate carries h sigma0 + A : eps_m; this class adds the plastic part
//   N_p,f = -C (P_P + P_N) / 2   (the owner's P on an edge held in-plane)
// on the plate's membrane faces, in the in-plane balances and the transverse term alike:
//   R_u += -sum_f N_p,f S_f,        R_w += -sum_f (N_p,f grad w_f) . S_f
// (outward S_f of the owner; the neighbour takes the opposite flux). Edges free in-plane (free,
// loaded or released) carry no membrane force, N n = 0: neither part. The residual stress then
// relaxes through in-plane equilibrium (div N = 0) instead of the linear plate's local rule.
// Jacobian: bilinear in (w, P):
//   dF_w / dw_k = a_k . (N_p,f S_f),  dF_u / dP_c = -alpha T(S_f) C,  dF_w / dP_c = grad w_f .
//   dF_u / dP_c, with T(S) the traction map N -> N S of Voigt (xx, yy, xy) and alpha = 1/2
//   (1 on an edge); the system expands dF/dP_c to the points by Simpson's weights.
#pragma once
#include <Eigen/Dense>
#include <span>
#include <vector>

#include "physics/plate/von_karman_plate.hpp"

namespace rfmems {

class VonKarmanCreepMembrane {
 public:
  // C: the plane-stress stiffness in Voigt (xx, yy, xy tensor). The plate must outlive this.
  VonKarmanCreepMembrane(const VonKarmanPlate& plate, const Eigen::Matrix3d& C);

  // eps_m,c of every cell (Voigt xx, yy, xy tensor).
  std::vector<Vec3> cell_strains(Real t, std::span<const Real> y) const;
  // The structural unknowns eps_m,c depends on (w, u, v of the cells of its faces' gradient
  // stencils), sorted.
  const std::vector<Index>& strain_dofs(Index c) const { return strain_dofs_[c]; }
  // d eps_m,c / dy_k at the state, aligned with strain_dofs(c).
  void strain_derivatives(Real t, std::span<const Real> y, Index c, std::vector<Vec3>& d) const;

  // r += the plastic membrane force's fluxes with the face slopes of slope_state's w and the
  // plastic strain integrals P (per cell; linear in P).
  void add_plastic_force(Real t, std::span<const Real> slope_state, const std::vector<Vec3>& P,
                         std::span<Real> r) const;

  // The Jacobian entries of those fluxes, in an order fixed at construction (the same at every
  // state): entries with respect to structural unknowns (the w of the slope stencils) and with
  // respect to the P of a cell (3 columns).
  struct StructuralEntry {
    Index row, col;
  };
  struct StrainEntry {
    Index row, cell;
  };
  const std::vector<StructuralEntry>& structural_entries() const { return structural_entries_; }
  const std::vector<StrainEntry>& strain_entries() const { return strain_entries_; }
  // Values of structural_entries() and strain_entries() (dF_row / dP_cell) at the state.
  void plastic_force_jacobian(Real t, std::span<const Real> y, const std::vector<Vec3>& P,
                              std::vector<Real>& structural, std::vector<Vec3>& strain) const;

 private:
  static Vec3 face_strain(const VonKarmanPlate::FaceState& s);
  // The traction map T(S): (N S)_x = N_xx S_x + N_xy S_y, (N S)_y = N_xy S_x + N_yy S_y.
  static Eigen::Matrix<Real, 2, 3> traction(const Vec3& S);
  // N_p,f for membrane face k (Voigt).
  Vec3 plastic_force(Index k, const std::vector<Vec3>& P) const;

  const VonKarmanPlate& plate_;
  Eigen::Matrix3d C_;
  struct CellFace {
    Index face;  // membrane face index k
    Real alpha;
  };
  std::vector<std::vector<CellFace>> cell_faces_;
  std::vector<std::vector<Index>> strain_dofs_;
  std::vector<StructuralEntry> structural_entries_;
  std::vector<StrainEntry> strain_entries_;
};

}  // namespace rfmems

// Creep of a Mindlin-Reissner plate (thesis ch. 4, eqs. 4.7-4.14 and 4.17-4.25;
// re-derived, the extracted text lost them). Only bending creeps: the in-plane bending strain
// at height z splits into elastic and plastic parts, the transverse shear stays elastic.
//
//   total strain       eps(z) = z kappa,   kappa = sym(grad beta)    (u = z beta_x, v = z beta_y)
//   plane stress       sigma(z) = C (z kappa - eps_p(z)),
//                      C: sigma_xx = E/(1-nu^2) (e_xx + nu e_yy), sigma_xy = E/(1+nu) e_xy
//                      (tensor shear strain e_xy = gamma_xy / 2)
//   moments            M = int z sigma dz = M_el(grad beta) - M_p,   M_p = int z C eps_p dz
//   creep law          eps_p' = CreepLaw rate of sigma(z) (von Mises of the in-plane stress,
//                      sigma_zz = 0), eps_eff' = its effective rate   (materials/creep_law.hpp)
//
// The plate's moment balances become -sum_f (M_el - M_p)_f S_f + Q_c A = 0: the plastic
// moments enter as the sources sum_f M_p,f S_f (thesis S1, S2 of eqs. 4.21-4.22), on the
// faces where the moment is transmitted: interior faces and edges whose rotation is held
// (clamped, prescribed displacement; the tangential part on a hard simple support). Edges
// whose moment is prescribed (free, loaded, soft support) prescribe the total moment, so M_p
// does not enter there. Face values M_p,f: the mean of the two cells' least-squares
// reconstructions of M_p at the face centroid (degree 2, no boundary data), the owner's
// reconstruction extrapolated on a boundary edge (where M_p is largest for a clamped plate).
//
// Through the thickness each cell holds N + 1 Simpson points (ThicknessQuadrature, N = 20 by
// default): M_p by Simpson's rule, sigma(z) and the creep rates at every point.
//
// State (CreepSystem layout): [y | q],
//   y[3c + k]                 plate unknowns (w, beta_x, beta_y) of cell c
//   q[4 (c (N+1) + i) + j]    point i of cell c: eps_p,xx, eps_p,yy, eps_p,xy (tensor), eps_eff
// Residual F_y = R_plate(t, y) + sum_f M_p,f(q) S_f (algebraic), F_q = q' - g(y, q).
//
// Jacobian (analytic): the y rows are constant (the plate is linear, M_p linear in q; but for
// the hold voltage and the relaxation of a residual stress, below) and are assembled once; a
// q row of point (c, i) depends on its own four states and, through kappa_c (the centroid
// gradient of the plate's beta reconstruction), on the rotations of c's stencil.
//
// Transverse shear creep (optional, shear_creep = true; docs/creep.md "Shear creep").
// The thesis's plate lets only bending creep; the continuum's von Mises stress also carries
// the transverse shear stress, which makes the thick-strip difference of Table 4.2. With shear
// creep each point also holds the tensor plastic shear strains eps_p,xz, eps_p,yz, and
//   tau_a(z) = phi(z) Q_el,a / h - 2 G eps_p,az(z),   phi(z) = (3/2)(1 - 4 z^2/h^2)
// (the elastic tau is the parabolic distribution of Q_el = k G h gamma_c, the plate's cell
// shear force; the kinematic shear strain is k phi(z) gamma_c, so int tau dz = Q_el - Q_p),
//   Q_p,a = 2 G int eps_p,az dz      (Simpson's rule; a uniform plastic shear gamma_c relaxes Q)
// tau enters the von Mises stress of the creep law at every point, and the plastic shear force
// is a source in the shear balances: the face shear force Q_f - Q_p,f on interior faces and
// edges whose deflection is held (Q is a reaction there), i.e. + sum_f Q_p,f.S_f in the w rows
// and - sum_f (x_f - x_c)(Q_p,f.S_f) in the beta rows (the plate's Q_c A term). Q_p,f is
// reconstructed like M_p,f. The Jacobian gains the constant y-q blocks of that source and, in
// the q rows, dg/dQ_el times the plate's linear map of Q_el (shear_force_weights). No
// Schur-complement preconditioner in this mode (it assumes 4 states per point): use KLU.
//
// Relaxation of the residual stress (a section with an in-plane sigma0, PlateSection::
// residual_stress; docs/creep.md "Relaxation of the residual stress"). The stress of a point is
//   sigma(z) = sigma0 + C (z kappa - eps_p(z))
// and the creep law acts on it (with shear creep, plus the transverse shear above), so a
// deposited film creeps under its own stress even when the plate does not bend. Its plastic
// strain relaxes the membrane force of the cell,
//   N_c = h sigma0 - C P_c,   P_c = int eps_p dz   (Simpson's rule, the quadrature of M_p),
// which replaces N0 = h sigma0 in the plate's geometric stiffness on every face that carries
// one (interior faces and edges whose deflection is held; free and loaded edges carry none):
//   R_w += -sum_f (N_f grad w_f) . S_f,   N_f = (N_P + N_N)/2 (owner's N on an edge),
// grad w_f the plate's face slope (PlateOperator::face_slope_weights). The plate keeps the
// N0 part; this system adds the relaxation -sum_f (dN_f grad w_f) . S_f, dN = -C P.
// N_f is the mean of the two cells' values, not a reconstruction like M_p,f: the relaxation
// is driven by the local stress and varies as slowly as the stress itself, the slope it
// multiplies is a second-order face value already, and the mean keeps each w row's q columns
// to its face neighbours (21 points x 3 strains each) instead of a reconstruction stencil.
// Approximation: the linear plate has no in-plane displacements, so N is the local relaxed
// value: every fibre's total in-plane strain stays z kappa (the film held in its plane) and
// the in-plane redistribution of a non-uniform relaxation (div N = 0, N n = 0 on a free edge)
// is ignored. Exact for a uniform film held on all edges; for a film with free edges (a
// bridge with free sides, sigma0 = [s (1 - nu), 0, 0]) the relaxed N_yy, which the free sides
// would release, is kept.
// The term is bilinear in (w, q): the w rows depend on the plastic strains of the cells whose
// N enters their faces (q columns eps_p,xx, yy, xy of every point) and their w-w block on q,
//   dF_w / dw_k = -sum_f +-(weight_fk . dN_f S_f),
//   dF_w / d eps_p(c, i) = +-sum_f a_fc w_i (b_f^T C),  b_f = (g_x S_x, g_y S_y, g_x S_y + g_y S_x)
// (a_fc = 1/2, 1 on an edge; g = grad w_f); the y rows are no longer constant: equilibrate
// refactorises the y-y block of J, and the Schur-complement preconditioner takes that block
// for K and adds the relaxation's P_m D^-1 G (plate_creep_schur_complement.hpp). With
// sigma0 = 0 none of this is built: N = 0 by symmetry (eps_p is odd in z), and the system is
// the one above.
//
// Hold voltage (set_hold_voltage, physics/creep/creep_hold_voltage.hpp): the parallel-plate
// pressure on the gap elements, sampled where the pull-in samples it
// (physics/electrostatics/parallel_plate_actuation.hpp, which this system holds for it): on a
// plate's quadrilateral cells at 3 x 3 Simpson points of its w reconstruction,
//   F_w,e += V^2 A_e sum_q a_q p1(g0 + u_q(y)),   u_q = offset_q + sum_k weight_qk w_k,
// one point u = w_e on other cells (plate_scene.cpp; docs/pull-in.md, "Contact and pull-out";
// docs/creep.md, "The gap creep samples"). F_y is nonlinear in w: the Jacobian's y rows are the
// constant ones but for the structural tangent K + V^2 A_e a_q p1'(g_q) weight_qk (row w_e, the
// columns of the reconstruction's stencil, so the y rows' pattern is the actuation's), and
// equilibrate() becomes a Newton iteration on it.
//
// Geometric nonlinearity (the constructor on a VonKarmanPlate, von_karman_plate.hpp): the
// mid-surface stretches and the plastic strains enter the membrane
// (physics/creep/von_karman_creep_membrane.hpp). The fibre at height z strains
//   eps(z) = eps_m + z kappa,   eps_m = sym grad u + 1/2 grad w (x) grad w,
// the creep law acts on sigma(z) = sigma0 + C (eps_m + z kappa - eps_p(z)), and the membrane
// force
//   N = h sigma0 + A : eps_m - C int eps_p dz,   A = h C,
// enters the in-plane balance div N = 0 (quasi-static, as the creep system neglects all
// inertia) and the transverse term div(N grad w); the moments M = D kappa - C int z eps_p dz
// are those above. A residual stress then relaxes through in-plane equilibrium, not the local
// rule of the linear plate (which is off). State: [w, beta_x, beta_y per cell | u, v per cell
// (the von Karman plate's numbering) | q], structural_size() = 5 n_cells.
// Jacobian: exact. The y rows hold the von Karman plate's tangent at the state (or that of the
// hold load built on it), the constant plastic-moment source, and the plastic membrane force,
// bilinear in (w, q); the q rows depend on the rotations of the curvature stencil and on the
// (w, u, v) of the membrane strain's stencil, dg/dy = dg/dsigma C (z dkappa/dy + deps_m/dy).
// equilibrate() is a Newton iteration on the y-y block of the Jacobian (the structure is
// nonlinear). Linear solves: the hand-factored Schur complement below covers the plate
// unknowns only, not u, v; the preconditioner is the Schur complement on (w, beta, u, v)
// formed numerically from J's entries (physics/creep/point_block_schur_complement.hpp), as
// exact (8x faster than KLU on the full Jacobian, whose q rows reach ~100 structural columns
// each and fill in). Not with shear creep.
#pragma once
#include <Eigen/Dense>
#include <memory>
#include <optional>
#include <vector>

#include "fv/polynomial_reconstruction.hpp"
#include "materials/creep_law.hpp"
#include "physics/creep/creep_hold_voltage.hpp"
#include "physics/creep/creep_system.hpp"
#include "physics/creep/leading_block_factors.hpp"
#include "physics/creep/thickness_quadrature.hpp"
#include "physics/creep/von_karman_creep_membrane.hpp"
#include "physics/electrostatics/parallel_plate_actuation.hpp"
#include "physics/plate/plate_operator.hpp"
#include "solvers/sparse_lu.hpp"

namespace rfmems {

class PlateCreepSchurComplement;
class PointBlockSchurComplement;

class PlateCreepSystem : public CreepSystem {
 public:
  // Per point: bending-only creep has kPerPoint = 4 states, shear creep adds kXZ, kYZ.
  static constexpr int kXX = 0, kYY = 1, kXY = 2, kEff = 3, kPerPoint = 4, kXZ = 4, kYZ = 5;

  // hold: as set_hold_voltage, at construction (the Jacobian's pattern is built once).
  PlateCreepSystem(PlateOperator& plate, const CreepLaw& law, int thickness_intervals = 20,
                   bool shear_creep = false, std::optional<CreepHoldVoltage> hold = std::nullopt);
  // With geometric nonlinearity (see above): creep of the von Karman plate (built on its plate
  // operator; both must outlive the system).
  PlateCreepSystem(VonKarmanPlate& plate, const CreepLaw& law, int thickness_intervals = 20,
                   std::optional<CreepHoldVoltage> hold = std::nullopt);
  ~PlateCreepSystem() override;

  // Layout.
  Index n_cells() const { return n_cells_; }
  Index n_points() const { return quadrature_.size(); }  // per cell
  Index structural_size() const override { return vk_ ? 5 * n_cells_ : 3 * n_cells_; }
  bool geometric_nonlinearity() const { return vk_ != nullptr; }
  bool shear_creep() const { return per_point_ == 6; }
  int per_point() const { return per_point_; }  // states per point: 4, or 6 with shear creep
  Index creep_index(Index c, Index i, int component) const {
    return structural_size() + per_point_ * (c * n_points() + i) + component;
  }
  Index size() const override { return structural_size() + per_point_ * n_cells_ * n_points(); }

  std::vector<Real> differential_components() const override;
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override;
  const CsrPattern& jacobian_pattern() const override { return pattern_; }
  void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> values) override;

  // Preconditioner: the exact Jacobian solve by the Schur complement on the plate unknowns
  // (physics/creep/plate_creep_schur_complement.hpp), so that IDA with SPGMR needs about one
  // Krylov iteration per Newton iteration and no factorisation of the full Jacobian.
  // Not with shear creep (see above): KLU. With geometric nonlinearity the Schur complement
  // formed from J's entries (point_block_schur_complement.hpp).
  bool has_preconditioner() const override { return !shear_creep(); }
  void preconditioner_setup(Real t, Real c_j, std::span<const Real> y,
                            std::span<const Real> yp) override;
  void preconditioner_solve(std::span<const Real> r, std::span<Real> z) override;
  // Lagged Schur factors: refactorise S only when ||S_old^-1 (S - S_old)|| exceeds this
  // (PlateCreepSchurComplement); 0 refactorises at every setup (the exact inverse of J).
  // Default 0.1: S = K - P D^-1 G is dominated by the plate stiffness K in the creep runs
  // measured (docs/creep.md), so a few factorisations serve a 500 h run with about the same
  // Krylov iterations as refactorising at each of IDA's ~27 setups.
  void set_schur_refactor_tolerance(Real tolerance);
  // Factorisations of S so far (0 before the first setup).
  long schur_factorizations() const;

  void creep_rates(Real t, std::span<const Real> state, std::span<Real> rates) override;
  void equilibrate(Real t, std::span<Real> state) override;
  void initial_state(Real t, std::vector<Real>& state, std::vector<Real>& state_dot) override;

  // The electrostatic hold load (replaces a previous one; before a solver is built on the
  // system, as it may widen jacobian_pattern() by the points' stencils). Throws InputError for
  // a dof (element or point term) that is not a structural unknown, an element dof without a
  // diagonal entry, a gap <= 0 or a negative voltage.
  void set_hold_voltage(CreepHoldVoltage hold);
  const std::optional<CreepHoldVoltage>& hold_voltage() const { return hold_; }
  // Smallest air gap g0 + u_q over the hold voltage's gap points; +infinity without one.
  Real min_gap(std::span<const Real> state) const;

  // Post-processing.
  // Plastic moments (M_p,xx, M_p,yy, M_p,xy) per cell [N m/m].
  std::vector<Vec3> plastic_moments(std::span<const Real> state) const;
  // Plastic shear forces (Q_p,x, Q_p,y, 0) per cell [N/m]; zero without shear creep.
  std::vector<Vec3> plastic_shear_forces(std::span<const Real> state) const;
  // In-plane stress (xx, yy, xy) at point i of every cell [Pa], sigma0 included.
  std::vector<Vec3> fibre_stress(Real t, std::span<const Real> state, Index i) const;
  // True when the section holds an in-plane residual stress whose relaxation the linear plate
  // models by the local rule (never with geometric nonlinearity).
  bool relaxes_membrane() const { return relaxes_membrane_; }
  // True when the membrane force is not zero in general: a relaxing residual stress, or the
  // stretching von Karman plate.
  bool has_membrane_force() const { return relaxes_membrane_ || vk_ != nullptr; }
  // Membrane force per cell (N_xx, N_yy, N_xy) [N/m]: N_c = h sigma0 - C int eps_p dz, and
  // with geometric nonlinearity + A : eps_m,c (the cell's membrane strain at t).
  std::vector<Vec3> membrane_forces(std::span<const Real> state, Real t = 0) const;

  const PlateOperator& plate() const { return plate_; }
  const CreepLaw& law() const { return law_; }
  const ThicknessQuadrature& quadrature() const { return quadrature_; }

 private:
  friend class PlateCreepSchurComplement;  // reads the blocks of the Jacobian it inverts
  using Mat23 = Eigen::Matrix<Real, 2, 3>;
  using Mat43 = Eigen::Matrix<Real, 4, 3>;
  // Rate derivatives of point (c, i): dg/d(eps_p xx, yy, xy), dg/d eps_eff, dg/d kappa.
  struct PointRateJacobian {
    Mat43 d_eps_p;
    Eigen::Vector4d d_eps_eff;
    Mat43 d_kappa;
    Mat43 d_membrane;  // dg/d eps_m
  };
  PointRateJacobian point_rate_jacobian(std::span<const Real> state, Index c, Index i,
                                        const Vec3& kappa, const Vec3& membrane) const;
  // The cells' membrane strains eps_m,c (Voigt; zero without geometric nonlinearity).
  std::vector<Vec3> membrane_strains(Real t, std::span<const Real> state) const;
  // Curvature of every cell at the state (kappa = sym grad beta at the centroid).
  std::vector<Vec3> curvatures(Real t, std::span<const Real> state) const;
  struct SourceBlock {  // moment rows of cell `row` += B M_p(col)
    Index row, col;
    Mat23 B;
  };
  struct ShearSourceBlock {  // (w, beta_x, beta_y) rows of cell `row` += B Q_p(col)
    Index row, col;
    Eigen::Matrix<Real, 3, 2> B;
  };
  // Shear creep: the cells a point's rates depend on, with d kappa_c / d beta_k's weight
  // (zero if k is not in the curvature stencil) and dQ_el,c / dy_k (rows Q_x, Q_y).
  struct RateStencil {
    Index cell;
    Vec3 curvature_weight;
    Mat3 shear_weight;
  };
  using Vec6 = Eigen::Matrix<Real, 6, 1>;
  using Mat6 = Eigen::Matrix<Real, 6, 6>;
  // Shear creep: dg/d(own 6 states, storage order), dg/dkappa, dg/dQ_el of point (c, i).
  struct ShearPointRateJacobian {
    Mat6 d_state;
    Eigen::Matrix<Real, 6, 3> d_kappa;
    Eigen::Matrix<Real, 6, 2> d_shear_force;
  };
  ShearPointRateJacobian shear_point_rate_jacobian(std::span<const Real> state, Index c, Index i,
                                                   const Vec3& kappa, const Vec3& q_el) const;
  // The full stress tensor of point (c, i) with the transverse shear (shear creep).
  Mat3 point_stress_tensor(std::span<const Real> state, Index c, Index i, const Vec3& kappa,
                           const Vec3& q_el) const;
  Vec3 cell_plastic_shear_force(std::span<const Real> state, Index c) const;

  void build_plastic_source();
  // The faces of the relaxed membrane force with their slope weights (relaxes_membrane()).
  void build_membrane_faces();
  // int eps_p dz of one cell (Voigt xx, yy, xy tensor), Simpson's rule.
  Vec3 cell_plastic_strain_integral(std::span<const Real> state, Index c) const;
  // r_w += the relaxation term -sum_f (dN_f grad w_f) . S_f with the slopes of slope_state's
  // w (boundary deflections at t) and dN = -C P of strain_state's plastic strains (linear in
  // them: with strain_state = q' it is dF_w/dq q').
  void add_membrane_relaxation(Real t, std::span<const Real> slope_state,
                               std::span<const Real> strain_state, std::span<Real> r) const;
  // The y rows of the Jacobian at the state (values [0, structural_nnz_)).
  void structural_rows(Real t, std::span<const Real> y, std::span<Real> values) const;
  void build_pattern();
  // Validates and installs the hold load; true if it changed structural_pattern().
  bool install_hold(CreepHoldVoltage hold);
  // Plastic moments of one cell from its points (Voigt xx, yy, xy).
  Vec3 cell_plastic_moment(std::span<const Real> state, Index c) const;
  // sigma = C (z kappa - eps_p) of point (c, i), Voigt; plus sigma0 with a relaxing residual
  // stress; sigma0 + C (eps_m + z kappa - eps_p) with geometric nonlinearity (membrane: eps_m
  // of the cell, ignored without).
  Vec3 point_stress(std::span<const Real> state, Index c, Index i, const Vec3& kappa,
                    const Vec3& membrane) const;
  static Mat3 stress_tensor(const Vec3& s);
  static Vec3 curvature(const Mat3& G);
  void add_plastic_source(std::span<const Real> state, std::span<Real> r) const;
  // R_y without the plastic source: the plate's, plus the hold load on the w rows
  // (RecoverableError if a gap has closed).
  void structural_residual(Real t, std::span<const Real> state, std::span<Real> r);
  // The pattern of dR_y/dy: the plate's stiffness pattern, widened by the hold load's point
  // stencils (the actuation's).
  const CsrPattern& structural_pattern() const;
  // dR_y/dy in structural_pattern(): K plus the hold load's tangent (with geometric
  // nonlinearity: the von Karman plate's tangent at (t, state)).
  void structural_tangent(std::span<const Real> state, std::vector<Real>& values, Real t = 0) const;
  // The von Karman plate (geometric nonlinearity) or the plate operator.
  SecondOrderOperator& structure();
  // r += the plastic membrane force (geometric nonlinearity) with the slopes of slope_state and
  // the plastic strains of strain_state (linear in them).
  void add_plastic_membrane_force(Real t, std::span<const Real> slope_state,
                                  std::span<const Real> strain_state, std::span<Real> r) const;
  // The factorised structural tangent at the state (the plate's own factors without a hold).
  // With the relaxation, the tangent also holds dF_w/dw of the relaxed membrane force (the
  // y-y block of the Jacobian).
  SparseLu& structural_factors(Real t, std::span<const Real> state);

  PlateCreepSystem(PlateOperator& plate, VonKarmanPlate* von_karman, const CreepLaw& law,
                   int thickness_intervals, bool shear_creep, std::optional<CreepHoldVoltage> hold);

  PlateOperator& plate_;
  VonKarmanPlate* vk_ = nullptr;  // geometric nonlinearity
  std::unique_ptr<VonKarmanCreepMembrane> membrane_;
  // Geometric nonlinearity: per cell, the structural columns of its points' rate rows (sorted):
  // a rotation of the curvature stencil (dkappa/dy of that unknown) or a (w, u, v) of the
  // membrane strain's stencil (its index in membrane_->strain_dofs(c)).
  struct MembraneRateColumn {
    Index dof;
    Vec3 dkappa;
    Index strain;  // -1: a rotation
  };
  std::vector<std::vector<MembraneRateColumn>> membrane_rate_columns_;
  // Value positions of membrane_->structural_entries(), and of strain_entries() expanded to
  // (point i, strain j) in the order i, j.
  std::vector<Index> membrane_structural_position_, membrane_strain_position_;
  CreepLaw law_;
  ThicknessQuadrature quadrature_;
  Index n_cells_;
  Eigen::Matrix3d C_;  // plane-stress stiffness, Voigt (xx, yy, xy tensor)
  std::unique_ptr<PolynomialReconstruction> moment_rec_;
  std::vector<SourceBlock> source_;
  int per_point_ = kPerPoint;
  Real shear_modulus_ = 0;
  std::vector<ShearSourceBlock> shear_source_;          // shear creep only
  std::vector<std::vector<RateStencil>> rate_stencil_;  // shear creep only
  // Per cell: the cells of its curvature stencil (sorted) and their gradient weights.
  std::vector<std::vector<PlateOperator::CellWeight>> curvature_weights_;
  CsrPattern pattern_;
  std::vector<Real> structural_values_;  // the constant y rows, in pattern order
  Index structural_nnz_ = 0;             // y rows occupy values [0, structural_nnz_)
  std::vector<Real> plate_stiffness_;
  std::unique_ptr<SparseLu> plate_lu_;  // dR_plate/dy, factorised once (linear), lazily
  std::optional<CreepHoldVoltage> hold_;
  std::unique_ptr<ParallelPlateActuation> hold_load_;  // the plate under the hold voltage
  std::vector<Index> tangent_position_;   // per structural_pattern() entry: its index in pattern_
  std::unique_ptr<SparseLu> tangent_lu_;  // K + hold tangent, refactorised per use
  std::vector<Real> tangent_values_;
  // Relaxation of the residual stress (relaxes_membrane_).
  bool relaxes_membrane_ = false;
  Vec3 sigma0_ = Vec3::Zero();  // in-plane residual stress, Voigt (xx, yy, xy)
  struct MembraneFace {
    Index face, owner, neighbour;  // neighbour < 0 on an edge
    Index begin, end;              // into slope_weights_
  };
  std::vector<MembraneFace> membrane_faces_;
  // grad w_f of a membrane face at the state (boundary deflections at t).
  Vec3 face_slope(Real t, std::span<const Real> state, const MembraneFace& m) const;
  std::vector<PlateOperator::SlopeWeight> slope_weights_;
  // Per membrane face, in the order structural_rows visits them: the value positions of
  // (owner row, neighbour row) for each slope cell, then for each face cell, point, strain.
  std::vector<Index> relaxation_position_;
  LeadingBlockFactors relaxed_block_;  // the y-y block of pattern_ (relaxation only)
  std::vector<Real> jacobian_scratch_;
  std::unique_ptr<PlateCreepSchurComplement> schur_;
  std::unique_ptr<PointBlockSchurComplement> block_schur_;  // geometric nonlinearity
  std::vector<Real> full_jacobian_;
  Real schur_refactor_tolerance_ = 0.1;
  std::vector<Real> scratch_;
};

}  // namespace rfmems

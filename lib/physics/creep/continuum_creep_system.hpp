// Creep of a continuum: plane stress, plane strain or 3D (thesis ch. 4, eqs.
// 4.4-4.6 and 4.15-4.16; re-derived, the extracted text lost them), on the cell-centred FV
// elasticity operator (physics/elasticity/elasticity_operator.hpp).
//
//   strain split       eps = sym(grad u) = eps_e + eps_p
//   stress             sigma = 2 mu (eps - eps_p) + lambda tr(eps - eps_p) I
//   momentum           0 = div sigma + b   (quasi-static: creep is slow, inertia neglected)
//                        = div sigma_el(u) - div sigma_p + b,
//                      sigma_p = 2 mu eps_p + lambda tr(eps_p) I
//   creep law          eps_p' = CreepLaw rate of the cell's stress (von Mises of the full 3 x 3
//                      stress, materials/creep_law.hpp), eps_eff' = its effective rate
//
// so the FV cell balance of the elasticity operator gains the source +sum_f sigma_p,f S_f
// (thesis eq. 4.16, R_P = -sum_f sigma_f S_f with sigma = sigma_el - sigma_p). sigma_p,f: the
// mean of the two cells' least-squares reconstructions of sigma_p at the face centroid (degree
// 2 by default, no boundary data), the owner's extrapolated on a boundary face. The source
// enters where the elastic operator transmits a face force computed from the displacement:
// interior faces, fixed faces, and the normal part on symmetry faces; a traction face
// prescribes the total traction, so sigma_p does not enter there (a free body with uniform
// eps_p is stress-free at u = eps_p x).
//
// The hypotheses, and what is kept per cell (tensor components: eps_xy = gamma_xy / 2):
//   plane stress (x, y)  eps_p xx, yy, xy, eps_eff. sigma_zz = sigma_xz = sigma_yz = 0 and
//                        lambda is the plane-stress lambda* = 2 lambda mu/(lambda + 2 mu) of
//                        LinearElastic; eps_p,zz = -(xx + yy) (volume preserving) changes only
//                        the thickness and is not a state (plastic_strain() returns it).
//   plane strain (x, y)  eps_p xx, yy, xy, zz, eps_eff. eps_zz = 0 total, so the out-of-plane
//                        plastic strain loads sigma_zz = lambda tr(eps - eps_p) - 2 mu eps_p,zz
//                        and must be a state; tr(eps_p) = 0 is not imposed but holds to
//                        round-off (the flow is deviatoric; BDF preserves linear invariants).
//   3D                   eps_p xx, yy, zz, xy, yz, xz, eps_eff (tr = 0 as in plane strain).
//
// State (CreepSystem layout): [u | q], u[dim c + k] displacement of cell c (the operator's
// layout), q[n_components (c) + j] component j of cell c (the order above). The creep law is
// evaluated at the centroid from the cell's least-squares displacement gradient (the
// operator's cell_gradients(), boundary values included).
//
// Jacobian (analytic): the u rows are constant (the operator is linear, sigma_p linear in q;
// but for the relaxation of a residual stress, below) and assembled once; a q row of cell c
// depends on its own components and, through the centroid gradient, on the displacements of
// c's reconstruction stencil.
//
// Relaxation of the residual stress (material.residual_stress sigma0 != 0; docs/creep.md
// "Relaxation of the residual stress"). The creep law acts on the cell's full stress
//   sigma = sigma0 + C (eps - eps_p)
// and the plastic strain relaxes the prestress of the geometric stiffness (the operator's
// G_f sigma0 S_f on every face but traction faces) to sigma0 - C eps_p per cell, so the system
// adds, on those faces,
//   R_P += -P G_f (dsigma_f S_f),  dsigma_f = -(sigma_p,P + sigma_p,N)/2 (the owner's on a
//   boundary face),  sigma_p = C eps_p,
// P the operator's projection (the normal on a symmetry face, else I), with the receiving
// cell's sign. The face value is the mean of the two cells' (not the reconstruction of the
// sigma_p source): the relaxation varies as slowly as the stress, and the mean keeps a u row's
// new q columns to its face neighbours. Like the plate's, the relaxed prestress is the local
// one: sigma0 - C eps_p is not re-equilibrated (its divergence is the plastic source, which
// the displacement answers, but the geometric term keeps the local value), exact for a uniform
// relaxation. The term is bilinear in (u, q): its exact Jacobian has
//   dF/du_k = (h_k . dsigma_f S_f) P T_k (the face gradient's terms, G_f = sum (T_k u_k) h_k^T),
//   dF/d eps_p,j(c) = -a_c P G_f (C E_j) S_f  (E_j the unit tensor of component j),
// so the u rows are not constant when sigma0 != 0 (equilibrate's tangent is refactorised).
// With sigma0 = 0 none of this is built.
//
// Linear solves (set_linear_solver). Both factorise the structural tangent for the equilibrium
// (K, once; with a relaxing prestress the u-u block at each solve). Direct: IDA's sparse LU of
// the full Jacobian (no preconditioner). Krylov (the default): IDA's GMRES with the block
// preconditioner of continuum_creep_preconditioner.hpp, whose structural solve is the tangent's
// LU: the full Jacobian, with the creep states and its wider coupling, is never factorised.
// Direct stays competitive on small meshes because, unlike the plate (21 points of 4 states per
// cell, whose Jacobian fills in until a Schur complement is needed), a cell holds 4-7 creep
// states whose rows are lower-degree than the displacement rows, so AMD eliminates them first:
// the factor has about the fill of the Schur complement K - P D^-1 G an explicit one would
// build (the source stencil composed with the gradient stencil). On a 3D mesh that factor,
// refactorised at each of IDA's setups, is what bounds the meshes that fit: Krylov took 5.8x
// less CPU and 2.7x less memory on the 3D strip of 345,600 unknowns (docs/creep.md).
#pragma once
#include <Eigen/Dense>
#include <array>
#include <memory>
#include <vector>

#include "fv/polynomial_reconstruction.hpp"
#include "materials/creep_law.hpp"
#include "physics/creep/continuum_creep_preconditioner.hpp"
#include "physics/creep/creep_system.hpp"
#include "physics/creep/leading_block_factors.hpp"
#include "physics/elasticity/elasticity_operator.hpp"
#include "solvers/sparse_lu.hpp"

namespace rfmems {

class ContinuumCreepSystem : public CreepSystem {
 public:
  // source_reconstruction_degree: degree of the least-squares reconstructions that give the
  // face values of sigma_p.
  ContinuumCreepSystem(ElasticityOperator& elasticity, const CreepLaw& law,
                       int source_reconstruction_degree = 2);

  // Layout.
  Index n_cells() const { return n_cells_; }
  int dim() const { return dim_; }
  // Creep states per cell: the plastic strain components, then eps_eff.
  int n_components() const { return n_plastic_ + 1; }
  int n_plastic_components() const { return n_plastic_; }
  // Tensor indices (i, j) of plastic component k.
  std::pair<int, int> component(int k) const { return components_[k]; }
  int effective_component() const { return n_plastic_; }
  Index structural_size() const override { return dim_ * n_cells_; }
  Index creep_index(Index c, int component) const {
    return dim_ * n_cells_ + n_components() * c + component;
  }
  Index size() const override { return (dim_ + n_components()) * n_cells_; }

  std::vector<Real> differential_components() const override;
  void residual(Real t, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> r) override;
  const CsrPattern& jacobian_pattern() const override { return pattern_; }
  void jacobian(Real t, Real c_j, std::span<const Real> y, std::span<const Real> yp,
                std::span<Real> values) override;

  // The linear solves (see the header; Krylov by default).
  enum class LinearSolver { Direct, Krylov };
  void set_linear_solver(LinearSolver solver);
  LinearSolver linear_solver() const { return linear_solver_; }
  bool has_preconditioner() const override { return linear_solver_ != LinearSolver::Direct; }
  void preconditioner_setup(Real t, Real c_j, std::span<const Real> y,
                            std::span<const Real> yp) override;
  void preconditioner_solve(std::span<const Real> r, std::span<Real> z) override;

  void creep_rates(Real t, std::span<const Real> state, std::span<Real> rates) override;
  void equilibrate(Real t, std::span<Real> state) override;
  void initial_state(Real t, std::vector<Real>& state, std::vector<Real>& state_dot) override;

  // Diagnostic (the plate-vs-continuum study): the creep law sees only the stress components
  // kept (Voigt xx, yy, zz, xy, yz, xz; all by default). Dropping the transverse shear and
  // normal stress of a beam section (section x-y: keep only xx and zz) reproduces the plate's
  // assumption that only the bending stress creeps. The elastic stress is not affected.
  void set_creep_stress_mask(const std::array<bool, 6>& keep);

  // Post-processing.
  // Plastic strain tensor of cell c (plane stress: eps_p,zz = -(xx + yy)).
  Mat3 plastic_strain(std::span<const Real> state, Index c) const;
  // Full 3 x 3 Cauchy stress of every cell [Pa], sigma0 included.
  std::vector<Mat3> cell_stresses(Real t, std::span<const Real> state) const;

  // True when the material holds a residual stress, whose relaxation the system models.
  bool relaxes_prestress() const { return relaxes_prestress_; }
  // The relaxed prestress sigma0 - C eps_p of every cell [Pa].
  std::vector<Mat3> prestresses(std::span<const Real> state) const;

  const ElasticityOperator& elasticity() const { return elasticity_; }
  const CreepLaw& law() const { return law_; }

 private:
  using Vec6 = Eigen::Matrix<Real, 6, 1>;
  using Mat6 = Eigen::Matrix<Real, 6, 6>;
  // Creep states of a cell (at most 7) and the maps into them.
  using RateVector = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, 7, 1>;
  using RateJacobian = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, 0, 7, 7>;
  // u rows of cell `row` += B (plastic components of cell col).
  struct SourceBlock {
    Index row, col;
    Eigen::Matrix<Real, 3, 6> B;
  };
  // Voigt stress increment per unit displacement of one stencil cell: dsigma = S du.
  struct StressWeight {
    Index cell;
    Eigen::Matrix<Real, 6, 3> S;
  };

  // sigma = 2 mu e + lambda tr(e) I_h (I_h without zz in plane stress).
  Mat3 hooke(const Mat3& strain) const;
  // The plastic strain that enters the stress (plane stress: without its zz part).
  Mat3 stress_plastic_strain(std::span<const Real> state, Index c) const;
  Mat3 cell_stress(std::span<const Real> state, Index c, const Mat3& G) const;
  // The stress the creep law sees (creep_stress_mask_ applied).
  Mat3 creep_stress(const Mat3& sigma) const;
  // dg/dsigma (Voigt xx, yy, zz, xy, yz, xz; unit symmetric increments) and dg/d eps_eff.
  void rate_derivatives(const Mat3& sigma, Real eps_eff, RateJacobian& d_sigma,
                        RateVector& d_eps_eff) const;
  RateVector rate_vector(const CreepRate& r) const;
  static Mat3 unit_tensor(int i, int j);
  static Vec6 voigt(const Mat3& s);

  void build_plastic_source(int degree);
  void build_stress_weights();
  void build_pattern();
  void add_plastic_source(std::span<const Real> state, std::span<Real> r) const;
  // The faces of the relaxed prestress with their gradient terms (relaxes_prestress()).
  void build_prestress_faces();
  // r_u += the relaxation term with the face gradients of gradient_state (boundary values at
  // t) and dsigma = -C eps_p of strain_state (linear in it: with q' it is dF_u/dq q').
  void add_prestress_relaxation(Real t, std::span<const Real> gradient_state,
                                std::span<const Real> strain_state, std::span<Real> r) const;
  // The u rows of the Jacobian at the state (values [0, structural_nnz_)).
  void structural_rows(Real t, std::span<const Real> y, std::span<Real> values) const;
  // The factorised dF_u/du at the state: K (factorised on first use), or with the relaxation
  // the u-u block (refactorised at each call).
  SparseLu& structural_factors(Real t, std::span<const Real> state);

  ElasticityOperator& elasticity_;
  CreepLaw law_;
  Index n_cells_;
  int dim_;
  int n_plastic_;
  Hypothesis hypothesis_;
  Real mu_, lambda_;
  std::vector<std::pair<int, int>> components_;
  std::array<Real, 6> creep_stress_mask_{1, 1, 1, 1, 1, 1};
  Eigen::Matrix<Real, 6, 6> plastic_stress_;  // Voigt sigma_p per plastic component (columns)
  std::vector<SourceBlock> source_;
  std::vector<std::vector<StressWeight>> stress_weights_;
  CsrPattern pattern_;
  std::vector<Real> structural_values_;
  Index structural_nnz_ = 0;
  std::vector<Real> stiffness_values_;  // K, in the elasticity operator's pattern
  std::unique_ptr<SparseLu> stiffness_lu_;
  LinearSolver linear_solver_ = LinearSolver::Direct;
  std::unique_ptr<ContinuumCreepPreconditioner> preconditioner_;
  SparseLu* tangent_factors_ = nullptr;  // the preconditioner's, from its set-up

  // Relaxation of the residual stress.
  bool relaxes_prestress_ = false;
  Mat3 sigma0_ = Mat3::Zero();
  std::vector<Mat3> component_stress_;  // C E_j per plastic component j
  struct PrestressFace {
    Index face, owner, neighbour;  // neighbour < 0 on a boundary face
    Mat3 projection;               // of the force onto what the cells receive
    Index begin, end;              // into gradient_terms_
  };
  std::vector<PrestressFace> prestress_faces_;
  std::vector<ElasticityOperator::GradientTerm> gradient_terms_;
  // Per prestress face, in structural_rows' order: for each term, each (row component a,
  // column component b), the positions of (owner row, neighbour row); then for each face cell,
  // each plastic component j, each row component a, the same pair.
  std::vector<Index> relaxation_position_;
  LeadingBlockFactors relaxed_block_;  // the u-u block of pattern_ (relaxation only)
  std::vector<Real> jacobian_scratch_;
  std::vector<Real> scratch_;
};

}  // namespace rfmems

// Squeeze film of gas under a moving plate: the isothermal compressible Reynolds equation
// (the thesis's cheap gas model, ch. 2; Bao, "Micro mechanical transducers", ch. 3),
// cell-centred finite volumes on the plate's 2D mesh (unit depth: areas are cell volumes).
//
//   d(p g)/dt = div( D grad p ),   D(p, g) = g^3 p / (12 mu_eff),   mu_eff = mu / Q(Kn)
//
// p: film pressure (one unknown per cell), g(x, y, t) > 0: the gap between the plate and the
// substrate, Q(Kn) = 1 + 9.638 Kn^1.159 with Kn = lambda_ref p_ref / (p g) (Veijola 1995,
// materials/gas_properties.hpp), Q from the kinetic solver's table
// (materials/flow_factor_table.hpp, monotone cubic in ln Kn with its exact derivative) or
// Q = 1. The equation is gas mass conservation (p g ~ mass per area for an isothermal ideal
// gas) with the lubrication (Poiseuille) flux -D grad p.
//
// Validity. Lubrication theory: g << plate size, small reduced Reynolds number
// (rho w L^2 / mu << 1, far below 1 for micron gaps at RF MEMS speeds), isothermal gas (the
// walls hold the temperature). Rarefaction through mu_eff: the Veijola fit is within 5 % for
// Kn <= 880 (continuum Q = 1 only for Kn < ~0.01; a 2 um gap at 1 atm has Kn = 0.034 and
// Q = 1.19). Compressibility is kept: the squeeze number sigma = 12 mu_eff w L^2 / (p_a g^2)
// may be anything (sigma << 1: incompressible viscous damping; sigma >> 1: the film acts as
// a gas spring, Blech 1983). Open edges ignore the edge (elongation) correction, which
// matters when g is not small against the plate width or perforation size.
//
// Discretisation, cell balance (F_c = 0):
//   F_c = (p'_c g_c + p_c g'_c) A_c - sum_f flux_f
//   interior face P|N: flux_f = D_f T_f (p_N - p_P),  D_f = w_P D(p_P, g_P) + w_N D(p_N, g_N)
//   Open face:         flux_f = D(p_a, g_P) T_f (p_a - p_P)
//   Wall face:         flux_f = 0
// with T_f = (S_f . e)/|d| (d = x_N - x_P, or x_f - x_P on a boundary; e = d/|d|) and linear
// interpolation weights w_P = ((x_N - x_f).d)/|d|^2, w_N = 1 - w_P.
//  - Face coefficient: interpolated, not harmonic. D is smooth (the gap has no jumps inside
//    one plate), so the arithmetic (linear) mean is second-order accurate and keeps the
//    Jacobian simple; the harmonic mean is the fix for discontinuous coefficients, which
//    this film does not have, and it is biased low when g^3 varies across a face.
//  - On an Open face the pressure in D is the known edge pressure p_a and the gap is the
//    cell's (the gap is known per cell only); that O(h) error in one coefficient shifts the
//    edge by O(h^2), so the scheme stays second order (measured in
//    test/regression/test_reynolds_incompressible.cpp).
//  - Two-point gradient, non-orthogonal part dropped (two-point flux approximation): of
//    S_f = (S_f.e) e + k_f only the part along d is kept (the "minimum correction" split, the
//    smallest dropped k_f). It is exact on orthogonal meshes (the rectangular plate meshes)
//    and O(skew) inconsistent otherwise; a correction would need cell gradients, widening
//    the stencil beyond the face neighbours that the coupled Jacobian is built on. Measured
//    on a 200 x 100 um plate (Blech damping, 0.16 % off on 80 x 40 rectangles) whose interior
//    nodes are shifted sinusoidally: cells sheared up to 6 degrees converge to ~0.5 % off,
//    up to 22 degrees to ~2.4 % off. Whatever
//    the mesh, each interior flux leaves one cell and enters the other, so mass is conserved
//    to round-off (test/unit/gas/test_reynolds_conservation.cpp).
//
// Jacobians (exact, analytic; both on cell_pattern(), the cell + face-neighbour graph):
//   pressure_jacobian = dF/dp + c_j dF/dp'    (dF/dp' = diag(g A))
//   gap_jacobian      = dF/dg + c_j dF/dg'    (dF/dg' = diag(p A))
// with dD/dp = g^3 (Q + p dQ/dp) / (12 mu), dD/dg = p (3 g^2 Q + g^3 dQ/dg) / (12 mu),
// dQ/dp = -Q'(Kn) Kn / p, dQ/dg = -Q'(Kn) Kn / g.
//
// Force on the plate: the film pushes the plate (above it, along +z) with (p - p_a) A_c per
// cell; the ambient pressure p_a is assumed to act on the plate's other side.
//
// A non-positive gap or pressure throws RecoverableError, so IDA retries with a smaller step.
// Serial: the mesh must have no ghost cells.
#pragma once
#include <array>
#include <span>
#include <vector>

#include "core/system_operator.hpp"
#include "materials/gas_properties.hpp"
#include "mesh/mesh.hpp"
#include "physics/gas/reynolds_boundary.hpp"

namespace rfmems {

class ReynoldsFilm {
 public:
  // boundaries[p] applies to mesh patch p. Throws InputError on a 3D mesh, a boundary count
  // that differs from the patch count, or non-positive gas properties.
  ReynoldsFilm(const Mesh& mesh, GasProperties gas, std::vector<FilmBoundary> boundaries);

  Index size() const { return mesh_.n_owned_cells(); }
  const Mesh& mesh() const { return mesh_; }
  const GasProperties& gas() const { return gas_; }

  // F_c = d(p g)/dt A_c - sum_f flux_f, with d(p g)/dt = p' g + p g'.
  void residual(std::span<const Real> p, std::span<const Real> p_rate, std::span<const Real> gap,
                std::span<const Real> gap_rate, std::span<Real> r) const;

  // The cell + face-neighbour graph (diagonal included, columns sorted): the pattern of both
  // Jacobian blocks.
  const CsrPattern& cell_pattern() const { return pattern_; }
  // dF/dp + c_j dF/dp' in cell_pattern() order.
  void pressure_jacobian(Real c_j, std::span<const Real> p, std::span<const Real> p_rate,
                         std::span<const Real> gap, std::span<const Real> gap_rate,
                         std::span<Real> values) const;
  // dF/dg + c_j dF/dg' in cell_pattern() order.
  void gap_jacobian(Real c_j, std::span<const Real> p, std::span<const Real> p_rate,
                    std::span<const Real> gap, std::span<const Real> gap_rate,
                    std::span<Real> values) const;

  // Net force per cell on the plate along +z, (p - p_a) A_c; its derivative d force_c / d p_c
  // is plate_force_derivative()[c] = A_c (and it does not depend on the gap).
  void plate_force(std::span<const Real> p, std::span<Real> force) const;
  const std::vector<Real>& plate_force_derivative() const { return area_; }
  Real total_force(std::span<const Real> p) const;

  // Flow coefficient D(p, g) = g^3 p Q / (12 mu) and its partial derivatives.
  Real flow_coefficient(Real p, Real g) const;
  struct FlowCoefficient {
    Real value, d_pressure, d_gap;
  };
  FlowCoefficient flow_coefficient_with_derivatives(Real p, Real g) const;

 private:
  struct Face {
    Index owner, neighbour;  // neighbour -1 on a boundary face
    Real transmissibility;   // (S.e)/|d|
    Real owner_weight;       // w_P (interior faces)
    bool open;               // boundary faces: Open (true) or Wall (false)
    // Positions in the value array of (P,P), (P,N), (N,P), (N,N) (interior faces).
    std::array<Index, 4> slot;
  };
  void check_state(std::span<const Real> p, std::span<const Real> gap) const;

  const Mesh& mesh_;
  GasProperties gas_;
  std::vector<FilmBoundary> boundaries_;
  std::vector<Real> area_;
  std::vector<Face> faces_;  // interior faces and Open boundary faces (Wall faces carry nothing)
  CsrPattern pattern_;
  std::vector<Index> diagonal_slot_;
};

}  // namespace rfmems

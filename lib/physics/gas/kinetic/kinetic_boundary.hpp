// Boundary conditions of the kinetic gas (thesis ch. 5), as face values of the distribution
// on a boundary face: the owner cell's values for outgoing ordinates (c . S >= 0, S outward from
// the gas), and for incoming ordinates (c . S < 0):
//   diffuse_wall {T, velocity, accommodation sigma (default 1)}:
//       f_in = sigma n_w M_w + (1 - sigma) f_owner(c'),  c' the specular image, M_w the wall
//       Maxwellian (u_w, T_w) of unit density; n_w from zero net mass flux through the face
//       (thesis eq. 5.32) in the wall's frame: sum_k w_k (c_k - u_w) . S f_face,k = 0, solved
//       for n_w in closed form on the grid, so a diffuse wall is impermeable to round-off
//       (eq. 5.34 for sigma < 1). The mesh is fixed: a wall moving along its normal (a beam
//       over a substrate, quasi-steady squeeze film) shows as the net mass flux
//       rho_face u_w . S through its faces; a tangential one as shear only.
//   specular_wall, symmetry:  f_in(c) = f_owner(c') (eq. 5.33), the reflection map of
//       VelocityGrid (exact for axis-aligned walls).
//   pressure {p, T}:  f_in = the Maxwellian at rest with rho = p / (R T) (eq. 5.35).
//       A reservoir, not a transparent side: a normal outflow u_n needs the interior pressure
//       p + C p u_n / sqrt(2 R T), C ~ 2 at every Kn (the condensation jump; measured 2.05-2.09
//       for ESBGK, test_kinetic_pressure_boundary.cpp), so near the continuum it is all but
//       closed to normal flow (docs/gas_damping.md "Why ESBGK sat 10.5 % above ...").
//   periodic {partner}: f_in = the values leaving through the partner patch's matching face
//       (the face translated by the offset between the two patches): the partner's owner cell
//       value, or its reconstruction there with second order. The two patches name each other
//       and match face by face; the operator fills these faces (fill_boundary_face cannot:
//       it sees only the owner). A channel one cell long between two periodic patches is
//       the fully developed flow of an infinitely long one (plane Poiseuille flow driven by
//       a body force, kinetic_operator.hpp).
//   external: face values supplied from outside (external_face_values.hpp; the immersed
//       boundary's IB faces); not available from case files, fill_boundary_face rejects it.
// The Maxwellians are the DISCRETE equilibria of the gas's collision model (equilibrium.hpp:
// exact discrete moments rho, u_w and covariance R T_w I; 10 coefficients for ESBGK, since on
// an anisotropic grid the 5-coefficient one has a slightly anisotropic discrete covariance),
// not samples of the continuous one: then a gas in equilibrium with its walls is an exact fixed
// point of the discrete equations, and a pressure boundary imposes exactly p, T.
// Both solvers (sequential and COMET) get boundary face values only through fill_boundary_face.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "fv/face_graph.hpp"
#include "io/case_schema.hpp"
#include "physics/gas/kinetic/kinetic_gas.hpp"
#include "physics/gas/kinetic/velocity_grid.hpp"

namespace rfmems {

class CaseNode;

enum class KineticBoundaryKind {
  DiffuseWall,
  SpecularWall,
  Pressure,
  Symmetry,
  Periodic,
  External
};

const char* kinetic_boundary_kind_name(KineticBoundaryKind kind);

struct KineticBoundary {
  KineticBoundaryKind kind = KineticBoundaryKind::SpecularWall;
  Real temperature = 0;          // K (diffuse wall, pressure)
  Vec3 velocity = Vec3::Zero();  // m/s (diffuse wall)
  Real accommodation = 1;        // sigma in [0, 1] (diffuse wall)
  Real pressure = 0;             // Pa (pressure boundary)
  std::string partner;           // the partner patch's name (periodic)

  static KineticBoundary diffuse_wall(Real T, const Vec3& velocity = Vec3::Zero(),
                                      Real accommodation = 1);
  static KineticBoundary specular_wall();
  static KineticBoundary symmetry();
  static KineticBoundary pressure_outlet(Real p, Real T);
  static KineticBoundary periodic(const std::string& partner);
  // Face values from an ExternalFaceValues source set on the operator.
  static KineticBoundary external();

  // Does the condition read the owner's reflected ordinates?
  bool needs_reflection() const;
};

// One condition per patch of the graph, from a case map whose keys are patch names:
//   boundaries:
//     top:    {type: diffuse_wall, T: 273.15 K, velocity: [10, 0], accommodation: 1}
//     left:   {type: specular_wall}
//     right:  {type: pressure, p: 0.5 Pa, T: 273.15 K}
//     bottom: {type: symmetry}
//     inlet:  {type: periodic, partner: outlet}   # and outlet: {type: periodic, partner: inlet}
// Every patch must be listed and every listed name must be a patch (InputError otherwise); a
// periodic patch's partner must be another periodic patch that names it back.
std::vector<KineticBoundary> kinetic_boundaries_from_case(const CaseNode& boundaries,
                                                          const FaceGraph& graph);

// The discrete Maxwellian of the condition, for every ordinate: diffuse wall: unit density at
// (u_w, T_w); pressure: rho = p / (R T) at rest; empty for specular walls and symmetry.
std::vector<Real> boundary_maxwellian(const KineticBoundary& bc, const VelocityGrid& grid,
                                      const KineticGas& gas);

// Fills f_face (all ordinates) on a boundary face with area vector `area` (outward from the
// gas) from the owner's distribution. `reflection` is grid.reflection_map(area / |area|)
// when bc.needs_reflection(), else may be empty; `maxwellian` is boundary_maxwellian(bc, ...).
void fill_boundary_face(const KineticBoundary& bc, const Vec3& area, std::span<const Real> f_owner,
                        const VelocityGrid& grid, std::span<const Index> reflection,
                        std::span<const Real> maxwellian, std::span<Real> f_face);

// The keys kinetic_boundaries_from_case reads under `boundaries` (kinetic_boundary.keys.yaml;
// io/case_schema.hpp).
CaseSchema kinetic_boundary_case_keys();

}  // namespace rfmems

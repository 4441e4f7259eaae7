// The distribution function on the IB faces of the immersed kinetic gas: the thesis's three
// steps (ch. 6) as the ExternalFaceValues of the "immersed" patch of a FluidFaceGraph.
//
//   (i)   At the surface segments' midpoints (the structure's faces, unit outward normal n_j),
//         the ordinates going INTO the solid (c_k . n_j < 0) from the FLUID cells alone:
//         g_jk = sum_i w_ji f_ik, the fit of IbInterpolation::to_surface_points.
//   (ii)  On segment j the ordinates leaving the solid (c_k . n_j > 0): diffuse reflection,
//         W_jk = n_j M_jk, M_j the discrete unit-density equilibrium at the wall temperature and
//         the segment's velocity u_j; n_j from zero net mass flux through the wall in its frame,
//           sum_{c.n<0} w_k (c_k - u_j) . n_j g_jk + n_j sum_{c.n>0} w_k (c_k - u_j) . n_j M_jk = 0
//         (thesis eq. 5.32, as KineticBoundary::diffuse_wall does on a body-fitted face).
//   (iii) On IB face i (normal n_i out of the fluid) the ordinates entering the fluid
//         (c_k . n_i < 0) from the FLUID cells and the wall values W_jk of the segments at
//         which ordinate k leaves the wall (c_k . n_j > 0): the IbInterpolation with
//         wall_point_admissible(j) = c_k . n_j > 0 and the foundation's one-sided rule (kappa,
//         Lebesgue constant; widen, then lower the degree). Ordinates whose admissible-segment
//         sets agree share one interpolation (a rectangle: 4 groups, one per quadrant of
//         (c_x, c_y)). The ordinates leaving the fluid take the FLUID cell's value at the face
//         (upwind): the owner's values the operator hands over (external_face_values.hpp),
//         its cell values with first-order transport, its limited linear reconstruction with
//         second order (immersed_kinetic_gas.hpp "Second-order transport").
//
// One change to the thesis (documented in docs/ibm.md): step (iii) is an interpolation, so the
// IB face's net mass flux is not the wall's. With `balance_mass_flux` (default) the entering values
// of face i are scaled by one factor a_i so that the face carries the mass flux of an
// impermeable wall moving at u_i (the ForceTransfer adjoint's velocity at the face):
//   sum_k w_k (c_k . S_i) f_ik = rho_ref u_i . S_i   (the leaving f_ik: the owner's values),
// rho_ref one reference density (the gas's mean at the last set_body / initialize). One rho_ref
// for all faces makes the IB faces' net mass flow rho_ref sum_i u_i . S_i, which is zero to
// round-off for a rigid motion (the IB faces close around the body and the adjoint reproduces
// rigid motions exactly): the FLUID gas mass is then conserved by every gas step. The cost is
// an O(delta rho / rho) error in the gas a normally moving wall pushes (squeeze film).
// Measured factors: |a_i - 1| <= 2.1e-7 in the Couette flow (tangential wall); up to 0.16 in
// the closed box with a body moving normally at 40 m/s (Mach 0.12; test_immersed_kinetic_gas):
// there the raw step-3 values miss part of the gas the body pushes.
//
// Positivity (`clip_negative`, default on). The step-(iii) fits have Lebesgue constants up
// to 2.5 (and step (i) up to 8), so an entering value can come out negative where f varies
// steeply across the stencil (the tail of the velocity grid beside a moving wall). Negative
// entering values are set to 0 before the mass-flux factor a_i is computed, so the factor
// restores the face's prescribed mass flux exactly (the entering half is re-scaled); with
// balance_mass_flux off, the clipped entering half is re-scaled to its unclipped mass flux.
// Either way the clip changes no mass flux, so the closed-box conservation is untouched. A face
// whose entering values are all <= 0 (no non-negative half could carry its flux) takes its
// FLUID cell's values for them, scaled by a_i (without the balance: unscaled, and its mass flux
// changes); counted.
// positivity() reports the last update's count and depth (docs/ibm.md "Positivity").
#pragma once
#include <array>
#include <span>
#include <vector>

#include "core/types.hpp"
#include "ibm/cell_marking.hpp"
#include "ibm/fluid_face_graph.hpp"
#include "ibm/ib_interpolation.hpp"
#include "ibm/immersed_surface.hpp"
#include "mesh/mesh.hpp"
#include "physics/gas/kinetic/external_face_values.hpp"
#include "physics/gas/kinetic/kinetic_gas.hpp"
#include "physics/gas/kinetic/velocity_grid.hpp"

namespace rfmems {

struct IbKineticOptions {
  Real wall_temperature = 300;                                                        // K
  IbInterpolationOptions face_options = {};                                           // step (iii)
  IbInterpolationOptions surface_options = IbInterpolation::surface_point_options();  // step (i)
  bool balance_mass_flux = true;
  bool clip_negative = true;  // entering values < 0 set to 0, the mass flux kept (above)
};

// Negative values of the last update, before any clipping.
struct IbPositivityReport {
  Index entering_values = 0;    // step (iii): IB faces x entering ordinates
  Index negative_entering = 0;  // of those, < 0
  Index faces_with_negative = 0;
  Real most_negative_entering = 0;    // min over faces of min_k e_ik / max_k abs(e_ik) (>= -1)
  Index faces_from_cell = 0;          // all entering values <= 0: the FLUID cell's taken
  Index negative_into_solid = 0;      // step (i): segments x into-solid ordinates < 0
  Real most_negative_into_solid = 0;  // min over segments of min_k g_jk / max_k g_jk
  Index negative_wall_density = 0;    // step (ii): segments with n_j < 0
};

class IbKineticFaceValues : public ExternalFaceValues {
 public:
  // segment_velocity: per segment of `body`; ib_face_velocity: per IB face of `marking`. All
  // references must outlive this object.
  IbKineticFaceValues(const Mesh& background, const FluidFaceGraph& fluid,
                      const CellMarking& marking, const ImmersedSurface& body,
                      std::span<const Vec3> segment_velocity,
                      std::span<const Vec3> ib_face_velocity, const VelocityGrid& grid,
                      const KineticGas& gas, Real reference_density,
                      const IbKineticOptions& options);

  void update(std::span<const Real> f, std::span<const Real> owner_values) override;
  void fill(Index face, std::span<const Real> owner_values, std::span<Real> out) const override;

  void set_reference_density(Real rho) { reference_density_ = rho; }
  Real reference_density() const { return reference_density_; }
  Index n_ordinate_groups() const { return static_cast<Index>(groups_.size()); }
  // After update(): the wall density n_j of segment j (step ii) and the mass-flux factors a_i.
  Real wall_density(Index segment) const { return wall_density_[segment]; }
  std::span<const Real> flux_factors() const { return factor_; }
  const IbPositivityReport& positivity() const { return positivity_; }
  // Degree counts and one-sided faces of the step-(iii) fits over all groups.
  Index count_one_sided() const;
  Index count_degree(int degree) const;

 private:
  // A stencil with cell indices already in the fluid graph's numbering.
  struct Stencils {
    std::vector<Index> offsets{0};
    std::vector<Index> index;  // fluid cell, or segment
    std::vector<char> wall;    // 1: segment (wall point)
    std::vector<Real> weight;
  };
  Stencils compact(const IbInterpolation& ib) const;

  const FluidFaceGraph& fluid_;
  const CellMarking& marking_;
  const ImmersedSurface& body_;
  std::span<const Vec3> ib_face_velocity_;
  std::vector<Vec3> segment_velocity_;
  const VelocityGrid& grid_;
  IbKineticOptions options_;
  Real reference_density_;

  Stencils surface_;              // step (i): per segment
  std::vector<Stencils> groups_;  // step (iii): per ordinate group, per IB face
  std::vector<std::vector<Index>> group_ordinates_;
  std::vector<Index> graph_face_of_ib_;  // IB face -> fluid graph face
  std::vector<Real> maxwellian_;         // per segment x N: M_jk
  std::vector<Real> into_solid_;         // per segment x N: g_jk (step i)
  std::vector<Real> wall_values_;        // per segment x N: W_jk (step ii)
  std::vector<Real> wall_density_;       // per segment
  std::vector<Real> entering_;           // per IB face x N: step (iii), scaled
  std::vector<Real> factor_;             // per IB face: a_i
  std::vector<IbFaceFit> fits_;          // step (iii) fits, all groups
  IbPositivityReport positivity_;
};

}  // namespace rfmems

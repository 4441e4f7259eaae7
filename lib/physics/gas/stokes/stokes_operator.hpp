// Steady incompressible Stokes flow on a MAC grid with solid blocks (mac_grid.hpp,
// stokes_boundary.hpp):
//
//   div sigma + f = 0,   sigma = -p I + mu (grad u + grad u^T),   div u = 0,
//
// finite volumes on the staggered control volumes: pressure per fluid cell, u on the
// vertical faces, v on the horizontal ones (Harlow and Welch 1965). The momentum balance of
// each velocity's control volume (the face's two half cells, or the gas half only on a
// boundary) is the sum of the forces on its edges, written in the stress-divergence form:
//   normal stress at cell centres   sigma_xx = -p + 2 mu (u_E - u_W)/h   (sigma_yy alike)
//   shear stress at grid nodes      tau = mu ((u_N - u_S)/h + (v_E - v_W)/h)
// With div u = 0 in every cell this equals the Laplacian form mu Lap u = grad p in the
// interior (the transposed terms are h^-1 times differences of cell divergences), and the
// stress form makes the open sides' traction condition the natural one and every edge force
// the same from its two sides, so a sum of balances telescopes to the boundary forces
// (stokes_force.hpp). A face in a wall or a symmetry side has a known normal velocity; its
// gas half-volume's wall edge carries the unknown reaction, which is what the force
// integration recovers. Open sides close their faces' half volumes with -p_a h.
//
// The unknowns x are in SI units (m/s, Pa): u faces, then v faces, then cell pressures. The
// pressure level is fixed by the open sides (at least one is needed).
#pragma once
#include <optional>
#include <vector>

#include "core/system_operator.hpp"
#include "physics/gas/stokes/affine_form.hpp"
#include "physics/gas/stokes/mac_grid.hpp"
#include "physics/gas/stokes/stokes_boundary.hpp"

namespace rfmems {

struct StokesProblem {
  Real viscosity = 0;  // mu [Pa s]
  StokesBoundaries boundaries;
  VelocityField body_force;  // f [N/m^3]; empty: none
};

// What lies across one edge (part) of a control volume: gas, a solid block or a side.
struct Across {
  enum class Kind { Fluid, Block, Side };
  Kind kind = Kind::Fluid;
  int index = 0;  // block number or Side
  bool operator==(const Across&) const = default;
  static Across block(int b) { return {Kind::Block, b}; }
  static Across side(Side s) { return {Kind::Side, static_cast<int>(s)}; }
};

// One momentum component of a control volume's gas: the forces on it through its edges,
// the body force, and (for a face of known normal velocity) the wall edge whose force is
// the unknown reaction that closes the balance.
struct ControlVolumeBalance {
  struct Edge {
    AffineForm force;
    Across across;
  };
  std::vector<Edge> edges;
  Real body_force = 0;
  std::optional<Across> reaction;
};

class StokesOperator {
 public:
  StokesOperator(const MacGrid& grid, StokesProblem problem);

  const MacGrid& grid() const { return grid_; }
  const StokesProblem& problem() const { return problem_; }
  Index size() const { return n_; }

  // Face velocities: an unknown, a known value, or nullopt where the face has no gas.
  std::optional<AffineForm> u(int i, int j) const;
  std::optional<AffineForm> v(int i, int j) const;
  AffineForm pressure(int i, int j) const;  // fluid cell
  AffineForm sigma_xx(int i, int j) const;  // fluid cell
  AffineForm sigma_yy(int i, int j) const;
  AffineForm shear(int i, int j) const;  // node with gas on both sides of a line through it
  ControlVolumeBalance u_balance(int i, int j) const;  // x momentum, u-face with gas
  ControlVolumeBalance v_balance(int i, int j) const;  // y momentum

  // The saddle-point system A x = b: momentum rows of the unknown faces, then continuity
  // rows of the fluid cells. Row and column scales that bring it to O(1) entries for the
  // pivoting (momentum / mu, pressure * h / mu, continuity / h) are applied by
  // solve_stokes (stokes_solve.hpp).
  const CsrPattern& pattern() const { return pattern_; }
  const std::vector<Real>& values() const { return values_; }
  const std::vector<Real>& rhs() const { return rhs_; }
  const std::vector<Real>& row_scale() const { return row_scale_; }
  const std::vector<Real>& column_scale() const { return column_scale_; }

 private:
  std::optional<AffineForm> face(int i, int j, bool vertical) const;
  Across across_cell(int i, int j, Side beyond) const;
  ControlVolumeBalance balance(int i, int j, bool vertical) const;
  void assemble();

  const MacGrid& grid_;
  StokesProblem problem_;
  Index n_ = 0, n_u_ = 0, n_v_ = 0;
  std::vector<Index> u_index_, v_index_, p_index_;  // -1: no unknown
  CsrPattern pattern_;
  std::vector<Real> values_, rhs_, row_scale_, column_scale_;
};

}  // namespace rfmems

// Least-squares interpolation to the immersed-boundary faces (thesis ch. 6; the fit of
// Ollivier-Gooch & Van Altena 2002 as in fv/polynomial_reconstruction, centred on the face).
//
// For each IB face f (centroid x_f, beside FLUID cell c_f) the value phi(x_f) is a fixed
// linear combination of stencil values,
//
//   phi_f = sum_j w_j phi_j,   j over FLUID cells near c_f and wall points,
//
// from the weighted least-squares polynomial of degree p centred at x_f,
//
//   min sum_j omega_j (P(x_j - x_f) - phi_j)^2,   P(d) = a_0 + a_1 dx + a_2 dy + a_3 dx^2/2 + ...,
//
// phi_f = a_0, omega_j = 1 / max(|x_j - x_f| / h, 1/2)^2, h = sqrt(area of c_f). Wall points
// are the midpoints of the surface segments (the structure's faces) with a prescribed
// (Dirichlet) value: the wall velocity, a wall potential, the distribution function leaving
// the wall. Degree 2 makes the map exact for quadratic fields (third-order accurate for
// smooth ones); degree 1 exact for linear fields (second order).
//
// The stencil: ring 1 is c_f and its FLUID face neighbours, each further ring adds the FLUID
// neighbours of the last; wall points are the admissible segments whose midpoint lies within
// (rings + 1/2) h of x_f (so the body must be thicker than that reach, or wall points of the
// far side would enter). `wall_point_admissible` lets a caller drop segments, e.g. for the
// ESBGK gas the faces at which ordinate c does not leave the wall (c . n <= 0).
//
// The one-sided corner case (thesis ch. 7). Where admissible wall points exist on one
// side of a corner only, or none at all (all wall points dropped), x_f is no longer
// surrounded by its stencil: the value is extrapolated, the fit's condition number grows and
// it amplifies the data (sum |w_j|, the Lebesgue constant, grows; > 1 means overshoot, and
// for distribution functions possibly negative values).
//   Detection: a stencil is one-sided when x_f lies outside the convex hull of its points
//   (Boost.Geometry convex_hull + covered_by; on the hull is the face on the surface, between
//   its wall points, and not one-sided).
//   Handling, by kappa = sigma_max / sigma_min of the column-scaled weighted least-squares
//   matrix (SVD) and by the Lebesgue constant:
//     for degree = p, p-1, ..., 0: for rings = 1, ..., max_rings:
//       accept the first stencil with at least as many points as coefficients,
//       kappa <= max_condition and sum |w_j| <= max_lebesgue;
//   i.e. widen the stencil first, then fall back to a lower degree: first order, and as the
//   last resort degree 0 (the weighted mean of ring 1, always accepted, sum |w| = 1).
// Each face records its degree, rings, kappa, Lebesgue constant and whether it is one-sided.
// Measured on a beam in a 32 x 32 mesh (test_ib_interpolation): two-sided quadratic fits
// have kappa 2.6-10.5 and sum |w| 1.3-2.3; a one-sided quadratic extrapolation half a cell
// beyond its fluid cells has kappa 18.5 and sum |w| 3.5, so the default bound 2.5 sends those
// faces to a linear fit (kappa 4.6, sum |w| = 2, second order) and leaves every two-sided
// face quadratic.
#pragma once
#include <functional>
#include <span>
#include <vector>

#include "core/types.hpp"
#include "ibm/cell_marking.hpp"
#include "ibm/immersed_surface.hpp"
#include "mesh/mesh.hpp"

namespace rfmems {

struct IbInterpolationOptions {
  int degree = 2;               // highest degree of the fit: 2, 1 or 0
  bool use_wall_points = true;  // false: extrapolate from the FLUID cells alone
  int max_rings = 3;            // widest stencil tried before a lower degree
  Real max_condition = 1e3;     // criterion on kappa of the scaled weighted fit
  Real max_lebesgue = 2.5;      // criterion on sum |w_j|
  // A fit needs at least this many stencil points per coefficient (1: square systems allowed).
  Real min_points_per_coefficient = 1.0;
  // Wall points may use segment k only if this returns true (empty: all
  // segments).
  std::function<bool(Index segment)> wall_point_admissible;
};

struct IbStencilPoint {
  enum class Kind { FluidCell, WallPoint };
  Kind kind;
  Index index;  // the cell, or the surface segment
  Real weight;  // phi(x_f) = sum_j weight_j phi_j
  // grad phi(x_f) = sum_j gradient_weight_j phi_j (the fit's gradient; zero for degree 0)
  Vec3 gradient_weight;
};

struct IbFaceFit {
  int degree = 0;
  int rings = 0;
  Real condition = 0;  // kappa of the accepted fit
  Real lebesgue = 0;   // sum |w_j|
  bool one_sided = false;
};

class IbInterpolation {
 public:
  IbInterpolation(const Mesh& background, const CellMarking& marking, const ImmersedSurface& body,
                  IbInterpolationOptions options = {});
  // The thesis's step 1 for the gas (ch. 6): values at the surface segments' midpoints
  // (the structure's faces) from the FLUID cells alone, seeded at the FLUID cell nearest each
  // midpoint; the same fit and rule (an extrapolation by about a cell, so most of these
  // stencils are one-sided). face(k) is then segment k.
  // The default options allow sum |w| <= 8 there (an extrapolation a cell beyond the fluid
  // amplifies more than an IB face's, and the 2.5 of the IB faces would leave only degree 0)
  // and ask 1.5 points per coefficient, up to 4 rings. Measured (circle, 16..128 cells): with
  // the IB-face options, 3-point linear fits at the diagonal walls (sum |w| = 4.7) spoiled the
  // order to 1.1; with these every stencil is quadratic (sum |w| <= 8) and the order is 2.8.
  static IbInterpolationOptions surface_point_options();
  static IbInterpolation to_surface_points(
      const Mesh& background, const CellMarking& marking, const ImmersedSurface& body,
      IbInterpolationOptions options = surface_point_options());

  Index n_faces() const { return static_cast<Index>(faces_.size()); }
  // The background face of IB face k (marking.ib_faces[k]); for to_surface_points, segment k.
  Index face(Index k) const { return faces_[k]; }
  const Vec3& target(Index k) const { return targets_[k]; }
  std::span<const IbStencilPoint> stencil(Index k) const {
    return {points_.data() + offsets_[k], static_cast<std::size_t>(offsets_[k + 1] - offsets_[k])};
  }
  const IbFaceFit& fit(Index k) const { return fits_[k]; }
  Index count_one_sided() const;
  Index count_degree(int degree) const;

  // phi at IB face k from values per background cell and per surface segment
  // (wall_values may be empty when no stencil uses a wall point).
  Real interpolate(Index k, std::span<const Real> cell_values,
                   std::span<const Real> wall_values) const;
  std::vector<Real> interpolate(std::span<const Real> cell_values,
                                std::span<const Real> wall_values) const;
  // The fit's gradient at IB face k (zero for a degree-0 face).
  Vec3 gradient(Index k, std::span<const Real> cell_values,
                std::span<const Real> wall_values) const;

 private:
  IbInterpolation() = default;
  void add(Index id, const Vec3& x, std::vector<IbStencilPoint> stencil, const IbFaceFit& fit);
  std::vector<Index> faces_;
  std::vector<Vec3> targets_;
  std::vector<Index> offsets_{0};
  std::vector<IbStencilPoint> points_;
  std::vector<IbFaceFit> fits_;
};

}  // namespace rfmems

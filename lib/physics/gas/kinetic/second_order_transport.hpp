// Second-order upwind face values for the discrete-velocity transport
// (docs/kinetic.md "Second-order transport"), applied by deferred correction.
//
// Per cell c and ordinate k a linear reconstruction f_ck(x) = f_ck + phi_ck g_ck . (x - x_c):
//   g_ck  least-squares gradient over the face neighbours, weights 1/|x_j - x_c|^2
//         (exact for linear data on any mesh, so the face values are second order);
//   phi_ck a slope limiter over the cell's faces (every interior face, and the boundary faces
//         when boundary reconstruction is on) with the bounds min/max of f_k over c and its
//         face neighbours.
// Limiters:
//   Venkatakrishnan (1995, the default): phi = min_f ((D^2 + e^2) d + 2 d^2 D) /
//     (d (D^2 + 2 d^2 + d D + e^2)), d = g . (x_f - x_c), D the bound's distance from f_ck; it
//     is smooth (the lagged deferred-correction iteration does not chatter) and with e^2 > 0
//     it leaves smooth extrema alone: the limiter does not bring back first-order numerical
//     viscosity near the continuum, where f_k varies by ~1e-4 of itself and every ordinate
//     has spatial extrema. e^2 = (K h_c / L)^3 M_ck^2 (Venkatakrishnan's (K h)^3 made
//     dimensionless: h_c = the cell's size V^(1/dim), L the mesh's largest extent,
//     M_ck = max |f_k| over the stencil): at a free-molecular discontinuity (jumps of O(M))
//     it limits, overshooting the bounds by at most ~e.
//   Barth-Jespersen (1989): phi = min_f min(1, D / d): the face values stay within the bounds
//     exactly (a positive f stays positive), but it clips smooth extrema to first order.
//
// Deferred correction: the solvers keep the first-order operator as the approximate inverse;
// the operator adds the lagged bracket D_ck = [F_2(f) - F_1(f)]_ck (the second-order minus the
// first-order net outflow of cell c, ordinate k) to the residual, D computed from the state of
// the last residual evaluation (kinetic_operator.hpp): at convergence r_1(f) + D(f) = r_2(f) = 0.
// D is accumulated face by face, +flux to the owner and -flux to the neighbour, so the
// correction is conservative (it sums to zero over the cells, up to boundary faces).
#pragma once
#include <span>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "fv/face_graph.hpp"
#include "parallel/communicator.hpp"

namespace rfmems {

enum class TransportOrder { FirstOrder, SecondOrder };
enum class SlopeLimiter { Venkatakrishnan, BarthJespersen, None };

TransportOrder transport_order_from_name(const std::string& name);  // first_order | second_order
const char* transport_order_name(TransportOrder order);
SlopeLimiter slope_limiter_from_name(
    const std::string& name);  // venkatakrishnan | barth_jespersen | none
const char* slope_limiter_name(SlopeLimiter limiter);

struct TransportScheme {
  TransportOrder order = TransportOrder::FirstOrder;
  SlopeLimiter limiter = SlopeLimiter::Venkatakrishnan;
  Real venkatakrishnan_k = 1.0;  // K of e^2 = (K h / L)^3 M^2
  // Boundary faces (not External): with true the owner's reconstructed values feed the
  // boundary condition (outgoing ordinates, and through them the diffuse wall's re-emission and
  // the specular / symmetry reflection); with false a boundary face keeps the first-order
  // values (the owner's cell value).
  bool reconstruct_boundaries = true;
};

// The geometry of the reconstruction: LS gradient weights and face offsets, per cell.
class LinearReconstruction {
 public:
  // comm: the ranks of a distributed graph (collective), whose largest extent L is the
  // global mesh's, so every part limits as the serial run does.
  explicit LinearReconstruction(const FaceGraph& graph,
                                const Communicator& comm = Communicator::serial());

  // Limited slopes phi_ck g_ck of the owned cells from f (cell-major, n ordinates), into
  // slopes[(c * n + k) * dim + d]; ghost rows untouched.
  void limited_slopes(std::span<const Real> f, Index n, const TransportScheme& scheme,
                      bool limit_on_boundary_faces, std::span<Real> slopes) const;

  // The same for one cell c (owned, or a ghost whose stencil is complete), into out[k * dim + d].
  void cell_slopes(Index c, std::span<const Real> f, Index n, const TransportScheme& scheme,
                   bool limit_on_boundary_faces, std::span<Real> out) const;

  int dim() const { return dim_; }

 private:
  const FaceGraph& graph_;
  int dim_;
  Real length_;                  // the mesh's largest extent (over every rank)
  std::vector<Vec3> weights_;    // per cell_faces entry: grad = sum w_j (f_j - f_c); 0 on boundary
  std::vector<Vec3> offsets_;    // per cell_faces entry: x_f - x_c
  std::vector<Real> cell_size_;  // V^(1/dim)
  // Per-ordinate scratch of cell_slopes (the operator is used by one thread at a time).
  mutable std::vector<Real> scratch_lo_, scratch_hi_, scratch_phi_;
};

// One limiter factor for a face: the largest phi in [0, 1] that keeps f_c + phi d within
// [f_c + lower, f_c + upper] (lower <= 0 <= upper), Venkatakrishnan's smooth version with e2.
Real limiter_factor(SlopeLimiter limiter, Real d, Real lower, Real upper, Real e2);

}  // namespace rfmems

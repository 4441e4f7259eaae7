// The steady (and semi-discrete transient) discrete-velocity BGK / ESBGK equation on a FaceGraph,
// cell-centred finite volumes with first-order upwind convection (thesis eq. 5.7, 5.9):
//
//   V_c df_ck/dt + r_ck = 0,
//   r_ck = sum_{faces f of c} [ (c_k . S_f)^+ f_ck + (c_k . S_f)^- f_k,upwind(f) ]
//          - V_c nu_c (f_eq,ck - f_ck),
//
// S_f the area vector outward from c, (x)^+ = max(x, 0), (x)^- = min(x, 0), f_upwind the
// neighbour's value or, on a boundary face, the incoming value of the boundary condition
// (kinetic_boundary.hpp). nu_c and f_eq,c are functions of the cell's moments: the collision
// frequency of KineticGas and the discrete-conservative equilibrium (equilibrium.hpp), so
// sum_k w_k phi_k r_ck over a cell is exactly the net flux of mass, momentum, energy.
//
// Layout: f[c * N + k], cell-major (all N ordinates of a cell contiguous): COMET solves a cell's
// ordinates together and a ghost exchange sends whole cells. Cells [0, n_owned) carry equations;
// ghost cells (if any) only supply upwind values.
//
// The operator caches, per cell, the macroscopic state, the equilibrium coefficients (so each
// Newton warm-starts from the last ones), f_eq and nu, and per boundary face the face values;
// update_collision / update_boundary_values refresh them from a state f. A solver reads the
// pieces it needs: outgoing coefficients sum_f (c_k . S_f)^+ and the incoming flux
// sum_f (c_k . S_f)^- f_upwind of a cell, the cached f_eq and nu.
//
// Distributed runs (parallel/distributed_mesh.hpp): the graph is a rank's part with its ghost
// cells; set_parallel gives the communicator and the ghost exchange. Solvers call
// exchange_ghosts after they change f; norms, masses and wall integrals are summed over the
// ranks (owned cells and their faces only), so every rank sees the global figures.
//
// Second-order transport (second_order_transport.hpp, set_transport): the residual gains the
// lagged deferred correction D(f) = F_2(f) - F_1(f), refreshed by residual(f, r) (and
// update_transport_correction) from the state it is evaluated at, and carried by
// incoming_flux (so every solver that reassembles the residual from the pieces sees it, the
// downwind sweep through transport_correction). With boundary reconstruction the cached
// boundary face values (and the wall integrals) are those of the owner's reconstructed values,
// External faces included (their source gets the reconstruction as the leaving values). Under
// MPI the reconstruction's length scale (the limiter's e^2) is the global mesh's, so a part
// limits as the serial run does.
// First order (the default): no correction, the operator is the first-order one above.
//
// Periodic patches (kinetic_boundary.hpp): each face is paired at construction with the face
// of the partner patch at its position translated by the offset between the two patches'
// centroids; its incoming values are the partner owner's values at the partner face.
//
// Body force (set_body_force; acceleration a, m/s^2): the term a . grad_c f of the kinetic
// equation, with f replaced by the cell's equilibrium f_eq (Gaussian of covariance Lambda,
// R T I for BGK): a . grad_c f_eq = -(Lambda^-1 a) . (c - u) f_eq, so the residual gains
//   - V_c s_ck,  s_ck = (Lambda_c^-1 a) . (c_k - u_c) f_eq,ck,
// which adds no mass and the momentum rho a exactly (the discrete equilibrium has the exact
// moments rho, u, Lambda). In the linear regime it is the pressure gradient
// dp/dx = -rho a of Poiseuille flow (Sharipov & Seleznev 1998): a periodic channel with a
// body force is the fully developed flow of a long one.
//
// Residual scaling shared by every kinetic solver: ||r||_2 over all owned (cell, ordinate)
// pairs, reported as ||r||_2 / ||r_0||_2 with r_0 the residual of the initial state;
// "converged" means that ratio <= 1e-6.
#pragma once
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "fv/face_graph.hpp"
#include "parallel/communicator.hpp"
#include "physics/gas/kinetic/equilibrium.hpp"
#include "physics/gas/kinetic/external_face_values.hpp"
#include "physics/gas/kinetic/kinetic_boundary.hpp"
#include "physics/gas/kinetic/kinetic_gas.hpp"
#include "physics/gas/kinetic/macroscopic_state.hpp"
#include "physics/gas/kinetic/second_order_transport.hpp"
#include "physics/gas/kinetic/velocity_grid.hpp"

namespace rfmems {

class GhostExchange;

// Density, velocity and temperature of a local Maxwellian (initial states).
struct GasState {
  Real rho = 0;
  Vec3 u = Vec3::Zero();
  Real T = 0;
};

class KineticOperator {
 public:
  // The graph must outlive the operator. boundaries: one per patch of the graph.
  KineticOperator(const FaceGraph& graph, VelocityGrid grid, KineticGas gas,
                  std::vector<KineticBoundary> boundaries);

  const FaceGraph& graph() const { return *graph_; }
  const VelocityGrid& grid() const { return grid_; }
  const KineticGas& gas() const { return gas_; }
  const std::vector<KineticBoundary>& boundaries() const { return boundaries_; }
  Index n_cells() const { return graph_->n_cells(); }
  Index n_owned_cells() const { return graph_->n_owned_cells; }
  Index n_ordinates() const { return grid_.size(); }
  // Length of f: n_cells * n_ordinates.
  Index size() const { return n_cells() * n_ordinates(); }

  // f = the discrete equilibrium of the gas's model with moments rho, u, covariance R T I of
  // state(x_c) in every cell (a fixed point of the collision operator).
  void initialize(std::span<Real> f, const std::function<GasState(const Vec3&)>& state);

  // --- distribution over ranks (serial: a no-op) ---
  void set_parallel(const Communicator& comm, const GhostExchange* exchange);
  const Communicator& communicator() const { return comm_; }
  // The exchange of set_parallel (null in a serial run): COMET builds its coarse levels on it.
  const GhostExchange* ghost_exchange() const { return exchange_; }
  // Refreshes the ghost cells' distributions from their owners.
  void exchange_ghosts(std::span<Real> f) const;
  // ||r||_2 over the owned rows of every rank.
  Real global_norm(std::span<const Real> r) const;

  // --- collision: macros, equilibrium (warm-started Newton), nu, per owned cell ---
  void update_collision(std::span<const Real> f);
  void update_collision(Index cell, std::span<const Real> f_cell);
  const MacroState& macro(Index c) const { return macro_[c]; }
  const EquilibriumTarget& target(Index c) const { return target_[c]; }
  const EquilibriumCoefficients& coefficients(Index c) const { return coefficients_[c]; }
  std::span<const Real> equilibrium(Index c) const {
    return {f_eq_.data() + c * n_ordinates(), static_cast<std::size_t>(n_ordinates())};
  }
  Real collision_frequency(Index c) const { return nu_[c]; }
  // Newton iterations of the last update_collision(f) (sum over cells).
  long equilibrium_iterations() const { return equilibrium_iterations_; }

  // --- transport ---
  // The face-value scheme (default first order). Second order builds the reconstruction's
  // geometry; the correction is zero until the next residual / update_transport_correction.
  void set_transport(const TransportScheme& scheme);
  const TransportScheme& transport() const { return transport_; }
  bool second_order() const { return transport_.order == TransportOrder::SecondOrder; }
  // Recomputes D(f) = F_2(f) - F_1(f) for the owned cells (second order; else a no-op); the
  // boundary values must be current (update_boundary_values(f)).
  void update_transport_correction(std::span<const Real> f);
  // D of cell c (all ordinates), empty with first order.
  std::span<const Real> transport_correction(Index c) const {
    if (correction_.empty()) return {};
    return {correction_.data() + c * n_ordinates(), static_cast<std::size_t>(n_ordinates())};
  }
  // The source of the face values of External patches (external_face_values.hpp); required
  // before any face value of such a patch is asked for. Null detaches it.
  void set_external_face_values(ExternalFaceValues* source) { external_ = source; }
  // Refreshes the face values of every boundary face from f.
  void update_boundary_values(std::span<const Real> f);
  // Face values of boundary face `face` from f, into out (not cached): the condition fed with
  // the owner's values at the face (second order with boundary reconstruction: the owner's
  // reconstruction, also for External faces; external_face_values.hpp).
  void face_values(Index face, std::span<const Real> f, std::span<Real> out) const;
  // The same for one face.
  void update_boundary_values(Index face, std::span<const Real> f);
  // Cached face values (all ordinates) of boundary face `face`.
  std::span<const Real> boundary_values(Index face) const;
  std::span<Real> boundary_values(Index face);
  // out_k = sum_f (c_k . S_f)^+ over the faces of cell c (>= 0).
  void outgoing_coefficients(Index c, std::span<Real> out) const;
  // in_k = sum_f (c_k . S_f)^- f_k,upwind (<= 0): neighbours' values from f, boundary faces'
  // from the cached boundary values; plus the lagged correction D_ck with second order.
  void incoming_flux(Index c, std::span<const Real> f, std::span<Real> in) const;
  // Reflection map of a boundary face (empty unless its condition needs one).
  std::span<const Index> reflection(Index face) const;
  // The discrete Maxwellian of patch p's condition (boundary_maxwellian; empty if none).
  std::span<const Real> boundary_maxwellian(int patch) const { return patch_maxwellian_[patch]; }

  // --- body force ---
  void set_body_force(const Vec3& acceleration) { body_force_ = acceleration; }
  const Vec3& body_force() const { return body_force_; }
  bool has_body_force() const { return body_force_.squaredNorm() > 0; }
  // s_ck above for every ordinate of owned cell c (the cached macros and equilibrium).
  void body_force_source(Index c, std::span<Real> s) const;
  // Lambda_c^-1 a of cell c (s_ck = that . (c_k - u_c) f_eq,ck).
  Vec3 body_force_gradient(Index c) const;

  // --- periodic faces ---
  // The partner face of a periodic boundary face, -1 for any other face.
  Index periodic_partner(Index face) const {
    return graph_->is_boundary(face) ? periodic_partner_[face - graph_->n_interior_faces] : -1;
  }

  // --- residual ---
  // r (length size(); ghost rows 0) of the steady equation at f: refreshes the boundary
  // values and the collision cache from f first.
  void residual(std::span<const Real> f, std::span<Real> r);
  // The same with the cached collision terms and boundary values (lagged).
  void residual_frozen(std::span<const Real> f, std::span<Real> r) const;
  // ||r(f)||_2 (refreshes the caches like residual()).
  Real residual_norm(std::span<const Real> f);

  // --- walls ---
  // Force of the gas on the patch (N; per unit depth in 2D): the momentum flux through its
  // faces, sum_f sum_k w_k c_k (c_k . S_f) f_face,k, pressure and shear together.
  Vec3 wall_force(int patch, std::span<const Real> f) const;
  Vec3 wall_force(const std::string& patch, std::span<const Real> f) const;
  // Heat flux from the gas into the patch (W; per unit depth in 2D):
  // sum_f sum_k w_k |c_k|^2 / 2 (c_k . S_f) f_face,k (moving walls: includes the work).
  Real wall_heat_flow(int patch, std::span<const Real> f) const;
  // The patch's area (m^2; m per unit depth in 2D), sum_f |S_f|, and its area vector
  // sum_f S_f (outward from the gas; |vector| = area on a flat patch).
  struct PatchArea {
    Real area = 0;
    Vec3 vector = Vec3::Zero();
  };
  PatchArea patch_area(int patch) const;
  // Net mass flow out through the patch (kg/s; per unit depth in 2D).
  Real boundary_mass_flow(int patch, std::span<const Real> f) const;
  // Total mass sum_c V_c rho_c over owned cells (of every rank).
  Real total_mass(std::span<const Real> f) const;
  // True if no patch lets gas in or out (no pressure boundary): the steady state is then
  // defined only up to the total mass, which the solvers pin to the initial state's.
  bool is_closed() const;
  // Scales f so that total_mass(f) = mass (a closed domain's iterate; serial: owned cells).
  void restore_mass(std::span<Real> f, Real mass) const;

 private:
  std::span<const Real> cell(std::span<const Real> f, Index c) const {
    return f.subspan(c * n_ordinates(), n_ordinates());
  }
  // The owner's values at boundary face `face`: its cell values, or with second order and
  // boundary reconstruction its limited reconstruction at the face centroid (into scratch;
  // the span returned is scratch or the cell of f).
  std::span<const Real> owner_values(Index face, std::span<const Real> f,
                                     std::span<Real> scratch) const;
  // The condition of boundary face `face` given the owner's values there (and, for a
  // periodic face, the partner face owner's values at the partner face).
  void condition_values(Index face, std::span<const Real> owner, std::span<Real> out,
                        std::span<const Real> partner = {}) const;
  // Pairs every face of the periodic patches with its partner face (InputError if one has
  // none).
  void pair_periodic_faces();

  // Does boundary face `face` belong to an owned cell (counted by this rank)?
  bool owned_face(Index face) const { return graph_->face_owner[face] < n_owned_cells(); }

  const FaceGraph* graph_;
  Communicator comm_ = Communicator::serial();
  const GhostExchange* exchange_ = nullptr;
  ExternalFaceValues* external_ = nullptr;
  VelocityGrid grid_;
  KineticGas gas_;
  std::vector<KineticBoundary> boundaries_;

  std::vector<MacroState> macro_;
  std::vector<EquilibriumTarget> target_;
  std::vector<EquilibriumCoefficients> coefficients_;
  std::vector<Real> f_eq_;
  std::vector<Real> nu_;
  long equilibrium_iterations_ = 0;

  std::vector<Real> boundary_values_;     // (face - n_interior) * N + k
  std::vector<Real> owner_values_;        // the same layout: the owners' values at the faces
  std::vector<Index> reflection_offset_;  // per boundary face, -1 if none
  std::vector<Index> reflections_;
  std::vector<std::vector<Real>> patch_maxwellian_;  // boundary_maxwellian per patch
  std::vector<Index> periodic_partner_;              // per boundary face, -1 if none
  Vec3 body_force_ = Vec3::Zero();

  TransportScheme transport_;
  std::unique_ptr<LinearReconstruction> reconstruction_;  // second order only
  std::vector<Real> correction_;                          // D, c * N + k (second order only)
  std::vector<Real> slopes_;                              // limited slopes, (c * N + k) * dim + d
};

}  // namespace rfmems

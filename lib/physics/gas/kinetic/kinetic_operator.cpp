#include "physics/gas/kinetic/kinetic_operator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "parallel/ghost_exchange.hpp"

namespace rfmems {

KineticOperator::KineticOperator(const FaceGraph& graph, VelocityGrid grid, KineticGas gas,
                                 std::vector<KineticBoundary> boundaries)
    : graph_(&graph),
      grid_(std::move(grid)),
      gas_(std::move(gas)),
      boundaries_(std::move(boundaries)) {
  gas_.validate();
  if (boundaries_.size() != graph.patch_names.size())
    throw InputError("kinetic operator: " + std::to_string(boundaries_.size()) +
                     " boundary conditions for " + std::to_string(graph.patch_names.size()) +
                     " patches");
  const Index nc = n_cells(), N = n_ordinates();
  macro_.resize(nc);
  target_.resize(nc);
  coefficients_.resize(nc);
  f_eq_.assign(nc * N, 0.0);
  nu_.assign(nc, 0.0);
  const Index nb = graph.n_faces() - graph.n_interior_faces;
  boundary_values_.assign(nb * N, 0.0);
  reflection_offset_.assign(nb, -1);
  for (const KineticBoundary& bc : boundaries_)
    patch_maxwellian_.push_back(rfmems::boundary_maxwellian(bc, grid_, gas_));
  pair_periodic_faces();
  for (Index f = graph.n_interior_faces; f < graph.n_faces(); ++f) {
    const KineticBoundary& bc = boundaries_[graph.face_patch[f]];
    if (!bc.needs_reflection()) continue;
    const Vec3 n = graph.face_area[f].normalized();
    reflection_offset_[f - graph.n_interior_faces] = static_cast<Index>(reflections_.size());
    const std::vector<Index> map = grid_.reflection_map(n);
    reflections_.insert(reflections_.end(), map.begin(), map.end());
  }
}

void KineticOperator::pair_periodic_faces() {
  const FaceGraph& g = *graph_;
  const Index n0 = g.n_interior_faces;
  periodic_partner_.assign(g.n_faces() - n0, -1);
  // The mean face centroid of each patch, and a length scale for matching positions.
  const std::size_t np = g.patch_names.size();
  std::vector<Vec3> centroid(np, Vec3::Zero());
  std::vector<int> count(np, 0);
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (Index f = n0; f < g.n_faces(); ++f) {
    centroid[g.face_patch[f]] += g.face_centroid[f];
    ++count[g.face_patch[f]];
    lo = lo.cwiseMin(g.face_centroid[f]);
    hi = hi.cwiseMax(g.face_centroid[f]);
  }
  const Real tolerance = 1e-9 * (hi - lo).norm();
  for (Index f = n0; f < g.n_faces(); ++f) {
    const KineticBoundary& bc = boundaries_[g.face_patch[f]];
    if (bc.kind != KineticBoundaryKind::Periodic) continue;
    const int p = g.face_patch[f], q = g.find_patch(bc.partner);
    if (q < 0 || count[q] != count[p])
      throw InputError("periodic patch '" + g.patch_names[p] + "': partner '" + bc.partner +
                       "' is missing or has another number of faces");
    const Vec3 shift = centroid[q] / count[q] - centroid[p] / count[p];
    for (Index h = n0; h < g.n_faces(); ++h)
      if (g.face_patch[h] == q &&
          (g.face_centroid[h] - g.face_centroid[f] - shift).norm() <= tolerance &&
          (g.face_area[h] + g.face_area[f]).norm() <= 1e-9 * g.face_area[f].norm()) {
        periodic_partner_[f - n0] = h;
        break;
      }
    if (periodic_partner_[f - n0] < 0)
      throw InputError("periodic patch '" + g.patch_names[p] +
                       "': a face has no matching face on '" + bc.partner +
                       "' (the patches must be translates of each other)");
  }
}

Vec3 KineticOperator::body_force_gradient(Index c) const {
  return target_[c].covariance.ldlt().solve(body_force_);
}

void KineticOperator::body_force_source(Index c, std::span<Real> s) const {
  const Index N = n_ordinates();
  const Vec3 a = body_force_gradient(c);
  const Vec3& u = macro_[c].u;
  const Real* feq = f_eq_.data() + c * N;
  for (Index k = 0; k < N; ++k) s[k] = a.dot(grid_.c[k] - u) * feq[k];
}

void KineticOperator::initialize(std::span<Real> f,
                                 const std::function<GasState(const Vec3&)>& state) {
  const Index N = n_ordinates();
  for (Index c = 0; c < n_cells(); ++c) {
    const GasState s = state(graph_->cell_centroid[c]);
    const EquilibriumTarget t = maxwellian_target(s.rho, s.u, s.T, gas_);
    EquilibriumCoefficients a;
    solve_equilibrium(t, gas_.model, grid_, a);
    evaluate_equilibrium(a, grid_, f.subspan(c * N, N));
  }
  update_boundary_values(f);
  update_collision(f);
}

void KineticOperator::update_collision(Index c, std::span<const Real> f_cell) {
  macro_[c] = cell_moments(f_cell, grid_, gas_);
  target_[c] = equilibrium_target(macro_[c], gas_);
  // f_eq_ of cell c always holds the values of coefficients_[c] (or nothing yet), which
  // solve_equilibrium refreshes only if they changed.
  const Index N = n_ordinates();
  const EquilibriumSolveInfo info = solve_equilibrium(
      target_[c], gas_.model, grid_, coefficients_[c], std::span<Real>(f_eq_.data() + c * N, N));
  equilibrium_iterations_ += info.iterations;
  nu_[c] = gas_.collision_frequency(macro_[c].rho, macro_[c].T);
}

void KineticOperator::update_collision(std::span<const Real> f) {
  equilibrium_iterations_ = 0;
  for (Index c = 0; c < n_owned_cells(); ++c) update_collision(c, cell(f, c));
}

std::span<const Index> KineticOperator::reflection(Index face) const {
  const Index off = reflection_offset_[face - graph_->n_interior_faces];
  if (off < 0) return {};
  return {reflections_.data() + off, static_cast<std::size_t>(n_ordinates())};
}

std::span<const Real> KineticOperator::owner_values(Index face, std::span<const Real> f,
                                                    std::span<Real> scratch) const {
  const Index owner = graph_->face_owner[face];
  if (!(second_order() && transport_.reconstruct_boundaries && owner < n_owned_cells()))
    return cell(f, owner);
  // The owner's reconstructed values at the face feed the condition (outgoing ordinates, the
  // diffuse wall's re-emission, the reflection, an External source), from the owner's slopes
  // at this f.
  const Index N = n_ordinates();
  const int D = reconstruction_->dim();
  std::vector<Real> slopes(N * D);
  reconstruction_->cell_slopes(owner, f, N, transport_, true, slopes);
  const Vec3 x = graph_->face_centroid[face] - graph_->cell_centroid[owner];
  const std::span<const Real> fo = cell(f, owner);
  for (Index k = 0; k < N; ++k) {
    Real v = fo[k];
    for (int d = 0; d < D; ++d) v += slopes[k * D + d] * x[d];
    scratch[k] = v;
  }
  return scratch;
}

void KineticOperator::condition_values(Index face, std::span<const Real> owner, std::span<Real> out,
                                       std::span<const Real> partner) const {
  const FaceGraph& g = *graph_;
  const int p = g.face_patch[face];
  if (boundaries_[p].kind == KineticBoundaryKind::Periodic) {
    // Outgoing: the owner's; incoming: those leaving through the partner face.
    const Vec3& S = g.face_area[face];
    for (Index k = 0; k < n_ordinates(); ++k)
      out[k] = grid_.c[k].dot(S) >= 0 ? owner[k] : partner[k];
    return;
  }
  if (boundaries_[p].kind == KineticBoundaryKind::External) {
    if (!external_) throw std::logic_error("kinetic operator: external patch without a source");
    external_->fill(face, owner, out);
    return;
  }
  fill_boundary_face(boundaries_[p], g.face_area[face], owner, grid_, reflection(face),
                     patch_maxwellian_[p], out);
}

void KineticOperator::face_values(Index face, std::span<const Real> f, std::span<Real> out) const {
  std::vector<Real> scratch(second_order() ? n_ordinates() : 0);
  const Index partner = periodic_partner(face);
  std::vector<Real> partner_scratch(partner >= 0 && second_order() ? n_ordinates() : 0);
  condition_values(
      face, owner_values(face, f, scratch), out,
      partner >= 0 ? owner_values(partner, f, partner_scratch) : std::span<const Real>{});
}

void KineticOperator::set_transport(const TransportScheme& scheme) {
  transport_ = scheme;
  if (!second_order()) {
    reconstruction_.reset();
    correction_.clear();
    slopes_.clear();
    return;
  }
  reconstruction_ = std::make_unique<LinearReconstruction>(*graph_, comm_);
  correction_.assign(n_cells() * n_ordinates(), 0.0);
  slopes_.assign(n_cells() * n_ordinates() * reconstruction_->dim(), 0.0);
}

void KineticOperator::update_transport_correction(std::span<const Real> f) {
  if (!second_order()) return;
  const FaceGraph& g = *graph_;
  const Index N = n_ordinates();
  const int D = reconstruction_->dim();
  reconstruction_->limited_slopes(f, N, transport_, transport_.reconstruct_boundaries, slopes_);
  // Ghost cells' slopes from their owners (their stencils are incomplete here).
  if (exchange_) exchange_->exchange(slopes_, static_cast<int>(N * D));
  std::fill(correction_.begin(), correction_.end(), 0.0);
  // Interior faces: (c.S) times the upwind side's reconstruction increment, + to the owner,
  // - to the neighbour (conservative).
  for (Index face = 0; face < g.n_interior_faces; ++face) {
    const Index o = g.face_owner[face], nb = g.face_neighbour[face];
    const Vec3& S = g.face_area[face];
    const Vec3 xo = g.face_centroid[face] - g.cell_centroid[o];
    const Vec3 xn = g.face_centroid[face] - g.cell_centroid[nb];
    const Real* so = slopes_.data() + o * N * D;
    const Real* sn = slopes_.data() + nb * N * D;
    Real* ro = correction_.data() + o * N;
    Real* rn = correction_.data() + nb * N;
    for (Index k = 0; k < N; ++k) {
      const Real s = grid_.c[k].dot(S);
      const Real* slope = s > 0 ? so + k * D : sn + k * D;
      const Vec3& x = s > 0 ? xo : xn;
      Real delta = 0;
      for (int d = 0; d < D; ++d) delta += slope[d] * x[d];
      ro[k] += s * delta;
      rn[k] -= s * delta;
    }
  }
  // Boundary faces with reconstruction: the incoming values (cached) already are the
  // second-order ones; the outgoing flux gains (c.S)^+ (f_face - f_c). External faces too:
  // their source was given the same reconstruction as the leaving values (its mass-flux
  // balance, ib_kinetic_face_values.hpp, then holds for the flux the residual carries).
  if (!transport_.reconstruct_boundaries) return;
  for (Index face = g.n_interior_faces; face < g.n_faces(); ++face) {
    const Index o = g.face_owner[face];
    if (o >= n_owned_cells()) continue;
    const Vec3& S = g.face_area[face];
    const Vec3 xo = g.face_centroid[face] - g.cell_centroid[o];
    const Real* so = slopes_.data() + o * N * D;
    Real* ro = correction_.data() + o * N;
    for (Index k = 0; k < N; ++k) {
      const Real s = grid_.c[k].dot(S);
      if (s <= 0) continue;
      Real delta = 0;
      for (int d = 0; d < D; ++d) delta += so[k * D + d] * xo[d];
      ro[k] += s * delta;
    }
  }
}

void KineticOperator::update_boundary_values(Index face, std::span<const Real> f) {
  face_values(face, f, boundary_values(face));
}

void KineticOperator::update_boundary_values(std::span<const Real> f) {
  const Index N = n_ordinates(), n0 = graph_->n_interior_faces;
  owner_values_.resize(boundary_values_.size());
  for (Index face = n0; face < graph_->n_faces(); ++face) {
    const std::span<Real> slot(owner_values_.data() + (face - n0) * N, N);
    const std::span<const Real> v = owner_values(face, f, slot);
    if (v.data() != slot.data()) std::copy(v.begin(), v.end(), slot.begin());
  }
  if (external_) external_->update(f, owner_values_);
  auto at = [&](Index face) {
    return std::span<const Real>(owner_values_.data() + (face - n0) * N, N);
  };
  for (Index face = n0; face < graph_->n_faces(); ++face)
    condition_values(
        face, at(face), boundary_values(face),
        periodic_partner(face) >= 0 ? at(periodic_partner(face)) : std::span<const Real>{});
}

std::span<const Real> KineticOperator::boundary_values(Index face) const {
  const Index N = n_ordinates();
  return {boundary_values_.data() + (face - graph_->n_interior_faces) * N,
          static_cast<std::size_t>(N)};
}

std::span<Real> KineticOperator::boundary_values(Index face) {
  const Index N = n_ordinates();
  return {boundary_values_.data() + (face - graph_->n_interior_faces) * N,
          static_cast<std::size_t>(N)};
}

void KineticOperator::outgoing_coefficients(Index c, std::span<Real> out) const {
  const FaceGraph& g = *graph_;
  const Index N = n_ordinates();
  std::fill(out.begin(), out.end(), 0.0);
  for (Index i = g.cell_face_offsets[c]; i < g.cell_face_offsets[c + 1]; ++i) {
    const Index face = g.cell_faces[i];
    const Vec3 S = g.face_owner[face] == c ? g.face_area[face] : Vec3(-g.face_area[face]);
    for (Index k = 0; k < N; ++k) out[k] += std::max(grid_.c[k].dot(S), 0.0);
  }
}

void KineticOperator::incoming_flux(Index c, std::span<const Real> f, std::span<Real> in) const {
  const FaceGraph& g = *graph_;
  const Index N = n_ordinates();
  std::fill(in.begin(), in.end(), 0.0);
  for (Index i = g.cell_face_offsets[c]; i < g.cell_face_offsets[c + 1]; ++i) {
    const Index face = g.cell_faces[i];
    const bool owner = g.face_owner[face] == c;
    const Vec3 S = owner ? g.face_area[face] : Vec3(-g.face_area[face]);
    const Real* upwind = g.is_boundary(face)
                             ? boundary_values(face).data()
                             : f.data() + (owner ? g.face_neighbour[face] : g.face_owner[face]) * N;
    for (Index k = 0; k < N; ++k) in[k] += std::min(grid_.c[k].dot(S), 0.0) * upwind[k];
  }
  if (!correction_.empty()) {
    const Real* d = correction_.data() + c * N;
    for (Index k = 0; k < N; ++k) in[k] += d[k];
  }
}

void KineticOperator::residual_frozen(std::span<const Real> f, std::span<Real> r) const {
  const Index N = n_ordinates();
  std::fill(r.begin(), r.end(), 0.0);
  std::vector<Real> out(N), in(N);
  for (Index c = 0; c < n_owned_cells(); ++c) {
    outgoing_coefficients(c, out);
    incoming_flux(c, f, in);
    const Real vnu = graph_->cell_volume[c] * nu_[c];
    const Real* fc = f.data() + c * N;
    const Real* feq = f_eq_.data() + c * N;
    Real* rc = r.data() + c * N;
    for (Index k = 0; k < N; ++k) rc[k] = out[k] * fc[k] + in[k] - vnu * (feq[k] - fc[k]);
    if (has_body_force()) {
      body_force_source(c, in);
      for (Index k = 0; k < N; ++k) rc[k] -= graph_->cell_volume[c] * in[k];
    }
  }
}

void KineticOperator::residual(std::span<const Real> f, std::span<Real> r) {
  update_boundary_values(f);
  update_collision(f);
  update_transport_correction(f);
  residual_frozen(f, r);
}

Real KineticOperator::residual_norm(std::span<const Real> f) {
  std::vector<Real> r(f.size());
  residual(f, r);
  return global_norm(r);
}

void KineticOperator::set_parallel(const Communicator& comm, const GhostExchange* exchange) {
  comm_ = comm;
  exchange_ = exchange;
  if (second_order()) set_transport(transport_);  // the length scale over every rank
}

void KineticOperator::exchange_ghosts(std::span<Real> f) const {
  if (exchange_) exchange_->exchange(f, static_cast<int>(n_ordinates()));
}

Real KineticOperator::global_norm(std::span<const Real> r) const {
  Real s = 0;
  for (Index i = 0; i < n_owned_cells() * n_ordinates(); ++i) s += r[i] * r[i];
  return std::sqrt(comm_.sum(s));
}

Vec3 KineticOperator::wall_force(int patch, std::span<const Real> f) const {
  const FaceGraph& g = *graph_;
  const Index N = n_ordinates();
  std::vector<Real> face(N);
  Vec3 force = Vec3::Zero();
  for (Index fc = g.n_interior_faces; fc < g.n_faces(); ++fc) {
    if (g.face_patch[fc] != patch || !owned_face(fc)) continue;
    face_values(fc, f, face);
    const Vec3& S = g.face_area[fc];
    for (Index k = 0; k < N; ++k) force += (grid_.w[k] * grid_.c[k].dot(S) * face[k]) * grid_.c[k];
  }
  comm_.sum_in_place(std::span<Real>(force.data(), 3));
  return force;
}

Vec3 KineticOperator::wall_force(const std::string& patch, std::span<const Real> f) const {
  const int p = graph_->find_patch(patch);
  if (p < 0) throw InputError("wall force: no patch named '" + patch + "'");
  return wall_force(p, f);
}

Real KineticOperator::wall_heat_flow(int patch, std::span<const Real> f) const {
  const FaceGraph& g = *graph_;
  const Index N = n_ordinates();
  std::vector<Real> face(N);
  Real q = 0;
  for (Index fc = g.n_interior_faces; fc < g.n_faces(); ++fc) {
    if (g.face_patch[fc] != patch || !owned_face(fc)) continue;
    face_values(fc, f, face);
    const Vec3& S = g.face_area[fc];
    for (Index k = 0; k < N; ++k)
      q += grid_.w[k] * 0.5 * grid_.c[k].squaredNorm() * grid_.c[k].dot(S) * face[k];
  }
  return comm_.sum(q);
}

KineticOperator::PatchArea KineticOperator::patch_area(int patch) const {
  const FaceGraph& g = *graph_;
  Real sums[4] = {0, 0, 0, 0};  // area, vector
  for (Index fc = g.n_interior_faces; fc < g.n_faces(); ++fc) {
    if (g.face_patch[fc] != patch || !owned_face(fc)) continue;
    const Vec3& S = g.face_area[fc];
    sums[0] += S.norm();
    for (int d = 0; d < 3; ++d) sums[1 + d] += S[d];
  }
  comm_.sum_in_place(std::span<Real>(sums, 4));
  return {sums[0], Vec3(sums[1], sums[2], sums[3])};
}

Real KineticOperator::boundary_mass_flow(int patch, std::span<const Real> f) const {
  const FaceGraph& g = *graph_;
  const Index N = n_ordinates();
  std::vector<Real> face(N);
  Real m = 0;
  for (Index fc = g.n_interior_faces; fc < g.n_faces(); ++fc) {
    if (g.face_patch[fc] != patch || !owned_face(fc)) continue;
    face_values(fc, f, face);
    const Vec3& S = g.face_area[fc];
    for (Index k = 0; k < N; ++k) m += grid_.w[k] * grid_.c[k].dot(S) * face[k];
  }
  return comm_.sum(m);
}

Real KineticOperator::total_mass(std::span<const Real> f) const {
  const Index N = n_ordinates();
  Real m = 0;
  for (Index c = 0; c < n_owned_cells(); ++c) {
    Real rho = 0;
    for (Index k = 0; k < N; ++k) rho += grid_.w[k] * f[c * N + k];
    m += graph_->cell_volume[c] * rho;
  }
  return comm_.sum(m);
}

// A global answer: a rank's part may touch no pressure boundary while another's does, and the
// mass rescaling it gates is a collective (a local answer deadlocked the squeeze film on 4 ranks).
bool KineticOperator::is_closed() const {
  Index open = 0;
  for (const KineticBoundary& bc : boundaries_)
    if (bc.kind == KineticBoundaryKind::Pressure) open = 1;
  return comm_.sum(open) == 0;
}

void KineticOperator::restore_mass(std::span<Real> f, Real mass) const {
  const Real factor = mass / total_mass(f);
  for (Real& x : f) x *= factor;
}

}  // namespace rfmems

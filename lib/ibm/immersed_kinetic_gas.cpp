#include "ibm/immersed_kinetic_gas.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/process_cpu_clock.hpp"
#include "ibm/background_partition.hpp"
#include "physics/gas/comet/transient_kinetic_system.hpp"
#include "solvers/ida_integrator.hpp"

namespace rfmems {
ImmersedKineticGas::ImmersedKineticGas(const Mesh& background, std::vector<KineticBoundary> outer,
                                       VelocityGrid grid, KineticGas gas,
                                       ImmersedGasOptions options)
    : background_(background),
      background_graph_(face_graph_of(background)),
      marker_(background),
      outer_(std::move(outer)),
      grid_(std::move(grid)),
      gas_(std::move(gas)),
      options_(std::move(options)) {
  if (outer_.size() != background_graph_.patch_names.size())
    throw InputError("immersed gas: " + std::to_string(outer_.size()) +
                     " boundary conditions for " +
                     std::to_string(background_graph_.patch_names.size()) + " patches");
  outer_.push_back(KineticBoundary::external());
}

ImmersedKineticGas::~ImmersedKineticGas() = default;

bool ImmersedKineticGas::closed() const {
  for (const KineticBoundary& b : outer_)
    if (b.kind == KineticBoundaryKind::Pressure) return false;
  return true;
}

// Carries a distribution on the old FLUID graph (fluid_, this rank's) over to `fluid` (the new
// one of this rank) by background cell (see the header); report: counts the cells gained and
// lost (over every rank). Distributed: the owned cells are filled, in passes separated by a
// ghost exchange (values and the "has a value" flags), so each pass sees the donors the
// serial pass sees.
std::vector<Real> ImmersedKineticGas::carry_over(const FluidFaceGraph& fluid,
                                                 const GhostExchange* exchange,
                                                 const std::vector<Real>& from,
                                                 RemarkReport* report) const {
  const Communicator& comm = options_.comm;
  const Index N = grid_.size();
  const Index nb = background_graph_.n_cells(), n_owned = fluid.graph.n_owned_cells;
  std::vector<Real> f(fluid.graph.n_cells() * N, 0.0);
  std::vector<Index> has(fluid.graph.n_cells(), 0);  // per new local cell
  std::vector<Index> pending;
  Index gained = 0, lost = 0;
  for (Index c = 0; c < n_owned; ++c) {
    const Index b = fluid.background_cell[c];
    const Index old = fluid_->fluid_cell[b];  // owned before too: the partition is fixed
    if (old >= 0) {
      std::copy_n(from.data() + old * N, N, f.data() + c * N);
      has[c] = 1;
    } else {
      pending.push_back(c);
      ++gained;
    }
  }
  for (Index b = 0; b < nb; ++b)
    if ((owner_rank_.empty() || owner_rank_[b] == comm.rank()) && fluid_->fluid_cell[b] >= 0 &&
        fluid.fluid_cell[b] < 0)
      ++lost;
  if (report) {
    report->cells_gained += comm.sum(gained);
    report->cells_lost += comm.sum(lost);
  }
  auto refresh_ghosts = [&] {
    if (!exchange) return;
    exchange->exchange(std::span<Real>(f), static_cast<int>(N));
    exchange->exchange(std::span<Index>(has), 1);
  };
  refresh_ghosts();
  const FaceGraph& g = background_graph_;
  while (comm.sum(static_cast<Index>(pending.size())) > 0) {
    std::vector<Index> still, filled;
    for (const Index c : pending) {
      const Index b = fluid.background_cell[c];
      Real wsum = 0;
      Real* fc = f.data() + c * N;
      for (Index i = g.cell_face_offsets[b]; i < g.cell_face_offsets[b + 1]; ++i) {
        const Index face = g.cell_faces[i];
        if (g.is_boundary(face)) continue;
        const Index nbr = g.face_owner[face] == b ? g.face_neighbour[face] : g.face_owner[face];
        const Index l = fluid.fluid_cell[nbr];  // a new FLUID neighbour is held (transport)
        if (l < 0 || !has[l]) continue;
        // Donors: FLUID cells before and after the move, or cells filled in a previous pass.
        const Real w = 1.0 / (g.cell_centroid[nbr] - g.cell_centroid[b]).norm();
        const Real* fs = f.data() + l * N;
        for (Index k = 0; k < N; ++k) fc[k] += w * fs[k];
        wsum += w;
      }
      if (wsum > 0) {
        for (Index k = 0; k < N; ++k) fc[k] /= wsum;
        filled.push_back(c);
      } else {
        still.push_back(c);
      }
    }
    if (comm.sum(static_cast<Index>(filled.size())) == 0)
      throw MeshError("immersed gas: a new FLUID cell has no fluid donor");
    for (const Index c : filled) has[c] = 1;
    pending = std::move(still);
    refresh_ghosts();
  }
  return f;
}

void ImmersedKineticGas::partition_background(const CellMarking& rest) {
  Partition p = partition_fluid_background(background_, rest, options_.comm);
  owner_rank_ = std::move(p.part);
  partition_.ranks = p.n_parts;
  partition_.edge_cut = p.edge_cut;
  partition_.imbalance = p.imbalance;
}

void ImmersedKineticGas::rebuild_graph(const CellMarking& marking) {
  auto global = std::make_unique<FluidFaceGraph>(fluid_face_graph(background_graph_, marking));
  std::unique_ptr<FluidGraphPart> part;
  const FluidFaceGraph* fluid = global.get();
  if (distributed()) {
    if (owner_rank_.empty()) partition_background(marking);
    // The widest IB stencil: 4 rings from a surface point's seed (step i), 3 from an IB
    // face's FLUID cell (step iii), the seed next to the body's cells; checked by
    // LocalIbFaceValues::covers_every_stencil in set_body, which widens the band if not.
    if (partition_.band_rings == 0)
      partition_.band_rings = options_.band_rings > 0
                                  ? options_.band_rings
                                  : std::max(options_.ib.face_options.max_rings,
                                             options_.ib.surface_options.max_rings) +
                                        1;
    part = std::make_unique<FluidGraphPart>(restrict_fluid_graph(
        *global, background_graph_, marking, owner_rank_, options_.comm, partition_.band_rings));
    fluid = &part->local;
    partition_.owned_cells = fluid->graph.n_owned_cells;
    partition_.ghost_cells = fluid->graph.n_cells() - fluid->graph.n_owned_cells;
  }
  auto op = std::make_unique<KineticOperator>(fluid->graph, grid_, gas_, outer_);
  if (part) op->set_parallel(options_.comm, &part->exchange);
  op->set_transport(options_.transport);
  remark_ = RemarkReport{};
  remark_.reclassified = true;
  if (has_state_) {
    remark_.mass_before = op_->total_mass(f_);
    // The predictor's f^(n-1) goes over the same way (BDF2 itself restarts, below).
    std::vector<Real> carried_previous;
    const GhostExchange* exchange = part ? &part->exchange : nullptr;
    if (options_.predictor && !f_previous_.empty() && dt_previous_ > 0)
      carried_previous = carry_over(*fluid, exchange, f_previous_, nullptr);
    std::vector<Real> f = carry_over(*fluid, exchange, f_, &remark_);
    predictor_previous_ = std::move(carried_previous);
    f_ = std::move(f);
    remark_.mass_carried = op->total_mass(f_);
    // The gas between the IB faces and the body (not simulated) at rho_ref: the FLUID area
    // grows by dA, so the FLUID mass grows by rho_ref dA (see the header). The areas of the
    // global graphs (every rank has them; the serial sums).
    Real area_old = 0, area_new = 0;
    for (Real v : global_fluid_->graph.cell_volume) area_old += v;
    for (Real v : global->graph.cell_volume) area_new += v;
    remark_.mass_target = remark_.mass_before + reference_density_ * (area_new - area_old);
    if (options_.conserve_mass_on_remark && closed()) op->restore_mass(f_, remark_.mass_target);
    remark_.mass_after = op->total_mass(f_);
  }
  point_.reset();  // its outgoing coefficients are those of the old operator
  op_ = std::move(op);
  global_fluid_ = std::move(global);
  part_ = std::move(part);
  band_buffer_.clear();  // a new band: refilled with NaN by LocalIbFaceValues
  fluid_ = fluid;
  f_previous_.clear();  // BDF2 restarts with a backward Euler step on a new graph
  downwind_ = downwind_groups(fluid_->graph, grid_);
}

// The same FLUID graph with a wider IB band: a new part and operator; the owned cells keep
// their values (the same cells), the ghosts are refreshed from their owners.
void ImmersedKineticGas::widen_band(int rings) {
  const Index N = grid_.size();
  partition_.band_rings = rings;
  auto part = std::make_unique<FluidGraphPart>(restrict_fluid_graph(
      *global_fluid_, background_graph_, marking_, owner_rank_, options_.comm, rings));
  auto op = std::make_unique<KineticOperator>(part->local.graph, grid_, gas_, outer_);
  op->set_parallel(options_.comm, &part->exchange);
  op->set_transport(options_.transport);
  auto move = [&](std::vector<Real>& v) {
    if (v.empty()) return;
    std::vector<Real> w(part->local.graph.n_cells() * N, 0.0);
    for (Index c = 0; c < part->local.graph.n_owned_cells; ++c)
      std::copy_n(v.data() + part_->local_of_global[part->global_cell[c]] * N, N, w.data() + c * N);
    part->exchange.exchange(std::span<Real>(w), static_cast<int>(N));
    v = std::move(w);
  };
  move(f_);
  move(f_previous_);
  move(predictor_previous_);
  point_.reset();
  op_ = std::move(op);
  part_ = std::move(part);
  band_buffer_.clear();
  fluid_ = &part_->local;
  downwind_ = downwind_groups(fluid_->graph, grid_);
  partition_.owned_cells = fluid_->graph.n_owned_cells;
  partition_.ghost_cells = fluid_->graph.n_cells() - fluid_->graph.n_owned_cells;
}

void ImmersedKineticGas::set_body(const ImmersedSurface& body, std::vector<Vec3> segment_velocity) {
  if (static_cast<Index>(segment_velocity.size()) != body.n_segments())
    throw InputError("immersed gas: one velocity per surface segment");
  double t0 = process_cpu_seconds();
  CellMarking marking = held_marking_ ? *held_marking_ : marker_.mark(body);
  const bool reclassify = !fluid_ || marking.cell != marking_.cell;
  if (values_) op_->set_external_face_values(nullptr);
  local_values_.reset();
  values_.reset();
  if (reclassify) {
    rebuild_graph(marking);
  } else {
    remark_ = RemarkReport{};
  }
  // Same classes: the graph (and its IB face numbering) is unchanged, the fits are not.
  marking_ = std::move(marking);
  double t1 = process_cpu_seconds();
  timings_.marking += t1 - t0;

  body_ = body;
  segment_velocity_ = std::move(segment_velocity);
  transfer_ = std::make_unique<ForceTransfer>(background_, marking_, *body_);
  ib_face_velocity_ = transfer_->to_ib_faces(segment_velocity_);
  if (has_state_ && reference_density_ <= 0)
    reference_density_ = op_->total_mass(f_) / marking_.area(background_, CellClass::Fluid);
  values_ = std::make_unique<IbKineticFaceValues>(background_, *global_fluid_, marking_, *body_,
                                                  segment_velocity_, ib_face_velocity_, grid_, gas_,
                                                  reference_density_, options_.ib);
  if (part_) {
    // The same global check on every rank (no communication): one verdict, so every rank
    // widens together.
    for (;;) {
      local_values_ = std::make_unique<LocalIbFaceValues>(*values_, *global_fluid_, *part_,
                                                          grid_.size(), band_buffer_);
      if (local_values_->covers_every_stencil()) break;
      if (partition_.band_rings >= 4 * options_.ib.surface_options.max_rings)
        throw SolverError("immersed gas: an IB stencil reaches beyond the " +
                          std::to_string(partition_.band_rings) + "-ring band of ghost cells");
      local_values_.reset();
      widen_band(partition_.band_rings + 1);
    }
    op_->set_external_face_values(local_values_.get());
  } else {
    op_->set_external_face_values(values_.get());
  }
  if (has_state_) {
    op_->update_boundary_values(f_);
    op_->update_collision(f_);
  }
  timings_.interpolation += process_cpu_seconds() - t1;
}

void ImmersedKineticGas::initialize(const GasState& state) {
  if (!op_) throw InputError("immersed gas: initialize needs a body (set_body first)");
  f_.assign(op_->size(), 0.0);
  f_previous_.clear();
  predictor_previous_.clear();
  reference_density_ = state.rho;
  values_->set_reference_density(state.rho);
  op_->initialize(f_, [&](const Vec3&) { return state; });
  has_state_ = true;
}

KineticSolveResult ImmersedKineticGas::solve_steady(const SequentialOptions& options) {
  const double t0 = process_cpu_seconds();
  KineticSolveResult r = solve_sequential(*op_, f_, options);
  op_->update_boundary_values(f_);
  timings_.gas += process_cpu_seconds() - t0;
  return r;
}

// The sequential solver's downwind sweep with the time term b V (f - h) (b = alpha / dt):
//   f_ck = (b V h_ck + V nu f_eq,ck - sum (c.S)^- f_up) / (b V + sum (c.S)^+ + V nu).
void ImmersedKineticGas::sweep(Real b, std::span<const Real> h) {
  downwind_sweep(*op_, downwind_, f_, b, h);
}

GasStepReport ImmersedKineticGas::advance(Real dt) {
  if (!(dt > 0)) throw InputError("immersed gas: time step must be positive");
  if (options_.stepper == GasStepper::Ida) return advance_ida(dt);
  const double t0 = process_cpu_seconds();
  const FaceGraph& g = fluid_->graph;
  const Index N = grid_.size(), nc = g.n_owned_cells;  // the rows with equations
  GasStepReport rep;
  // alpha / dt (f - h) + r(f) / V = 0: backward Euler (alpha = 1, h = f^n) or BDF2
  // (alpha = 3/2, h = (4 f^n - f^(n-1)) / 3) when the last step had the same dt and graph.
  const bool bdf2 = options_.bdf2 && !f_previous_.empty() && dt == dt_previous_;
  rep.order = bdf2 ? 2 : 1;
  const Real b = (bdf2 ? 1.5 : 1.0) / dt;
  // Scratch kept between steps: a fresh n_cells x N vector per step cost page faults.
  std::vector<Real>& h = scratch_h_;
  h.assign(f_.begin(), f_.end());
  if (bdf2)
    for (std::size_t i = 0; i < h.size(); ++i) h[i] = (4 * f_[i] - f_previous_[i]) / 3;
  rep.mass_before = op_->total_mass(f_);
  Real scale = 0;
  for (Index c = 0; c < nc; ++c)
    for (Index k = 0; k < N; ++k) scale += std::pow(b * g.cell_volume[c] * h[c * N + k], 2);
  scale = std::sqrt(options_.comm.sum(scale));
  std::vector<Real>& r = scratch_r_;
  r.resize(op_->size());
  std::vector<Real>& f_start = scratch_start_;
  f_start.assign(f_.begin(), f_.end());
  const std::vector<Real>& previous = f_previous_.empty() ? predictor_previous_ : f_previous_;
  if (options_.predictor && previous.size() == f_.size() && dt_previous_ > 0) {
    // Linear extrapolation, kept positive (the equilibrium's Newton needs positive moments).
    const Real s = dt / dt_previous_;
    for (std::size_t i = 0; i < f_.size(); ++i)
      f_[i] = std::max(f_start[i] + s * (f_start[i] - previous[i]), 0.1 * f_start[i]);
    rep.predicted = true;
  }
  predictor_previous_.clear();
  const bool point = options_.smoother != GasSmoother::Downwind;
  std::vector<Real>& source = scratch_source_;
  if (point) {
    if (!point_) point_ = std::make_unique<PointCoupledSmoother>(*op_, CometCoupling::Conserved);
    point_->set_time_coefficient(b);
    source.resize(h.size());
    for (Index c = 0; c < nc; ++c)
      for (Index k = 0; k < N; ++k) source[c * N + k] = b * g.cell_volume[c] * h[c * N + k];
  }
  for (;;) {
    op_->residual(f_, r);  // refreshes the IB-face values and the collision from f
    for (Index c = 0; c < nc; ++c)
      for (Index k = 0; k < N; ++k)
        r[c * N + k] += b * g.cell_volume[c] * (f_[c * N + k] - h[c * N + k]);
    rep.residual_ratio = op_->global_norm(r) / scale;
    rep.converged = rep.residual_ratio <= options_.step_tolerance;
    if (rep.converged || rep.sweeps >= options_.max_step_sweeps ||
        !std::isfinite(rep.residual_ratio))
      break;
    if (options_.smoother != GasSmoother::PointCoupled) {
      sweep(b, h);
      op_->exchange_ghosts(f_);  // ranks: block Jacobi between parts
    }
    if (point) {
      // The downwind sweep leaves the collision cache stale; the point solve needs it current.
      if (options_.smoother == GasSmoother::Both) op_->update_collision(f_);
      point_->sweep(f_, source, rep.sweeps % 2 == 0);
      op_->exchange_ghosts(f_);
    }
    ++rep.sweeps;
  }
  std::swap(f_previous_, f_start);  // f^n becomes f^(n-1); the old buffer is scratch
  dt_previous_ = dt;
  rep.mass_after = op_->total_mass(f_);
  for (int p = 0; p < static_cast<int>(g.patch_names.size()); ++p)
    rep.boundary_mass_flow += op_->boundary_mass_flow(p, f_);
  timings_.gas += process_cpu_seconds() - t0;
  return rep;
}

// IDA over [0, dt] (variable order and step, error-controlled at ida_rtol; steps <= dt),
// Newton-GMRES with the arrowhead preconditioner, restarted at every call (the operator may
// have changed with set_body, and IDA's history with it). IDA's fixed-step mode is not used:
// it makes the Newton test vacuous (tolerances 1e10), i.e. an explicit predictor step.
GasStepReport ImmersedKineticGas::advance_ida(Real dt) {
  if (distributed()) throw InputError("immersed gas: the IDA stepper runs serially only");
  const double t0 = process_cpu_seconds();
  const FaceGraph& g = fluid_->graph;
  const Index N = grid_.size(), nc = g.n_cells();
  GasStepReport rep;
  rep.mass_before = op_->total_mass(f_);
  TransientKineticSystem system(*op_);
  std::vector<Real> r(op_->size()), fp(op_->size());
  op_->residual(f_, r);
  Real f_max = 0;
  for (Index c = 0; c < nc; ++c)
    for (Index k = 0; k < N; ++k) {
      fp[c * N + k] = -r[c * N + k] / g.cell_volume[c];
      f_max = std::max(f_max, std::abs(f_[c * N + k]));
    }
  IdaOptions ida;
  ida.linear_solver = IdaOptions::LinearSolver::Spgmr;
  ida.rtol = options_.ida_rtol;
  ida.atol = options_.ida_rtol * 1e-3 * f_max;
  ida.max_step = dt;
  IdaIntegrator integrator(system, ida);
  integrator.initialize(0, f_, fp);
  integrator.advance(dt);
  std::copy(integrator.y().begin(), integrator.y().end(), f_.begin());
  const IntegratorStats stats = integrator.stats();
  rep.newton = stats.newton_iters;
  rep.krylov = stats.linear_iters;
  rep.sweeps = static_cast<int>(stats.steps);  // IDA's internal steps
  rep.order = stats.last_order;
  rep.converged = integrator.time() >= dt;
  f_previous_.clear();
  rep.mass_after = op_->total_mass(f_);
  for (int p = 0; p < static_cast<int>(g.patch_names.size()); ++p)
    rep.boundary_mass_flow += op_->boundary_mass_flow(p, f_);
  timings_.gas += process_cpu_seconds() - t0;
  return rep;
}

Real ImmersedKineticGas::fluid_area() const {
  Real a = 0;
  for (Real v : global_fluid_->graph.cell_volume) a += v;
  return a;
}

std::vector<Real> ImmersedKineticGas::global_distribution() const {
  if (!part_) return f_;
  const Index N = grid_.size();
  std::vector<Real> all(global_fluid_->graph.n_cells() * N, 0.0);
  for (Index c = 0; c < fluid_->graph.n_owned_cells; ++c)
    std::copy_n(f_.data() + c * N, N, all.data() + part_->global_cell[c] * N);
  options_.comm.sum_in_place(all);  // one nonzero term per entry: exact
  return all;
}

Real ImmersedKineticGas::conserved_mass() const {
  Real background = 0;
  for (Real v : background_graph_.cell_volume) background += v;
  return total_mass() + reference_density_ * (background - body_->area() - fluid_area());
}

std::vector<Vec3> ImmersedKineticGas::ib_face_forces() const {
  const FaceGraph& g = fluid_->graph;
  const Index N = grid_.size();
  std::vector<Vec3> forces(marking_.ib_faces.size(), Vec3::Zero());
  std::vector<Real> face(N);
  for (Index f = g.n_interior_faces; f < g.n_faces(); ++f) {
    const Index i = fluid_->ib_face[f];
    if (i < 0) continue;
    op_->face_values(f, f_, face);  // the leaving values as the transport scheme gives them
    const Vec3& S = g.face_area[f];
    Vec3 F = Vec3::Zero();
    for (Index k = 0; k < N; ++k) F += (grid_.w[k] * grid_.c[k].dot(S) * face[k]) * grid_.c[k];
    forces[i] = F;
  }
  // Each IB face is a face of its owner's part only: the sum is exact, the same on every rank.
  if (part_ && !forces.empty())
    options_.comm.sum_in_place(std::span<Real>(forces.front().data(), 3 * forces.size()));
  return forces;
}

struct ImmersedKineticGas::Checkpoint {
  Checkpoint(ImmersedSurface b, CellMarking m, std::vector<Vec3> v)
      : body(std::move(b)), marking(std::move(m)), segment_velocity(std::move(v)) {}
  ImmersedSurface body;
  CellMarking marking;  // the body's, or a held one (hold_marking)
  std::vector<Vec3> segment_velocity;
  std::vector<Real> f, f_previous, predictor_previous;
  Real dt_previous = 0;
  std::vector<Index> global_cell;  // distributed: per owned cell, its global FLUID cell
  RemarkReport remark;
};

void ImmersedKineticGas::save_checkpoint() {
  if (!body_ || !has_state_) throw InputError("immersed gas: checkpoint before initialize");
  checkpoint_ = std::make_unique<Checkpoint>(*body_, marking_, segment_velocity_);
  Checkpoint& c = *checkpoint_;
  c.f = f_;
  c.f_previous = f_previous_;
  c.predictor_previous = predictor_previous_;
  c.dt_previous = dt_previous_;
  c.remark = remark_;
  if (part_)
    checkpoint_->global_cell.assign(part_->global_cell.begin(),
                                    part_->global_cell.begin() + fluid_->graph.n_owned_cells);
}

std::vector<Real> ImmersedKineticGas::to_current_layout(
    const std::vector<Real>& v, const std::vector<Index>& global_cell) const {
  if (!part_ || v.empty()) return v;  // serial: the same marking gives the same graph
  const Index N = grid_.size();
  std::vector<Real> w(fluid_->graph.n_cells() * N, 0.0);
  for (std::size_t c = 0; c < global_cell.size(); ++c) {
    const Index local = part_->local_of_global[global_cell[c]];
    if (local < 0 || local >= fluid_->graph.n_owned_cells)
      throw SolverError("immersed gas: a checkpointed cell is no longer owned here");
    std::copy_n(v.data() + c * N, N, w.data() + local * N);
  }
  op_->exchange_ghosts(w);
  return w;
}

void ImmersedKineticGas::restore_checkpoint() {
  if (!checkpoint_) throw InputError("immersed gas: restore without a saved checkpoint");
  const Checkpoint& s = *checkpoint_;
  std::optional<CellMarking> held = std::move(held_marking_);
  held_marking_ = s.marking;
  set_body(s.body, s.segment_velocity);  // the saved marking, graph and IB fits
  held_marking_ = std::move(held);
  f_ = to_current_layout(s.f, s.global_cell);
  if (static_cast<Index>(f_.size()) != op_->size())
    throw SolverError("immersed gas: the checkpoint's distribution does not fit the graph");
  f_previous_ = to_current_layout(s.f_previous, s.global_cell);
  predictor_previous_ = to_current_layout(s.predictor_previous, s.global_cell);
  dt_previous_ = s.dt_previous;
  remark_ = s.remark;
  op_->update_boundary_values(f_);  // as set_body does, now from the saved f
  op_->update_collision(f_);
}

void ImmersedKineticGas::hold_marking(bool hold) {
  if (hold)
    held_marking_ = marking_;
  else
    held_marking_.reset();
}

std::vector<Vec3> ImmersedKineticGas::step(const ImmersedSurface& surface,
                                           std::span<const Vec3> segment_velocity, Real dt,
                                           GasStepReport* report) {
  set_body(surface, std::vector<Vec3>(segment_velocity.begin(), segment_velocity.end()));
  const GasStepReport rep = advance(dt);
  if (report) *report = rep;
  return segment_forces();
}

std::vector<Vec3> ImmersedKineticGas::segment_forces() const {
  return transfer_->to_surface(ib_face_forces());
}

}  // namespace rfmems

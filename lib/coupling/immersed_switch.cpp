#include "coupling/immersed_switch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"
#include "core/process_cpu_clock.hpp"
#include "core/reduced_inertia_system.hpp"
#include "coupling/aitken_relaxation.hpp"
#include "coupling/displacement_control_fixed_point.hpp"
#include "coupling/gap_scaled_lagged_load.hpp"
#include "coupling/step_voltage_run.hpp"
#include "coupling/voltage_control_fixed_point.hpp"
#include "ibm/force_transfer.hpp"
#include "solvers/ida_integrator.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

Mesh make_switch_background(const ImmersedSwitchGeometry& g) {
  const int nx = g.background_cells[0], ny = g.background_cells[1];
  if (nx < 2 || ny < 2) throw InputError("immersed switch: the background needs >= 2 x 2 cells");
  const Vec3 lo = g.background_lower, hi = g.background_upper;
  if (!(hi.x() > lo.x() && hi.y() > lo.y()))
    throw InputError("immersed switch: the background's upper corner is not above its lower one");
  MeshBuilder builder(2);
  auto node = [&](int i, int j) -> Index { return static_cast<Index>(j) * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      builder.add_node(
          Vec3(lo.x() + (hi.x() - lo.x()) * i / nx, lo.y() + (hi.y() - lo.y()) * j / ny, 0));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      builder.add_cell(CellShape::Quad,
                       {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)});
  int n_electrode = 0;
  for (int i = 0; i < nx; ++i) {
    const Real mid = lo.x() + (hi.x() - lo.x()) * (i + 0.5) / nx;
    const bool on = mid >= g.electrode_begin && mid <= g.electrode_end;
    n_electrode += on;
    builder.add_boundary_face({node(i, 0), node(i + 1, 0)}, on ? "electrode" : "substrate");
  }
  if (n_electrode == 0)
    throw InputError(
        fmt::format("immersed switch: no bottom face centre in the electrode [{:g}, {:g}] m",
                    g.electrode_begin, g.electrode_end));
  for (int i = 0; i < nx; ++i) builder.add_boundary_face({node(i, ny), node(i + 1, ny)}, "top");
  for (int j = 0; j < ny; ++j) {
    builder.add_boundary_face({node(0, j), node(0, j + 1)}, "left");
    builder.add_boundary_face({node(nx, j), node(nx, j + 1)}, "right");
  }
  return builder.build("immersed switch background");
}

struct ImmersedSwitch::Kernel {
  CellMarker marker;
  ImmersedElectrostatics electrostatics;
  Kernel(const Mesh& bg, std::map<std::string, PotentialBoundary> bcs)
      : marker(bg), electrostatics(bg, std::move(bcs)) {}
};

ImmersedSwitch::ImmersedSwitch(ElasticityOperator& beam, const ImmersedSwitchGeometry& geometry,
                               LinearFunctional control)
    : beam_(beam),
      geometry_(geometry),
      background_(std::make_unique<Mesh>(make_switch_background(geometry))),
      rest_surface_(ImmersedSurface::from_mesh_boundary(beam.mesh())),
      control_(std::move(control)) {
  const Mesh& mesh = beam.mesh();
  if (mesh.dim() != 2) throw InputError("immersed switch: the beam must be a plane (2D) model");
  const int anchor = mesh.find_patch(geometry.anchor_patch);
  const int facing = mesh.find_patch(geometry.facing_patch);
  if (anchor < 0)
    throw InputError(fmt::format("immersed switch: no beam patch '{}'", geometry.anchor_patch));
  if (facing < 0)
    throw InputError(fmt::format("immersed switch: no beam patch '{}'", geometry.facing_patch));
  if (!control_.within(beam.size()))
    throw InputError("immersed switch: the control is not a functional of the beam's unknowns");
  std::map<std::string, PotentialBoundary> bcs{{"electrode", PotentialBoundary::potential(0.0)},
                                               {"substrate", PotentialBoundary::zero_flux()},
                                               {"left", PotentialBoundary::zero_flux()},
                                               {"right", PotentialBoundary::zero_flux()},
                                               {"top", PotentialBoundary::zero_flux()}};
  if (background_->find_patch("substrate") < 0) bcs.erase("substrate");
  kernel_ = std::make_unique<Kernel>(*background_, std::move(bcs));
  electrode_y_ = geometry.background_lower.y();

  const Real hx = (geometry.background_upper.x() - geometry.background_lower.x()) /
                  geometry.background_cells[0];
  const Real extension = geometry.anchor_extension > 0 ? geometry.anchor_extension : hx;
  const Real scale = rest_surface_.perimeter();
  std::vector<Vec3> vertices = rest_surface_.vertices();
  const Patch& anchor_patch = mesh.patches()[anchor];
  Real thickness_lo = 1e300, thickness_hi = -1e300;
  for (Index k = 0; k < rest_surface_.n_segments(); ++k) {
    const Index f = rest_surface_.source_face(k);
    Index node = -1;
    for (Index candidate : mesh.face_nodes(f))
      if ((mesh.nodes()[candidate] - rest_surface_.start(k)).norm() <= 1e-12 * scale)
        node = candidate;
    if (node < 0) throw MeshError("immersed switch: a surface vertex is not a node of its face");
    vertex_node_.push_back(node);
    segment_cell_.push_back(mesh.face_owner(f));
    thickness_lo = std::min(thickness_lo, vertices[k].y());
    thickness_hi = std::max(thickness_hi, vertices[k].y());
  }
  // Vertices on the anchored patch: clamped, and moved into the wall.
  std::vector<bool> on_anchor(mesh.n_nodes(), false);
  for (Index f = anchor_patch.first_face; f < anchor_patch.first_face + anchor_patch.n_faces; ++f)
    for (Index node : mesh.face_nodes(f)) on_anchor[node] = true;
  const Vec3 anchor_normal = mesh.face_area(anchor_patch.first_face).normalized();
  for (Index k = 0; k < rest_surface_.n_segments(); ++k) {
    vertex_anchored_.push_back(on_anchor[vertex_node_[k]]);
    if (vertex_anchored_.back()) vertices[k] += extension * anchor_normal;
  }
  rest_surface_.set_vertices(vertices);

  const Patch& facing_patch = mesh.patches()[facing];
  Real bottom = 1e300;
  for (Index f = facing_patch.first_face; f < facing_patch.first_face + facing_patch.n_faces; ++f)
    bottom = std::min(bottom, mesh.face_centroid(f).y());
  gap0_ = bottom - electrode_y_;
  if (!(gap0_ > 0))
    throw InputError("immersed switch: the beam's facing side is not above the electrode");
  // The facing side's free vertices, each with its u_y as vertex_displacements moves it (the
  // mean of its two segments' cell reconstructions): the gap the contact root watches is the
  // surface's, down to the tip's corner, not the facing cells' centroids half a cell inside.
  const Index n_vertices = rest_surface_.n_segments();
  std::vector<bool> facing_vertex(n_vertices, false);
  for (Index k = 0; k < n_vertices; ++k)
    if (mesh.face_patch(rest_surface_.source_face(k)) == facing)
      facing_vertex[k] = facing_vertex[(k + 1) % n_vertices] = true;
  for (Index k = 0; k < n_vertices; ++k) {
    if (!facing_vertex[k] || vertex_anchored_[k]) continue;
    const Vec3& x = mesh.nodes()[vertex_node_[k]];
    LinearFunctional u_y;
    u_y.add(beam.displacement_functional(segment_cell_[(k + n_vertices - 1) % n_vertices], x, 1),
            0.5)
        .add(beam.displacement_functional(segment_cell_[k], x, 1), 0.5);
    facing_vertices_.push_back({x.y() - electrode_y_, std::move(u_y)});
  }

  // Wall points must stay within the beam's thickness: (rings + 1/2) h < 0.9 thickness.
  const Real hy = (geometry.background_upper.y() - geometry.background_lower.y()) /
                  geometry.background_cells[1];
  const Real h = std::sqrt(hx * hy);
  const Real thickness = thickness_hi - thickness_lo;
  Real x_lo = 1e300, x_hi = -1e300;
  for (const Vec3& x : mesh.nodes()) {
    x_lo = std::min(x_lo, x.x());
    x_hi = std::max(x_hi, x.x());
  }
  const LinearElastic& m = beam.material();
  const Real span = x_hi - x_lo;
  first_period_ =
      2 * M_PI / (1.875104 * 1.875104 * thickness / (span * span) * std::sqrt(m.E / (12 * m.rho)));
  interpolation_.max_rings =
      std::clamp(static_cast<int>(std::floor(0.9 * thickness / h - 0.5)), 1, 3);
}

ImmersedSwitch::~ImmersedSwitch() = default;

Real ImmersedSwitch::background_cell_height() const {
  return (geometry_.background_upper.y() - geometry_.background_lower.y()) /
         geometry_.background_cells[1];
}

std::span<const Real> ImmersedSwitch::potential() const {
  return kernel_->electrostatics.potential();
}

void ImmersedSwitch::set_electrostatics_lu(LuReuse reuse) {
  kernel_->electrostatics.set_lu_reuse(reuse);
}

void ImmersedSwitch::distribute_electrostatics(const Communicator& comm,
                                               const DistributedLinearOptions& options) {
  kernel_->electrostatics.distribute(comm, options);
}

bool ImmersedSwitch::electrostatics_distributed() const {
  return kernel_->electrostatics.distributed();
}

std::vector<Vec3> ImmersedSwitch::vertex_displacements(std::span<const Real> u) const {
  // Vertex k joins segments k-1 and k: the mean of their cells' linear reconstructions, so
  // that a segment moves with its own cell and both neighbours alike and the load stiffness
  // between neighbouring cells is nearly symmetric, as a conservative force's must be (a
  // vertex moved by one of its cells only made cell c's load follow cell c+1's motion but
  // hardly the reverse, and left cell 0 at the clamp nearly without its own stiffness;
  // docs/immersed_switch.md, "Grid damping").
  const std::vector<Mat3> gradients = beam_.cell_gradients(0.0, u);
  const Mesh& mesh = beam_.mesh();
  const std::size_t n = vertex_node_.size();
  std::vector<Vec3> out(n, Vec3::Zero());
  for (std::size_t k = 0; k < n; ++k) {
    if (vertex_anchored_[k]) continue;
    const Vec3& x = mesh.nodes()[vertex_node_[k]];
    const Index before = segment_cell_[(k + n - 1) % n], after = segment_cell_[k];
    out[k] = 0.5 * (beam_.displacement_at(before, x, u, gradients) +
                    beam_.displacement_at(after, x, u, gradients));
  }
  return out;
}

ImmersedSurface ImmersedSwitch::moved_surface(std::span<const Real> u) const {
  const std::vector<Vec3> moved = vertex_displacements(u);
  std::vector<Vec3> vertices = rest_surface_.vertices();
  for (std::size_t k = 0; k < vertices.size(); ++k) vertices[k] += moved[k];
  ImmersedSurface surface = rest_surface_;
  surface.set_vertices(std::move(vertices));
  return surface;
}

std::vector<Vec3> ImmersedSwitch::segment_velocities(std::span<const Real> v) const {
  const std::vector<Vec3> vertex = vertex_displacements(v);
  const std::size_t n = vertex.size();
  std::vector<Vec3> out(n);
  for (std::size_t k = 0; k < n; ++k) out[k] = 0.5 * (vertex[k] + vertex[(k + 1) % n]);
  return out;
}

Real ImmersedSwitch::min_gap(std::span<const Real> u) const {
  Real g = 1e300;
  for (const FacingVertex& v : facing_vertices_) g = std::min(g, v.rest_gap + v.u_y(u));
  return facing_vertices_.empty() ? gap0_ : g;
}

std::vector<Real> ImmersedSwitch::to_structure(std::span<const Vec3> segment_forces) const {
  std::vector<Real> q(beam_.size(), 0.0);
  for (std::size_t k = 0; k < segment_forces.size(); ++k) {
    q[2 * segment_cell_[k]] += segment_forces[k].x();
    q[2 * segment_cell_[k] + 1] += segment_forces[k].y();
  }
  return q;
}

std::vector<Index> ImmersedSwitch::facing_segments() const {
  const Mesh& mesh = beam_.mesh();
  const int facing = mesh.find_patch(geometry_.facing_patch);
  std::vector<Index> out;
  for (Index k = 0; k < rest_surface_.n_segments(); ++k)
    if (mesh.face_patch(rest_surface_.source_face(k)) == facing) out.push_back(k);
  return out;
}

ImmersedLoad ImmersedSwitch::electrostatic_load(std::span<const Real> u, Real voltage) {
  ++times_.load_evaluations;
  std::unique_ptr<ImmersedSurface> surface;
  {
    ScopedCpuTimer t{times_.move};
    surface = std::make_unique<ImmersedSurface>(moved_surface(u));
  }
  CellMarking marking;
  {
    ScopedCpuTimer t{times_.marking};
    marking = kernel_->marker.mark(*surface);
  }
  std::unique_ptr<IbInterpolation> ib;
  {
    ScopedCpuTimer t{times_.interpolation};
    ib = std::make_unique<IbInterpolation>(*background_, marking, *surface, interpolation_);
  }
  {
    ScopedCpuTimer t{times_.electrostatics};
    ImmersedElectrostatics& field = kernel_->electrostatics;
    const long analyses = field.analyses(), iterations = field.krylov_iterations();
    field.solve(marking, *ib, voltage);
    times_.electrostatic_analyses += field.analyses() - analyses;
    times_.electrostatic_krylov_iterations += field.krylov_iterations() - iterations;
  }
  ImmersedLoad load;
  {
    ScopedCpuTimer t{times_.transfer};
    const ForceTransfer transfer(*background_, marking, *surface);
    const std::vector<Vec3> segment = transfer.to_surface(kernel_->electrostatics.ib_face_forces());
    for (const Vec3& f : segment) load.total += f;
    load.force = to_structure(segment);
  }
  load.ib_faces = static_cast<Index>(marking.ib_faces.size());
  load.one_sided = ib->count_one_sided();
  load.unreached = marking.n_unreached_outside;
  return load;
}

ImmersedStatic ImmersedSwitch::solve_static(Real voltage, Real tolerance, int max_iterations) {
  // The plain fixed point (voltage_control_fixed_point.hpp), not Aitken: on a background where
  // the beam's faces lie on grid lines the load jumps as slivers get cut
  // (docs/immersed_switch.md), and Aitken's secant amplified the jumps (measured: omega
  // between -8 and 15, no convergence).
  const Index n = beam_.size();
  std::vector<Real> k_values(beam_.stiffness_pattern().nnz()), rest(n, 0.0);
  beam_.stiffness(0.0, rest, k_values);
  KluFactorization stiffness(beam_.stiffness_pattern(), k_values);
  ImmersedStatic out;
  auto load = [&](std::span<const Real> u) {
    ImmersedLoad l = electrostatic_load(u, voltage);
    out.force_y = l.total.y();
    return std::move(l.force);
  };
  VoltageControlResult r =
      relax_voltage_control(stiffness, load, n, control_, tolerance, max_iterations);
  if (!r.converged)
    throw SolverError(
        fmt::format("immersed switch: static solve at {:g} V not converged in {} "
                    "iterations (above the quasi-static pull-in?)",
                    voltage, max_iterations));
  out.iterations = r.iterations;
  out.control = control_(r.u);
  out.u = std::move(r.u);
  return out;
}

QuasiStaticPullIn ImmersedSwitch::trace_quasi_static(const QuasiStaticOptions& options,
                                                     Real coupling_tolerance) {
  const Index n = beam_.size();
  std::vector<Real> k_values(beam_.stiffness_pattern().nnz()), zero(n, 0.0);
  beam_.stiffness(0.0, zero, k_values);
  KluFactorization stiffness(beam_.stiffness_pattern(), k_values);
  long solves = 0;
  auto solve = [&](Real delta, const FoldSample& from) {
    FoldSample s{{}, from.state};
    if (from.point.displacement != 0)
      for (Real& v : s.state) v *= delta / from.point.displacement;
    std::vector<Real>& u = s.state;
    const auto load_per_volt2 = [&](std::span<const Real> state) {
      ++solves;
      return electrostatic_load(state, 1.0).force;
    };
    const DisplacementControlResult r = relax_displacement_control(
        stiffness, load_per_volt2, control_, delta, coupling_tolerance, 200, u);
    if (!r.converged || r.voltage_squared < 0)
      throw SolverError(
          fmt::format("immersed switch: quasi-static coupling failed at delta = {:.4e} m", delta));
    s.point = {delta, std::sqrt(r.voltage_squared), min_gap(u), true, r.iterations + 1};
    return s;
  };
  FoldSample rest{{0.0, 0.0, gap0_, true, 0}, std::vector<Real>(n, 0.0)};
  QuasiStaticPullIn out = trace_fold(solve, rest, gap0_, options);
  out.solves = solves;
  return out;
}

DynamicRun ImmersedSwitch::run(Real voltage, const DynamicOptions& options, ImmersedGasModel* gas) {
  if (options.coupling.scheme == CouplingScheme::Monolithic)
    throw InputError(
        "immersed switch: the field gives no exact Jacobian blocks; use staggered, "
        "implicit or strongly_coupled");
  const Index n = beam_.size();
  // The lagged, gap-scaled IBM load (see the header); a trial gap below 2 % of g0 is retried.
  GapScaledLaggedLoad structure(beam_, gap0_, 0.02);
  ReducedInertiaSystem system(structure, {});
  std::vector<Real> y(system.size(), 0.0);
  ImmersedLoad load = electrostatic_load(std::span<const Real>(y.data(), n), voltage);
  structure.set_reference(load.force, std::span<const Real>(y.data(), n));
  if (options.coupling.scheme == CouplingScheme::Implicit)
    structure.set_exact(
        [&](std::span<const Real> u) { return electrostatic_load(u, voltage).force; });
  Real gas_force = 0;
  if (gas) {
    ScopedCpuTimer t{times_.gas};
    gas->reset(rest_surface_, 0.0);
  }
  std::vector<Real> yp = system.consistent_derivative(0.0, y);
  IdaOptions ida_options = options.ida;
  ida_options.atols.assign(system.size(), options.ida.atol);
  for (Index i = n; i < system.size(); ++i)
    ida_options.atols[i] = options.ida.atol * 2 * M_PI / first_period_;
  IdaIntegrator ida(system, ida_options);
  ida.initialize(0.0, y, yp);
  // The control's velocity: the same weights on the velocity unknowns.
  const LinearFunctional velocity =
      control_.mapped([&system](Index i) { return system.velocity_index(i); });
  StepVoltageEvents events(
      options.stop_at_turning, options.turning_retreat, 0.25 * first_period_,
      early_ends(options.stop_at_turning, options.settle_tolerance, options.fold,
                 options.stop_past_fold, options.past_fold_margin));
  events.set_roots(ida, n, control_, velocity, options.contact_gap,
                   [this](std::span<const Real> u) { return min_gap(u); });

  std::vector<StepRecord> records{{0.0, 0.0, 0.0, gap0_, load.total.y(), 0.0}};
  DynamicRun out;
  Real t_gas = 0;  // the gas's time: it advances every gas_every accepted steps
  int since_gas = 0;
  const bool strong = options.coupling.scheme == CouplingScheme::StronglyCoupled;
  if (options.coupling.strong_gas && !strong)
    throw InputError("immersed switch: strong_gas needs the strongly_coupled scheme");
  const bool gas_inside = strong && options.coupling.strong_gas && gas;
  if (gas_inside && options.coupling.gas_every != 1)
    throw InputError("immersed switch: strong_gas advances the gas over every step (gas_every 1)");
  std::vector<Real> held(n, 0.0);  // the gas load in the structure's residual
  // The gas over [t_gas, t_end] with the body at state's displacement and velocity (its end
  // state); the gas force per structure unknown.
  auto advance_gas = [&](std::span<const Real> state, Real t_end) {
    ScopedCpuTimer timer{times_.gas};
    std::vector<Real> v(n);
    for (Index i = 0; i < n; ++i) v[i] = state[system.velocity_index(i)];
    const std::vector<Vec3> f = gas->advance(moved_surface(state.subspan(0, n)),
                                             segment_velocities(v), t_gas, t_end - t_gas);
    ++times_.gas_steps;
    gas_force = 0;
    for (const Vec3& x : f) gas_force += x.y();
    return to_structure(f);
  };
  // Strong coupling per step (block Gauss-Seidel with Aitken relaxation, Kuettler & Wall 2008):
  // the step is redone from IDA's checkpoint with the interface load G_k, applied in the
  // residual as G_k (g_k / g(u))^2 with g_k the gap of iterate k's end state (k = 0 is the
  // staggered step: G_0 = F(u_n) at g_n), until the IBM load F(u_k) at the step's end state
  // (IDA's t_n, also after a root return) matches the load A_k applied there:
  // |r_k| <= tol |F(u_k)|, r_k = F(u_k) - A_k; then G_{k+1} = A_k + omega_k r_k, omega_0 = 1 and
  // Aitken's factor after. Without strong_gas the gas is advanced once, after the converged
  // step (lagged, as in the staggered scheme). With it, every iterate also redoes the gas's
  // step from the gas's checkpoint with u_k and its velocity, and the interface load is the
  // sum: F = F_e(u_k) + F_g(u_k), A_k = A_e,k + H_k (H_k the gas load held over iterate k,
  // H_0 the last step's gas force), one Aitken factor on the summed residual, each part
  // relaxed by it (G_e = A_e + omega r_e, H = H_k + omega r_g).
  auto strong_step = [&]() {
    ida.save_checkpoint();
    if (gas_inside) {
      ScopedCpuTimer t{times_.gas};
      gas->save_checkpoint();
    }
    std::vector<Real> residual_prev;
    Real omega = 1;
    for (int k = 0;; ++k) {
      IdaIntegrator::Status status;
      {
        ScopedCpuTimer t{times_.structure};
        status = ida.step(options.end_time);
      }
      const std::span<const Real> y_end = ida.internal_y();
      const std::span<const Real> u_end = y_end.subspan(0, n);
      const std::vector<Real> applied = structure.applied(u_end);
      load = electrostatic_load(u_end, voltage);
      // After a root return IDA's next call may end at the same t_n: the gas is there already.
      const Real t_end = ida.internal_time();
      const bool gas_steps = gas_inside && t_end > t_gas;
      std::vector<Real> gas_load = held;
      if (gas_steps) {
        if (k > 0) {
          ScopedCpuTimer t{times_.gas};
          gas->restore_checkpoint();
        }
        gas_load = advance_gas(y_end, t_end);
        if (k == 0) gas->hold_marking(true);  // the later iterates on iterate 0's marking
      }
      ++times_.coupling_iterations;
      std::vector<Real> residual(n);
      Real r2 = 0, f2 = 0;
      for (Index i = 0; i < n; ++i) {
        const Real total = load.force[i] + (gas_inside ? gas_load[i] : 0);
        residual[i] = total - applied[i] - (gas_inside ? held[i] : 0);
        r2 += residual[i] * residual[i];
        f2 += total * total;
      }
      const bool converged = r2 <= options.coupling.tolerance * options.coupling.tolerance * f2;
      if (converged || k + 1 >= options.coupling.max_iterations) {
        times_.unconverged_steps += !converged;
        times_.max_coupling_iterations = std::max(times_.max_coupling_iterations, k + 1);
        if (f2 > 0)
          times_.max_coupling_residual = std::max(times_.max_coupling_residual, std::sqrt(r2 / f2));
        structure.set_reference(load.force, u_end);  // the next step's k = 0
        if (gas_inside) gas->hold_marking(false);
        if (gas_steps) {
          held = std::move(gas_load);
          structure.set_held(held);
          t_gas = t_end;
        }
        return status;
      }
      if (k > 0) omega = std::clamp(aitken_factor(omega, residual, residual_prev), 0.01, 4.0);
      std::vector<Real> next(n);
      for (Index i = 0; i < n; ++i) next[i] = applied[i] + omega * (load.force[i] - applied[i]);
      structure.set_reference(std::move(next), u_end);
      if (gas_steps) {
        for (Index i = 0; i < n; ++i) held[i] += omega * (gas_load[i] - held[i]);
        structure.set_held(held);
      }
      residual_prev = std::move(residual);
      ida.restore_checkpoint();
    }
  };
  while (true) {
    IdaIntegrator::Status status;
    if (strong) {
      status = strong_step();
    } else {
      ScopedCpuTimer t{times_.structure};
      status = ida.step(options.end_time);
    }
    ++times_.structure_steps;
    const Real t = ida.time();
    const std::span<const Real> state = ida.y();
    const std::span<const Real> u = state.subspan(0, n);
    const bool stop = events.after_step(ida, status, t, control_(u), out);
    // The coupled step's exchange: the IBM load and the gas at the accepted state.
    if (!strong) {  // strong_step left the IBM load at IDA's internal state as reference
      load = electrostatic_load(u, voltage);
      structure.set_reference(load.force, u);
    }
    if (gas && !gas_inside && t > t_gas && (++since_gas >= options.coupling.gas_every || stop)) {
      since_gas = 0;
      held = advance_gas(state, t);
      structure.set_held(held);  // the lagged gas force
    }
    records.push_back({t, control_(u), velocity(state), min_gap(u), load.total.y(), gas_force});
    if (since_gas == 0 && !gas_inside) t_gas = t;
    if (stop || events.after_record(records.back(), voltage, out)) break;
  }
  finish_step_voltage_run(ida, records, voltage, options.output_interval, true, out);
  return out;
}

}  // namespace rfmems

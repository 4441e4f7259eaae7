#include "ibm/immersed_boundary_field.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"
#include "core/process_cpu_clock.hpp"
#include "ibm/force_transfer.hpp"

namespace rfmems {

Mesh make_switch_background(const ImmersedBoundaryGeometry& g) {
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

struct ImmersedBoundaryField::Kernel {
  CellMarker marker;
  ImmersedElectrostatics electrostatics;
  Kernel(const Mesh& bg, std::map<std::string, PotentialBoundary> bcs)
      : marker(bg), electrostatics(bg, std::move(bcs)) {}
};

ImmersedBoundaryField::ImmersedBoundaryField(ElasticityOperator& beam,
                                             const ImmersedBoundaryGeometry& geometry,
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

ImmersedBoundaryField::~ImmersedBoundaryField() = default;

Real ImmersedBoundaryField::background_cell_height() const {
  return (geometry_.background_upper.y() - geometry_.background_lower.y()) /
         geometry_.background_cells[1];
}

std::span<const Real> ImmersedBoundaryField::potential() const {
  return kernel_->electrostatics.potential();
}

void ImmersedBoundaryField::set_electrostatics_lu(LuReuse reuse) {
  kernel_->electrostatics.set_lu_reuse(reuse);
}

void ImmersedBoundaryField::distribute_electrostatics(const Communicator& comm,
                                                      const DistributedLinearOptions& options) {
  kernel_->electrostatics.distribute(comm, options);
}

bool ImmersedBoundaryField::electrostatics_distributed() const {
  return kernel_->electrostatics.distributed();
}

std::vector<Vec3> ImmersedBoundaryField::vertex_displacements(std::span<const Real> u) const {
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

ImmersedSurface ImmersedBoundaryField::moved_surface(std::span<const Real> u) const {
  const std::vector<Vec3> moved = vertex_displacements(u);
  std::vector<Vec3> vertices = rest_surface_.vertices();
  for (std::size_t k = 0; k < vertices.size(); ++k) vertices[k] += moved[k];
  ImmersedSurface surface = rest_surface_;
  surface.set_vertices(std::move(vertices));
  return surface;
}

std::vector<Vec3> ImmersedBoundaryField::segment_velocities(std::span<const Real> v) const {
  const std::vector<Vec3> vertex = vertex_displacements(v);
  const std::size_t n = vertex.size();
  std::vector<Vec3> out(n);
  for (std::size_t k = 0; k < n; ++k) out[k] = 0.5 * (vertex[k] + vertex[(k + 1) % n]);
  return out;
}

Real ImmersedBoundaryField::min_gap(std::span<const Real> u) const {
  Real g = 1e300;
  for (const FacingVertex& v : facing_vertices_) g = std::min(g, v.rest_gap + v.u_y(u));
  return facing_vertices_.empty() ? gap0_ : g;
}

std::vector<Real> ImmersedBoundaryField::to_structure(std::span<const Vec3> segment_forces) const {
  std::vector<Real> q(beam_.size(), 0.0);
  for (std::size_t k = 0; k < segment_forces.size(); ++k) {
    q[2 * segment_cell_[k]] += segment_forces[k].x();
    q[2 * segment_cell_[k] + 1] += segment_forces[k].y();
  }
  return q;
}

std::vector<Index> ImmersedBoundaryField::facing_segments() const {
  const Mesh& mesh = beam_.mesh();
  const int facing = mesh.find_patch(geometry_.facing_patch);
  std::vector<Index> out;
  for (Index k = 0; k < rest_surface_.n_segments(); ++k)
    if (mesh.face_patch(rest_surface_.source_face(k)) == facing) out.push_back(k);
  return out;
}

ImmersedLoad ImmersedBoundaryField::electrostatic_load(std::span<const Real> u, Real voltage) {
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

StructureLoad ImmersedBoundaryField::load(std::span<const Real> u, Real voltage) {
  ImmersedLoad l = electrostatic_load(u, voltage);
  return {std::move(l.force), l.total.y()};
}

GapFieldTraits ImmersedBoundaryField::traits() const {
  GapFieldTraits t;
  // The equilibria by the plain fixed point, to what the background resolves: where the beam's
  // faces lie on grid lines the load jumps as slivers get cut (docs/immersed_switch.md).
  t.static_tolerance = 1e-7;
  t.quasi_static_tolerance = 1e-6;
  t.closed_fraction = 0.02;
  t.velocity_rate = 2 * M_PI / first_period_;
  t.turning_after = 0.25 * first_period_;
  return t;
}

Json ImmersedBoundaryField::counters() const {
  return {{"move_s", times_.move},
          {"marking_s", times_.marking},
          {"interpolation_s", times_.interpolation},
          {"electrostatics_s", times_.electrostatics},
          {"transfer_s", times_.transfer},
          {"load_evaluations", times_.load_evaluations},
          {"electrostatic_analyses", times_.electrostatic_analyses},
          {"electrostatic_krylov_iterations", times_.electrostatic_krylov_iterations}};
}

namespace {

class SurfaceGas : public StructureGas {
 public:
  SurfaceGas(const ImmersedBoundaryField& field, std::unique_ptr<ImmersedGasModel> gas)
      : field_(field), gas_(std::move(gas)) {}
  std::string name() const override { return gas_->name(); }
  void reset(Real t0) override { gas_->reset(field_.rest_surface(), t0); }
  StructureLoad advance(std::span<const Real> u, std::span<const Real> v, Real t,
                        Real dt) override {
    const std::vector<Vec3> f =
        gas_->advance(field_.moved_surface(u), field_.segment_velocities(v), t, dt);
    StructureLoad out{field_.to_structure(f), 0.0};
    for (const Vec3& x : f) out.force_y += x.y();
    return out;
  }
  void save_checkpoint() override { gas_->save_checkpoint(); }
  void restore_checkpoint() override { gas_->restore_checkpoint(); }
  void hold_marking(bool hold) override { gas_->hold_marking(hold); }
  Real max_knudsen() const override { return gas_->max_knudsen(); }

 private:
  const ImmersedBoundaryField& field_;
  std::unique_ptr<ImmersedGasModel> gas_;
};

}  // namespace

std::unique_ptr<StructureGas> ImmersedBoundaryField::surface_gas(
    std::unique_ptr<ImmersedGasModel> gas) const {
  return std::make_unique<SurfaceGas>(*this, std::move(gas));
}

}  // namespace rfmems

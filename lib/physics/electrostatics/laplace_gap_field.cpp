#include "physics/electrostatics/laplace_gap_field.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"
#include "core/process_cpu_clock.hpp"
#include "physics/electrostatics/electrostatic_solver.hpp"
#include "physics/electrostatics/gap_mesh.hpp"

namespace rfmems {

LaplaceGapField::LaplaceGapField(ElasticityOperator& beam, const std::string& bottom_patch,
                                 Real gap, const ElectrodeExtent& electrode,
                                 const LaplaceGapOptions& options)
    : beam_(beam), gap_(gap) {
  const Mesh& beam_mesh = beam.mesh();
  if (beam_mesh.dim() != 2)
    throw InputError("Laplace gap field: the beam must be a 2D (plane) model");
  const int bottom = beam_mesh.find_patch(bottom_patch);
  if (bottom < 0)
    throw InputError(fmt::format("Laplace gap field: the beam has no patch '{}'", bottom_patch));
  const Patch& patch = beam_mesh.patches()[bottom];
  const Real y_bottom = beam_mesh.face_centroid(patch.first_face).y();

  // The gap mesh below the beam, shifted so that its top is the beam's bottom face.
  GapMeshSpec spec;
  spec.x = patch_node_x(beam_mesh, bottom_patch);
  spec.gap = gap;
  spec.n_y = options.gap_cells;
  spec.electrode_begin = electrode.x_min;
  spec.electrode_end = electrode.x_max;
  gap_mesh_ = std::make_unique<Mesh>(make_gap_mesh(spec));
  {
    std::vector<Vec3> nodes = gap_mesh_->nodes();
    for (Vec3& x : nodes) x.y() += y_bottom;
    gap_mesh_->set_node_coordinates(std::move(nodes));
  }
  std::vector<std::string> fixed{"electrode"};
  if (gap_mesh_->find_patch("substrate") >= 0) fixed.push_back("substrate");
  motion_ = std::make_unique<MeshMotion>(*gap_mesh_, std::vector<std::string>{"top"}, fixed,
                                         options.motion);
  std::map<std::string, PotentialBoundary> potentials;
  for (const Patch& p : gap_mesh_->patches()) potentials[p.name] = PotentialBoundary::zero_flux();
  potentials["top"] = PotentialBoundary::potential(1.0);
  potentials["electrode"] = PotentialBoundary::potential(0.0);
  field_ = std::make_unique<ElectrostaticSolver>(*gap_mesh_, potentials);

  // Gap top node k <-> beam bottom node; gap top face <-> beam bottom face (same centroid x).
  beam_nodes_ = beam_mesh.patch_nodes(bottom);
  const std::span<const Index> top_nodes = motion_->moving_nodes();
  node_match_ = match_nodes(beam_mesh, beam_nodes_, *gap_mesh_, top_nodes,
                            1e-9 * (spec.x.back() - spec.x.front()));
  std::map<Index, Index> owner;  // beam node -> a beam cell owning a bottom face on it
  for (Index f = patch.first_face; f < patch.first_face + patch.n_faces; ++f) {
    for (Index node : beam_mesh.face_nodes(f)) owner.emplace(node, beam_mesh.face_owner(f));
    bottom_cells_.push_back(beam_mesh.face_owner(f));
  }
  for (std::size_t k = 0; k < top_nodes.size(); ++k)
    node_owner_.push_back(owner.at(beam_nodes_[node_match_[k]]));
  const int top = gap_mesh_->find_patch("top");
  std::map<Index, Index> face_owner_by_x;  // rounded centroid x -> beam cell
  auto key = [&](Real x) { return static_cast<Index>(std::llround(x / (1e-6 * gap))); };
  for (Index f = patch.first_face; f < patch.first_face + patch.n_faces; ++f)
    face_owner_by_x[key(beam_mesh.face_centroid(f).x())] = beam_mesh.face_owner(f);
  const Patch& top_patch = gap_mesh_->patches()[top];
  top_first_face_ = top_patch.first_face;
  for (Index f = top_patch.first_face; f < top_patch.first_face + top_patch.n_faces; ++f) {
    const auto it = face_owner_by_x.find(key(gap_mesh_->face_centroid(f).x()));
    if (it == face_owner_by_x.end())
      throw MeshError("Laplace gap field: gap and beam faces do not match");
    top_face_cell_.push_back(it->second);
  }
  node_displacement_.resize(top_nodes.size());
}

LaplaceGapField::~LaplaceGapField() = default;

Index LaplaceGapField::gap_cells_total() const { return gap_mesh_->n_cells(); }

Real LaplaceGapField::min_gap(std::span<const Real> u) const {
  Real g = 1e300;
  for (Index c : bottom_cells_) g = std::min(g, gap_ + u[beam_.gap_unknown(c)]);
  return g;
}

Json LaplaceGapField::counters() const {
  return {{"field_solves", solves_}, {"move_s", move_seconds_}, {"field_s", field_seconds_}};
}

StructureLoad LaplaceGapField::load(std::span<const Real> u, Real voltage) {
  const Mesh& beam_mesh = beam_.mesh();
  {
    ScopedCpuTimer timer{move_seconds_};
    const std::vector<Mat3> gradients = beam_.cell_gradients(0.0, u);
    for (std::size_t k = 0; k < node_displacement_.size(); ++k) {
      const Index node = beam_nodes_[node_match_[k]];
      node_displacement_[k] =
          beam_.displacement_at(node_owner_[k], beam_mesh.nodes()[node], u, gradients);
    }
    motion_->move(node_displacement_);
  }
  ScopedCpuTimer timer{field_seconds_};
  field_->solve();
  ++solves_;
  const SurfaceLoad load = field_->surface_load("top");
  // The field scales with V, the Maxwell traction with V^2: solved at V = 1.
  const Real v2 = voltage * voltage;
  StructureLoad out{std::vector<Real>(beam_.size(), 0.0), 0.0};
  Real force_y = 0;
  for (std::size_t i = 0; i < load.faces.size(); ++i) {
    const Vec3 force = load.traction[i] * gap_mesh_->face_area(load.faces[i]).norm();
    const Index c = top_face_cell_[load.faces[i] - top_first_face_];
    out.force[beam_.unknown(c, 0)] += force.x();
    out.force[beam_.gap_unknown(c)] += force.y();
    force_y += force.y();
  }
  for (Real& f : out.force) f *= v2;
  out.force_y = v2 * force_y;
  return out;
}

}  // namespace rfmems

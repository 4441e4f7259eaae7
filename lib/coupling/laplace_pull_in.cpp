#include "coupling/laplace_pull_in.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"
#include "coupling/displacement_control_fixed_point.hpp"
#include "physics/electrostatics/electrostatic_solver.hpp"
#include "physics/electrostatics/gap_mesh.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

LaplacePullIn trace_pull_in_laplace(ElasticityScene& beam, const std::string& bottom_patch,
                                    Real gap, const ElectrodeExtent& electrode, Index control,
                                    const LaplacePullInOptions& options) {
  const Mesh& beam_mesh = *beam.mesh;
  if (beam_mesh.dim() != 2)
    throw InputError("Laplace pull-in: the beam must be a 2D (plane) model");
  const int bottom = beam_mesh.find_patch(bottom_patch);
  if (bottom < 0)
    throw InputError(fmt::format("Laplace pull-in: the beam has no patch '{}'", bottom_patch));
  const Patch& patch = beam_mesh.patches()[bottom];
  const Real y_bottom = beam_mesh.face_centroid(patch.first_face).y();

  // The gap mesh below the beam, shifted so that its top is the beam's bottom face.
  GapMeshSpec spec;
  spec.x = patch_node_x(beam_mesh, bottom_patch);
  spec.gap = gap;
  spec.n_y = options.gap_cells;
  spec.electrode_begin = electrode.x_min;
  spec.electrode_end = electrode.x_max;
  Mesh gap_mesh = make_gap_mesh(spec);
  {
    std::vector<Vec3> nodes = gap_mesh.nodes();
    for (Vec3& x : nodes) x.y() += y_bottom;
    gap_mesh.set_node_coordinates(std::move(nodes));
  }
  std::vector<std::string> fixed{"electrode"};
  if (gap_mesh.find_patch("substrate") >= 0) fixed.push_back("substrate");
  MeshMotion motion(gap_mesh, {"top"}, fixed, options.motion);
  std::map<std::string, PotentialBoundary> potentials;
  for (const Patch& p : gap_mesh.patches()) potentials[p.name] = PotentialBoundary::zero_flux();
  potentials["top"] = PotentialBoundary::potential(1.0);
  potentials["electrode"] = PotentialBoundary::potential(0.0);
  ElectrostaticSolver field(gap_mesh, potentials);

  // Gap top node k <-> beam bottom node; gap top face <-> beam bottom face (same centroid x).
  const std::vector<Index> beam_nodes = beam_mesh.patch_nodes(bottom);
  const std::span<const Index> top_nodes = motion.moving_nodes();
  const std::vector<Index> node_match = match_nodes(beam_mesh, beam_nodes, gap_mesh, top_nodes,
                                                    1e-9 * (spec.x.back() - spec.x.front()));
  std::map<Index, Index> node_owner;  // beam node -> a beam cell owning a bottom face on it
  for (Index f = patch.first_face; f < patch.first_face + patch.n_faces; ++f)
    for (Index node : beam_mesh.face_nodes(f)) node_owner.emplace(node, beam_mesh.face_owner(f));
  const int top = gap_mesh.find_patch("top");
  std::map<Index, Index> face_owner_by_x;  // rounded centroid x -> beam cell
  auto key = [&](Real x) { return static_cast<Index>(std::llround(x / (1e-6 * gap))); };
  for (Index f = patch.first_face; f < patch.first_face + patch.n_faces; ++f)
    face_owner_by_x[key(beam_mesh.face_centroid(f).x())] = beam_mesh.face_owner(f);
  std::vector<Index> top_face_cell;
  const Patch& top_patch = gap_mesh.patches()[top];
  for (Index f = top_patch.first_face; f < top_patch.first_face + top_patch.n_faces; ++f) {
    const auto it = face_owner_by_x.find(key(gap_mesh.face_centroid(f).x()));
    if (it == face_owner_by_x.end())
      throw MeshError("Laplace pull-in: gap and beam faces do not match");
    top_face_cell.push_back(it->second);
  }

  // One factorisation of the (linear) beam stiffness.
  ElasticityOperator& op = *beam.op;
  const Index n = op.size();
  std::vector<Real> k_values(op.stiffness_pattern().nnz()), zero(n, 0.0);
  op.stiffness(0.0, zero, k_values);
  KluFactorization stiffness(op.stiffness_pattern(), k_values);

  LaplacePullIn out;
  out.gap_cells_total = gap_mesh.n_cells();
  // Force per V^2 on the beam's unknowns at displacement u (moves the gap mesh).
  std::vector<Vec3> node_displacement(top_nodes.size());
  auto load_per_volt2 = [&](std::span<const Real> u) {
    const std::vector<Mat3> gradients = op.cell_gradients(0.0, u);
    for (std::size_t k = 0; k < top_nodes.size(); ++k) {
      const Index node = beam_nodes[node_match[k]];
      node_displacement[k] =
          op.displacement_at(node_owner.at(node), beam_mesh.nodes()[node], u, gradients);
    }
    motion.move(node_displacement);
    field.solve();
    ++out.coupling_iterations;
    const SurfaceLoad load = field.surface_load("top");
    std::vector<Real> q(n, 0.0);
    for (std::size_t i = 0; i < load.faces.size(); ++i) {
      const Vec3 force = load.traction[i] * gap_mesh.face_area(load.faces[i]).norm();
      const Index c = top_face_cell[load.faces[i] - top_patch.first_face];
      q[2 * c] += force.x();
      q[2 * c + 1] += force.y();
    }
    return q;
  };

  // Equilibrium at delta from a solved state: Aitken-relaxed fixed point (see the header).
  auto solve = [&](Real delta, const FoldSample& from) {
    FoldSample s{{}, from.state};
    if (from.point.displacement != 0)
      for (Real& v : s.state) v *= delta / from.point.displacement;
    std::vector<Real>& u = s.state;
    const DisplacementControlResult r =
        relax_displacement_control(stiffness, load_per_volt2, control, delta,
                                   options.coupling_tolerance, options.max_coupling_iterations, u);
    const Real lambda = r.voltage_squared;
    const int it = r.iterations;
    if (!r.converged)
      throw SolverError(
          fmt::format("Laplace pull-in: coupling not converged at delta = {:.4e} m "
                      "after {} iterations",
                      delta, it));
    if (lambda < 0)
      throw SolverError(fmt::format("Laplace pull-in: negative V^2 at delta = {:.4e} m", delta));
    Real min_gap = gap;
    for (const Vec3& d : node_displacement) min_gap = std::min(min_gap, gap + d.y());
    s.point = {delta, std::sqrt(lambda), min_gap, true, it + 1};
    return s;
  };
  FoldSample rest{{0.0, 0.0, gap, true, 0}, std::vector<Real>(n, 0.0)};
  out.result = trace_fold(solve, rest, gap, options.sampling);
  out.result.solves = out.coupling_iterations;
  return out;
}

}  // namespace rfmems

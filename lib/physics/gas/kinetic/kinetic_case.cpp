#include "physics/gas/kinetic/kinetic_case.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "io/case_schema_yaml.hpp"
#include "io/mesh_from_case.hpp"
#include "physics/gas/comet/comet_kinetic_solver.hpp"
#include "physics/gas/kinetic/kinetic_boundary.hpp"
#include "physics/gas/kinetic/sequential_solver.hpp"

namespace rfmems {
namespace {

KineticGas read_gas(const CaseNode& node) {
  KineticGas gas;
  gas.model = collision_model_from_name(node.get_choice("collision", {"bgk", "esbgk"}, "esbgk"));
  gas.R = node.get_real("R", gas.R, Range::positive());
  gas.mu_ref = node.get_quantity("mu_ref", Dimension::Viscosity, gas.mu_ref, Range::positive());
  gas.T_ref = node.get_quantity("T_ref", Dimension::Temperature, gas.T_ref, Range::positive());
  gas.omega = node.get_real("omega", gas.omega, Range::closed(0, 2));
  gas.prandtl = node.get_real("prandtl", gas.prandtl, Range::closed(2.0 / 3.0 - 1e-9, 10));
  return gas;
}

Real largest_extent(const FaceGraph& g) {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Vec3& x : g.face_centroid) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return (hi - lo).maxCoeff();
}

}  // namespace

VelocityGrid read_velocity_grid(const CaseNode& vg, Real thermal_speed) {
  const std::vector<Real> points = vg.get_reals("points");
  if (points.size() != 3) vg.fail("points", "expected 3 numbers [N1, N2, N3]");
  std::array<int, 3> n;
  for (int d = 0; d < 3; ++d) {
    if (!(points[d] >= 2 && points[d] <= 200 && points[d] == std::floor(points[d])))
      vg.fail("points", "each must be an integer in [2, 200]");
    n[d] = static_cast<int>(points[d]);
  }
  const std::string type = vg.get_choice("type", velocity_rule_names(), "uniform");
  const Real extent = vg.get_real("extent", 3.5, Range::positive());
  const Real stretch = vg.get_real("stretch", 3.0, Range::positive());
  std::array<VelocityRule, 3> rule;
  Vec3 extents;
  static const char* const kAxes[3] = {"x", "y", "z"};
  for (int d = 0; d < 3; ++d) {
    const CaseNode axis = vg.child_or_empty(kAxes[d]);
    rule[d] = velocity_rule_from_name(axis.get_choice("type", velocity_rule_names(), type));
    extents[d] = axis.get_real("extent", extent, Range::positive());
    if (rule[d] == VelocityRule::HalfRangeHermite && n[d] % 2 != 0)
      vg.fail("points", std::string("half_range_hermite along ") + kAxes[d] +
                            " needs an even number of points");
  }
  return VelocityGrid::product(rule, n, extents, stretch, thermal_speed);
}

KineticSolverSettings read_kinetic_solver_settings(const CaseNode& node) {
  KineticSolverSettings s;
  std::vector<std::string> names;
  for (const auto& [name, fn] : kinetic_solvers()) names.push_back(name);
  s.type = node.get_choice("type", names, "sequential");
  if (s.type == "comet") read_comet_options(node);  // its keys are checked with the case's
  s.tolerance = node.get_real("tolerance", 1e-6, Range::open(0, 1));
  s.max_iterations =
      static_cast<int>(node.get_int("max_iterations", 200000, Range::closed(1, 1e9)));
  s.transport = read_transport_scheme(node);
  s.node = node;
  return s;
}

TransportScheme read_transport_scheme(const CaseNode& node) {
  TransportScheme t;
  t.order = transport_order_from_name(
      node.get_choice("transport", {"first_order", "second_order"}, "first_order"));
  t.limiter = slope_limiter_from_name(node.get_choice(
      "limiter", {"venkatakrishnan", "barth_jespersen", "none"}, "venkatakrishnan"));
  t.venkatakrishnan_k = node.get_real("limiter_k", 1.0, Range::positive());
  t.reconstruct_boundaries = node.get_bool("boundary_reconstruction", true);
  return t;
}

KineticScene build_kinetic_scene(const CaseNode& root, const std::string& case_dir,
                                 const Communicator& comm) {
  KineticScene scene;
  scene.mesh = std::make_unique<Mesh>(mesh_from_case(root.child("mesh"), case_dir));
  scene.graph = std::make_unique<FaceGraph>(face_graph_of(*scene.mesh));
  const KineticGas gas = read_gas(root.child_or_empty("gas"));

  const CaseNode initial = root.child("initial");
  scene.initial.T = initial.get_quantity("T", Dimension::Temperature, Range::positive());
  scene.reference_length =
      initial.has("reference_length")
          ? initial.get_quantity("reference_length", Dimension::Length, Range::positive())
          : largest_extent(*scene.graph);
  const bool has_density = initial.has("density"), has_knudsen = initial.has("knudsen");
  if (has_density == has_knudsen)
    initial.fail("density", "give exactly one of 'density' and 'knudsen'");
  scene.initial.rho = has_density
                          ? initial.get_quantity("density", Dimension::Density, Range::positive())
                          : gas.density_for_knudsen(initial.get_real("knudsen", Range::positive()),
                                                    scene.initial.T, scene.reference_length);
  scene.initial.u = initial.has("velocity")
                        ? initial.get_vec3_quantity("velocity", Dimension::Velocity)
                        : Vec3::Zero();
  scene.knudsen = gas.knudsen(scene.initial.rho, scene.initial.T, scene.reference_length);

  VelocityGrid grid =
      read_velocity_grid(root.child("velocity_grid"), gas.thermal_speed(scene.initial.T));

  std::vector<KineticBoundary> bcs =
      kinetic_boundaries_from_case(root.child("boundaries"), *scene.graph);
  for (std::size_t p = 0; p < bcs.size(); ++p)
    scene.conditions[scene.graph->patch_names[p]] = bcs[p];
  const CaseNode solver = root.child_or_empty("solver");
  scene.solver = read_kinetic_solver_settings(solver);

  // Periodic patches and a body force: the sequential solver on one rank (COMET's coarse
  // levels and the distributed parts carry neither).
  const CaseNode force = root.child_or_empty("body_force");
  if (force.has("acceleration")) {
    const std::vector<Real> a = force.get_reals("acceleration");
    if (a.size() != 3) force.fail("acceleration", "expected 3 numbers [a_x, a_y, a_z] in m/s^2");
    scene.body_force = Vec3(a[0], a[1], a[2]);
  }
  const bool periodic = std::any_of(bcs.begin(), bcs.end(), [](const KineticBoundary& b) {
    return b.kind == KineticBoundaryKind::Periodic;
  });
  if ((periodic || scene.body_force.squaredNorm() > 0) && scene.solver.type != "sequential")
    solver.fail("type", "periodic boundaries and body_force need the sequential solver");
  if (periodic && !comm.is_serial())
    throw InputError("periodic boundaries run on one rank (run without mpirun)");

  const CaseNode output = root.child_or_empty("output");
  if (output.has("forces")) {
    for (const std::string& p : output.get_strings("forces")) {
      if (scene.graph->find_patch(p) < 0) output.fail("forces", "no patch named '" + p + "'");
      scene.force_patches.push_back(p);
    }
  } else {
    for (std::size_t p = 0; p < bcs.size(); ++p)
      if (bcs[p].kind == KineticBoundaryKind::DiffuseWall ||
          bcs[p].kind == KineticBoundaryKind::SpecularWall)
        scene.force_patches.push_back(scene.graph->patch_names[p]);
  }

  if (!comm.is_serial()) {
    // This rank's part; its patches by name (a part may lack some), and the faces closing
    // its ghost layer ("processor") get a placeholder: only ghost cells touch them.
    scene.distributed = std::make_unique<DistributedMesh>(distribute_mesh(*scene.mesh, comm, 1));
    const FaceGraph global_graph = std::move(*scene.graph);
    *scene.graph = face_graph_of(scene.distributed->local.mesh);
    std::vector<KineticBoundary> local_bcs;
    for (const std::string& name : scene.graph->patch_names) {
      const int p = global_graph.find_patch(name);
      local_bcs.push_back(p >= 0 ? bcs[p] : KineticBoundary::specular_wall());
    }
    bcs = std::move(local_bcs);
  }
  scene.op = std::make_unique<KineticOperator>(*scene.graph, std::move(grid), gas, std::move(bcs));
  if (scene.distributed) scene.op->set_parallel(comm, &scene.distributed->exchange);
  scene.op->set_transport(scene.solver.transport);
  scene.op->set_body_force(scene.body_force);
  return scene;
}

std::vector<Real> KineticScene::gather(std::span<const Real> values, int block) const {
  if (!distributed) return {values.begin(), values.begin() + graph->n_owned_cells * block};
  return gather_to_root(op->communicator(), distributed->local, values, block,
                        distributed->n_global_cells);
}

const std::map<std::string, KineticSolverFunction>& kinetic_solvers() {
  static const std::map<std::string, KineticSolverFunction> solvers = {
      {"sequential",
       [](KineticOperator& op, std::span<Real> f, const KineticSolverSettings& s,
          const std::function<bool(int, Real)>& monitor) {
         SequentialOptions options;
         options.tolerance = s.tolerance;
         options.max_iterations = s.max_iterations;
         options.monitor = monitor;
         return solve_sequential(op, f, options);
       }},
      {"comet",
       [](KineticOperator& op, std::span<Real> f, const KineticSolverSettings& s,
          const std::function<bool(int, Real)>& monitor) {
         return solve_comet(op, f, read_comet_options(*s.node), s.tolerance, s.max_iterations,
                            monitor);
       }},
  };
  return solvers;
}

void add_transport_scheme_keys(CaseSchema& schema, const std::string& section) {
  const auto group = std::find_if(schema.begin(), schema.end(),
                                  [&](const CaseKeyGroup& g) { return g.section == section; });
  if (group == schema.end())
    throw std::logic_error("transport scheme keys: no group '" + section + "' to add them to");
  const CaseSchema transport =
      embedded_case_schema("physics/gas/kinetic/transport_scheme.keys.yaml");
  group->keys.insert(group->keys.end(), transport.at(0).keys.begin(), transport.at(0).keys.end());
}

CaseSchema kinetic_case_keys() {
  CaseSchema own = embedded_case_schema("physics/gas/kinetic/kinetic_case.keys.yaml");
  add_transport_scheme_keys(own, "solver");
  return join_schemas({mesh_case_keys(), own, kinetic_boundary_case_keys(), comet_case_keys()});
}

}  // namespace rfmems

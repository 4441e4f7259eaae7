// A kinetic gas simulation from a case file: mesh, gas, velocity grid, boundaries, initial
// state and solver settings, and the solver chosen by name (the rfmems-gas driver's model).
//
//   mesh: {type: rectangle, size: [1 m, 1 m], cells: [1, 80]}     # io/mesh_from_case.hpp
//   gas:                                 # all optional; defaults: argon (thesis ch. 5)
//     collision: esbgk                   # bgk | esbgk
//     R: 208.13                          # J/(kg K)
//     mu_ref: 2.117e-5 Pa s
//     T_ref: 273.15 K
//     omega: 0.81
//     prandtl: 0.6667                    # ESBGK only; [2/3, 10]
//   initial:                             # uniform Maxwellian
//     T: 273.15 K
//     density: 9.28e-6 kg/m^3            # or: knudsen: 0.1 (with reference_length)
//     knudsen: 0.1                       # Kn = lambda / L, lambda = mu/p sqrt(pi R T/2)
//     reference_length: 1 m              # L (default: the mesh's largest extent)
//     velocity: [0, 0, 0]                # optional
//   velocity_grid:                       # velocity_grid.hpp, velocity_quadrature.hpp
//     points: [10, 10, 10]
//     type: uniform                      # | gauss_hermite | half_range_hermite | sinh_stretched
//     extent: 3.5                        # half-width in units of sqrt(2 R T_initial)
//     stretch: 3                         # sinh_stretched: x = E sinh(a s) / sinh(a)
//     y: {type: half_range_hermite}      # x, y, z: one direction's own type and extent
//   boundaries: {...}                    # kinetic_boundary.hpp, every patch (periodic
//                                        # pairs: sequential solver, one rank)
//   body_force:
//     acceleration: [100, 0, 0]          # m/s^2 (kinetic_operator.hpp; sequential solver)
//   solver:
//     type: sequential                   # sequential | comet (registry below)
//     tolerance: 1e-6                    # on ||r||_2 / ||r_0||_2
//     max_iterations: 200000
//     transport: first_order             # | second_order (second_order_transport.hpp)
//     limiter: venkatakrishnan           # second order: | barth_jespersen | none
//     limiter_k: 1                       # Venkatakrishnan's K
//     boundary_reconstruction: true      # second order: reconstructed values at boundaries
//   output:
//     forces: [top, bottom]              # patches whose force / heat flow is reported
//                                        # (default: every wall patch)
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fv/face_graph.hpp"
#include "io/case_file.hpp"
#include "io/case_schema.hpp"
#include "mesh/mesh.hpp"
#include "parallel/distributed_mesh.hpp"
#include "physics/gas/kinetic/kinetic_operator.hpp"
#include "physics/gas/kinetic/kinetic_solve_result.hpp"

namespace rfmems {

struct KineticSolverSettings {
  std::string type = "sequential";
  Real tolerance = 1e-6;
  int max_iterations = 200000;
  TransportScheme transport;     // applied to the scene's operator
  std::optional<CaseNode> node;  // the whole `solver:` map, for solver-specific keys
};

// Serial: graph is the whole mesh's. Distributed (comm.size() > 1): `mesh` is still the whole
// mesh (the root writes results on it), `distributed` holds this rank's part with one ghost
// layer and its exchange, and graph / op live on that part.
struct KineticScene {
  std::unique_ptr<Mesh> mesh;
  std::unique_ptr<DistributedMesh> distributed;
  std::unique_ptr<FaceGraph> graph;
  std::unique_ptr<KineticOperator> op;
  GasState initial;
  Real reference_length = 0;
  Real knudsen = 0;  // of the initial state over reference_length
  KineticSolverSettings solver;
  Vec3 body_force = Vec3::Zero();          // acceleration, m/s^2
  std::vector<std::string> force_patches;  // by name: a rank's part may lack a patch
  // Every patch's condition by name, the whole mesh's (a rank's operator holds its part's).
  std::map<std::string, KineticBoundary> conditions;

  // Owned cells' values (block per cell) in global cell order on the root (serial: as is).
  std::vector<Real> gather(std::span<const Real> values, int block) const;
};

// Reads every section above (InputError naming file and key on bad input); distributes the
// mesh over comm's ranks (METIS) when there are several.
KineticScene build_kinetic_scene(const CaseNode& root, const std::string& case_dir,
                                 const Communicator& comm = Communicator::serial());

// Reads `velocity_grid:` (above): the product of one rule per direction, velocities in units of
// thermal_speed (sqrt(2 R T) of the initial state).
VelocityGrid read_velocity_grid(const CaseNode& velocity_grid, Real thermal_speed);
// Reads `solver:` (type must be a registered solver).
KineticSolverSettings read_kinetic_solver_settings(const CaseNode& solver);
// The transport keys of a node (transport, limiter, limiter_k, boundary_reconstruction; above):
// the body-fitted gas's `solver:` and the immersed switch's `gas:` block.
TransportScheme read_transport_scheme(const CaseNode& node);
// Appends the keys read_transport_scheme reads (transport_scheme.keys.yaml) to the group of
// `section` in schema, the group of the node a reader gives it.
void add_transport_scheme_keys(CaseSchema& schema, const std::string& section);

// A steady solver: iterates f (the initial state on entry); monitor(iteration, ratio) may stop
// it by returning false.
using KineticSolverFunction = std::function<KineticSolveResult(
    KineticOperator& op, std::span<Real> f, const KineticSolverSettings& settings,
    const std::function<bool(int, Real)>& monitor)>;

// The solvers by name ("sequential"; COMET registers "comet").
const std::map<std::string, KineticSolverFunction>& kinetic_solvers();

// The keys build_kinetic_scene reads, the mesh's, boundaries' and solvers' included
// (kinetic_case.keys.yaml; io/case_schema.hpp).
CaseSchema kinetic_case_keys();

}  // namespace rfmems

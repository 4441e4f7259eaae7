#include "physics/elasticity/distributed_elasticity.hpp"

namespace rfmems {

namespace {

std::unique_ptr<SecondOrderOperator> local_elasticity(const ElasticityOperator& global,
                                                      const LocalMesh& part) {
  // The same condition on each physical patch (by name: the local mesh numbers its patches
  // in its own order); the cut through the last ghost layer is clamped.
  std::vector<ElasticityBoundary> boundaries;
  for (const Patch& p : part.mesh.patches()) {
    const int g = global.mesh().find_patch(p.name);
    boundaries.push_back(g >= 0 ? global.boundaries()[g]
                                : ElasticityBoundary{ElasticityBoundary::Kind::Fixed, {}});
  }
  auto local = std::make_unique<ElasticityOperator>(part.mesh, global.material(),
                                                    std::move(boundaries), global.body_force(),
                                                    global.requested_reconstruction_degree());
  local->set_damping_time(global.damping_time());  // the global mesh's beta, not the part's
  local->set_geometric_nonlinearity(global.geometric_nonlinearity());
  return local;
}

}  // namespace

DistributedElasticity::DistributedElasticity(const ElasticityOperator& global,
                                             const Communicator& comm)
    : DistributedLocalOperator(
          global.mesh(), comm, kGhostLayers, global.dim(),
          [&global](const LocalMesh& part) { return local_elasticity(global, part); }) {}

}  // namespace rfmems

#include "physics/plate/distributed_plate.hpp"

#include <unordered_map>

namespace rfmems {

namespace {

std::unique_ptr<SecondOrderOperator> local_plate(const PlateOperator& global,
                                                 const LocalMesh& part) {
  std::vector<PlateBoundary> boundaries;
  for (const Patch& p : part.mesh.patches()) {
    const int g = global.mesh().find_patch(p.name);
    boundaries.push_back(g >= 0 ? global.boundaries()[g]
                                : PlateBoundary{PlateBoundary::Kind::Clamped, {}});
  }
  auto op = std::make_unique<PlateOperator>(part.mesh, global.section(), std::move(boundaries),
                                            global.pressure(), global.reconstruction_degree());
  std::unordered_map<Index, Index> local_of_global;
  for (std::size_t c = 0; c < part.global_cell.size(); ++c)
    local_of_global.emplace(part.global_cell[c], static_cast<Index>(c));
  for (const auto& [cell, value] : global.point_loads()) {
    const auto it = local_of_global.find(cell);
    if (it != local_of_global.end()) op->add_point_load(it->second, value);
  }
  return op;
}

}  // namespace

DistributedPlate::DistributedPlate(const PlateOperator& global, const Communicator& comm)
    : DistributedLocalOperator(
          global.mesh(), comm, kGhostLayers, 3,
          [&global](const LocalMesh& part) { return local_plate(global, part); }) {}

}  // namespace rfmems

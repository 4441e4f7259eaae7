#include "ibm/background_partition.hpp"

namespace rfmems {

Partition partition_fluid_background(const Mesh& background, const CellMarking& rest,
                                     const Communicator& comm) {
  std::vector<int> weights(background.n_cells());
  for (std::size_t b = 0; b < weights.size(); ++b)
    weights[b] = rest.cell[b] == CellClass::Fluid ? 16 : 1;
  Partition p;
  if (comm.is_root()) p = partition_cells(background, comm.size(), weights);
  comm.broadcast(p.part);
  p.n_parts = comm.size();
  p.edge_cut = comm.sum(comm.is_root() ? p.edge_cut : Index{0});
  p.imbalance = comm.max(comm.is_root() ? p.imbalance : 0.0);
  return p;
}

}  // namespace rfmems

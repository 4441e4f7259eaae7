#include "parallel/distributed_mesh.hpp"

#include <mpi.h>

namespace rfmems {

DistributedMesh distribute_mesh(const Mesh& global, const Communicator& comm, int ghost_layers,
                                std::span<const int> weights) {
  DistributedMesh d;
  d.n_global_cells = global.n_cells();
  // Partitioned on the root and broadcast: METIS is deterministic with its seed, but one
  // answer everywhere should not depend on that.
  if (comm.is_root()) d.partition = partition_cells(global, comm.size(), weights);
  d.partition.n_parts = comm.size();
  comm.broadcast(d.partition.part);
  d.local =
      extract_local_mesh(global, d.partition, comm.rank(), comm.is_serial() ? 0 : ghost_layers);
  d.exchange = GhostExchange(comm, d.local);
  return d;
}

std::vector<Real> gather_to_root(const Communicator& comm, const LocalMesh& local,
                                 std::span<const Real> values, int block, Index n_global_cells) {
  const Index n_owned = local.mesh.n_owned_cells();
  if (comm.is_serial()) {
    std::vector<Real> all(n_global_cells * block);
    for (Index c = 0; c < n_owned; ++c)
      std::copy(values.begin() + c * block, values.begin() + (c + 1) * block,
                all.begin() + local.global_cell[c] * block);
    return all;
  }
  MPI_Comm mpi = static_cast<MPI_Comm>(comm.handle());
  const int p = comm.size();
  int n_mine = static_cast<int>(n_owned);
  std::vector<int> counts(p), offsets(p + 1, 0);
  MPI_Gather(&n_mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, mpi);
  for (int r = 0; r < p; ++r) offsets[r + 1] = offsets[r] + counts[r];

  std::vector<Index> ids(local.global_cell.begin(), local.global_cell.begin() + n_owned), all_ids;
  if (comm.is_root()) all_ids.resize(offsets[p]);
  MPI_Gatherv(ids.data(), n_mine, MPI_INT64_T, all_ids.data(), counts.data(), offsets.data(),
              MPI_INT64_T, 0, mpi);

  std::vector<int> value_counts(p), value_offsets(p);
  for (int r = 0; r < p; ++r) {
    value_counts[r] = counts[r] * block;
    value_offsets[r] = offsets[r] * block;
  }
  std::vector<Real> stacked;
  if (comm.is_root()) stacked.resize(static_cast<std::size_t>(offsets[p]) * block);
  MPI_Gatherv(values.data(), n_mine * block, MPI_DOUBLE, stacked.data(), value_counts.data(),
              value_offsets.data(), MPI_DOUBLE, 0, mpi);
  if (!comm.is_root()) return {};
  std::vector<Real> all(n_global_cells * block);
  for (std::size_t i = 0; i < all_ids.size(); ++i)
    std::copy(stacked.begin() + i * block, stacked.begin() + (i + 1) * block,
              all.begin() + all_ids[i] * block);
  return all;
}

}  // namespace rfmems

// Ghost-cell exchange with non-blocking point-to-point MPI (Isend/Irecv, one message per
// neighbouring rank and direction), for fields stored cell-major with `block` values per cell
// (3 for a displacement, N for the ordinates of the kinetic model).
//
// Built once from the cells a rank holds: owned cells [0, n_owned) and ghosts after them,
// each with its global number and the rank that owns it. Each rank tells the owners which of
// their cells it holds as ghosts (global numbers), and both sides keep the local index lists
// in the same order, so an exchange is pack -> Isend/Irecv -> Waitall -> unpack with no
// searching. The cells can be a mesh's (LocalMesh) or any numbering, e.g. the agglomerated
// coarse cells of COMET's multigrid levels (fv/agglomeration.hpp), whose global numbers exist
// only as (rank offset + local index).
//
// Every exchange is counted (parallel/communication_counters.hpp).
#pragma once
#include <span>
#include <vector>

#include "core/types.hpp"
#include "parallel/communicator.hpp"

namespace rfmems {

struct LocalMesh;

class GhostExchange {
 public:
  GhostExchange() = default;
  GhostExchange(const Communicator& comm, const LocalMesh& local);
  // global_cell, owner_rank: per local cell (owned first, n_owned of them, then ghosts).
  // Collective: every rank of comm constructs its exchange together.
  GhostExchange(const Communicator& comm, Index n_owned, std::span<const Index> global_cell,
                std::span<const int> owner_rank);

  // Overwrites the ghost cells' blocks of `values` with their owners' current values.
  void exchange(std::span<Real> values, int block) const;
  // The same for integer data (e.g. the coarse cell numbers of fine cells).
  void exchange(std::span<Index> values, int block) const;

  // Messages per exchange (sent by this rank) and their total size in values per unit block,
  // for the communication model of the scaling benchmarks.
  int n_neighbours() const { return static_cast<int>(send_rank_.size()); }
  Index n_sent_cells() const;
  Index n_received_cells() const;

 private:
  template <class T>
  void exchange_blocks(std::span<T> values, int block, void* mpi_type) const;

  Communicator comm_ = Communicator::serial();
  std::vector<int> send_rank_, recv_rank_;
  std::vector<std::vector<Index>> send_cells_, recv_cells_;  // local indices, matching order
};

}  // namespace rfmems

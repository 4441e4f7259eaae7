// Ghost-cell exchange with non-blocking point-to-point MPI (Isend/Irecv, one message per
// neighbouring rank and direction), for fields stored cell-major with `block` values per cell
// (3 for a displacement, N for the ordinates of the kinetic model).
//
// Built once from a local mesh: each rank tells the owners which of their cells it holds as
// ghosts (global numbers), and both sides keep the local index lists in the same order, so an
// exchange is pack -> Isend/Irecv -> Waitall -> unpack with no searching.
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

  // Overwrites the ghost cells' blocks of `values` with their owners' current values.
  void exchange(std::span<Real> values, int block) const;

  // Messages per exchange (sent by this rank) and their total size in values per unit block,
  // for the communication model of the scaling benchmarks.
  int n_neighbours() const { return static_cast<int>(send_rank_.size()); }
  Index n_sent_cells() const;
  Index n_received_cells() const;

 private:
  Communicator comm_ = Communicator::serial();
  std::vector<int> send_rank_, recv_rank_;
  std::vector<std::vector<Index>> send_cells_, recv_cells_;  // local indices, matching order
};

}  // namespace rfmems

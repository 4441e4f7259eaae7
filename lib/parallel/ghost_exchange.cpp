#include "parallel/ghost_exchange.hpp"

#include <mpi.h>

#include <map>
#include <unordered_map>

#include "core/error.hpp"
#include "mesh/partition.hpp"
#include "parallel/communication_counters.hpp"

namespace rfmems {

namespace {

constexpr int kRequestTag = 7301;
constexpr int kValuesTag = 7302;

MPI_Comm comm_of(const Communicator& comm) { return static_cast<MPI_Comm>(comm.handle()); }

}  // namespace

GhostExchange::GhostExchange(const Communicator& comm, const LocalMesh& local)
    : GhostExchange(comm, local.mesh.n_owned_cells(), local.global_cell, local.owner_part) {}

GhostExchange::GhostExchange(const Communicator& comm, Index n_owned,
                             std::span<const Index> global_cell, std::span<const int> owner_rank)
    : comm_(comm) {
  const Index n_cells = static_cast<Index>(global_cell.size());
  if (comm.is_serial()) {
    if (n_cells != n_owned) throw SolverError("GhostExchange: ghost cells in a serial run");
    return;
  }
  // Ghosts grouped by owner, in local order (the order both sides keep).
  std::map<int, std::vector<Index>> ghosts_of;
  for (Index c = n_owned; c < n_cells; ++c) ghosts_of[owner_rank[c]].push_back(c);

  const int p = comm.size();
  std::vector<int> n_request(p, 0), n_requested(p, 0);
  for (const auto& [owner, cells] : ghosts_of) n_request[owner] = static_cast<int>(cells.size());
  MPI_Alltoall(n_request.data(), 1, MPI_INT, n_requested.data(), 1, MPI_INT, comm_of(comm));

  // Ask each owner for its cells by global number.
  std::vector<std::vector<Index>> requests_out, requests_in;
  std::vector<MPI_Request> pending;
  for (const auto& [owner, cells] : ghosts_of) {
    recv_rank_.push_back(owner);
    recv_cells_.push_back(cells);
    std::vector<Index> ids;
    for (Index c : cells) ids.push_back(global_cell[c]);
    requests_out.push_back(std::move(ids));
  }
  for (int r = 0; r < p; ++r)
    if (n_requested[r] > 0) {
      send_rank_.push_back(r);
      requests_in.emplace_back(n_requested[r]);
    }
  pending.resize(requests_out.size() + requests_in.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < requests_in.size(); ++i)
    MPI_Irecv(requests_in[i].data(), static_cast<int>(requests_in[i].size()), MPI_INT64_T,
              send_rank_[i], kRequestTag, comm_of(comm), &pending[k++]);
  for (std::size_t i = 0; i < requests_out.size(); ++i)
    MPI_Isend(requests_out[i].data(), static_cast<int>(requests_out[i].size()), MPI_INT64_T,
              recv_rank_[i], kRequestTag, comm_of(comm), &pending[k++]);
  MPI_Waitall(static_cast<int>(pending.size()), pending.data(), MPI_STATUSES_IGNORE);

  std::unordered_map<Index, Index> local_of_global;
  for (Index c = 0; c < n_owned; ++c) local_of_global.emplace(global_cell[c], c);
  for (const auto& ids : requests_in) {
    std::vector<Index> cells;
    for (Index g : ids) {
      auto it = local_of_global.find(g);
      if (it == local_of_global.end())
        throw SolverError("GhostExchange: a rank asked for a cell this rank does not own");
      cells.push_back(it->second);
    }
    send_cells_.push_back(std::move(cells));
  }
}

template <class T>
void GhostExchange::exchange_blocks(std::span<T> values, int block, void* mpi_type) const {
  if (comm_.is_serial()) return;
  const MPI_Datatype type = static_cast<MPI_Datatype>(mpi_type);
  std::vector<std::vector<T>> out(send_rank_.size()), in(recv_rank_.size());
  std::vector<MPI_Request> pending(send_rank_.size() + recv_rank_.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < recv_rank_.size(); ++i) {
    in[i].resize(recv_cells_[i].size() * block);
    MPI_Irecv(in[i].data(), static_cast<int>(in[i].size()), type, recv_rank_[i], kValuesTag,
              comm_of(comm_), &pending[k++]);
  }
  std::int64_t bytes = 0;
  for (std::size_t i = 0; i < send_rank_.size(); ++i) {
    out[i].reserve(send_cells_[i].size() * block);
    for (Index c : send_cells_[i])
      out[i].insert(out[i].end(), values.begin() + c * block, values.begin() + (c + 1) * block);
    bytes += static_cast<std::int64_t>(out[i].size() * sizeof(T));
    MPI_Isend(out[i].data(), static_cast<int>(out[i].size()), type, send_rank_[i], kValuesTag,
              comm_of(comm_), &pending[k++]);
  }
  detail::count_exchange();
  detail::count_messages(static_cast<std::int64_t>(send_rank_.size()), bytes);
  {
    const detail::WaitTimer timer;
    MPI_Waitall(static_cast<int>(pending.size()), pending.data(), MPI_STATUSES_IGNORE);
  }
  for (std::size_t i = 0; i < recv_rank_.size(); ++i)
    for (std::size_t j = 0; j < recv_cells_[i].size(); ++j)
      std::copy(in[i].begin() + j * block, in[i].begin() + (j + 1) * block,
                values.begin() + recv_cells_[i][j] * block);
}

void GhostExchange::exchange(std::span<Real> values, int block) const {
  exchange_blocks(values, block, static_cast<void*>(MPI_DOUBLE));
}

void GhostExchange::exchange(std::span<Index> values, int block) const {
  exchange_blocks(values, block, static_cast<void*>(MPI_INT64_T));
}

Index GhostExchange::n_sent_cells() const {
  Index n = 0;
  for (const auto& cells : send_cells_) n += static_cast<Index>(cells.size());
  return n;
}

Index GhostExchange::n_received_cells() const {
  Index n = 0;
  for (const auto& cells : recv_cells_) n += static_cast<Index>(cells.size());
  return n;
}

}  // namespace rfmems

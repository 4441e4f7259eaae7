// The MPI communicator the library runs on, and the few collectives it needs. Everything MPI
// in rfmems goes through lib/parallel, as everything SUNDIALS goes through lib/solvers: physics
// code sees ranks, sums and ghost exchanges, never MPI handles.
//
// MpiSession initialises MPI once per program (drivers and MPI tests construct one in main);
// code that runs without it (the serial unit tests) sees Communicator::serial(), a
// one-rank communicator whose collectives are identities.
#pragma once
#include <span>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  static bool active();
};

class Communicator {
 public:
  // MPI_COMM_WORLD if MPI is initialised, else the serial communicator.
  static Communicator world();
  static Communicator serial();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool is_root() const { return rank_ == 0; }
  bool is_serial() const { return size_ == 1; }

  Real sum(Real x) const;
  Index sum(Index x) const;
  Real max(Real x) const;
  Index max(Index x) const;
  Real min(Real x) const;
  // Sum of x over the ranks below this one (rank 0: 0): the first global number of this
  // rank's items when each rank numbers its own consecutively.
  Index exclusive_sum(Index x) const;
  // Element-wise sum across ranks, in place.
  void sum_in_place(std::span<Real> values) const;
  void broadcast(std::vector<int>& values, int root = 0) const;
  void barrier() const;
  // Ends every rank of this communicator's job with `code` (MPI_Abort). For a failure on one
  // rank while the others may be inside a collective (a ghost exchange, a reduction): they
  // would wait for it for ever. Serial: std::exit(code).
  [[noreturn]] void abort(int code) const;

  // The MPI_Comm as an opaque handle (Open MPI's MPI_Comm is a pointer), so this header
  // needs no mpi.h.
  void* handle() const { return handle_; }

 private:
  Communicator(void* handle, int rank, int size) : handle_(handle), rank_(rank), size_(size) {}
  void* handle_ = nullptr;
  int rank_ = 0, size_ = 1;
};

}  // namespace rfmems

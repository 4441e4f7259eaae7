#include "parallel/communicator.hpp"

#include <mpi.h>

#include <cstdlib>

#include "parallel/communication_counters.hpp"

namespace rfmems {

namespace {

MPI_Comm comm_of(void* handle) { return static_cast<MPI_Comm>(handle); }

template <class T>
T all_reduce(void* handle, bool serial, T x, MPI_Datatype type, MPI_Op op) {
  if (serial) return x;
  detail::count_reduction();
  const detail::WaitTimer timer;
  T out{};
  MPI_Allreduce(&x, &out, 1, type, op, comm_of(handle));
  return out;
}

}  // namespace

MpiSession::MpiSession(int* argc, char*** argv) {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised) MPI_Init(argc, argv);
}

MpiSession::~MpiSession() {
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (!finalised) MPI_Finalize();
}

bool MpiSession::active() {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  return initialised && !finalised;
}

Communicator Communicator::world() {
  if (!MpiSession::active()) return serial();
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return Communicator(static_cast<void*>(MPI_COMM_WORLD), rank, size);
}

Communicator Communicator::serial() { return Communicator(nullptr, 0, 1); }

Real Communicator::sum(Real x) const {
  return all_reduce(handle_, is_serial(), x, MPI_DOUBLE, MPI_SUM);
}
Index Communicator::sum(Index x) const {
  return all_reduce(handle_, is_serial(), x, MPI_INT64_T, MPI_SUM);
}
Real Communicator::max(Real x) const {
  return all_reduce(handle_, is_serial(), x, MPI_DOUBLE, MPI_MAX);
}
Index Communicator::max(Index x) const {
  return all_reduce(handle_, is_serial(), x, MPI_INT64_T, MPI_MAX);
}
Real Communicator::min(Real x) const {
  return all_reduce(handle_, is_serial(), x, MPI_DOUBLE, MPI_MIN);
}

void Communicator::sum_in_place(std::span<Real> values) const {
  if (is_serial() || values.empty()) return;
  detail::count_reduction();
  const detail::WaitTimer timer;
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM,
                comm_of(handle_));
}

Index Communicator::exclusive_sum(Index x) const {
  if (is_serial()) return 0;
  detail::count_reduction();
  const detail::WaitTimer timer;
  Index out = 0;
  MPI_Exscan(&x, &out, 1, MPI_INT64_T, MPI_SUM, comm_of(handle_));
  return rank_ == 0 ? 0 : out;  // MPI leaves rank 0's result undefined
}

void Communicator::broadcast(std::vector<int>& values, int root) const {
  if (is_serial()) return;
  long n = static_cast<long>(values.size());
  MPI_Bcast(&n, 1, MPI_LONG, root, comm_of(handle_));
  values.resize(n);
  if (n > 0) MPI_Bcast(values.data(), static_cast<int>(n), MPI_INT, root, comm_of(handle_));
}

void Communicator::barrier() const {
  if (!is_serial()) MPI_Barrier(comm_of(handle_));
}

void Communicator::abort(int code) const {
  if (!is_serial()) MPI_Abort(comm_of(handle_), code);
  std::exit(code);
}

}  // namespace rfmems

#include "parallel/communication_counters.hpp"

namespace rfmems {
namespace {
CommunicationCounters totals;  // one process, one thread of MPI calls (MPI_THREAD_SINGLE)
}  // namespace

CommunicationCounters communication_counters() { return totals; }

namespace detail {
void count_messages(std::int64_t messages, std::int64_t bytes) {
  totals.messages += messages;
  totals.bytes += bytes;
}
void count_exchange() { ++totals.exchanges; }
void count_reduction() { ++totals.reductions; }
}  // namespace detail

}  // namespace rfmems

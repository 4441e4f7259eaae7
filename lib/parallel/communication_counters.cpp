#include "parallel/communication_counters.hpp"

#include <ctime>

namespace rfmems {
namespace {
CommunicationCounters totals;  // one process, one thread of MPI calls (MPI_THREAD_SINGLE)

double seconds(clockid_t clock) {
  timespec ts;
  clock_gettime(clock, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
}  // namespace

CommunicationCounters communication_counters() { return totals; }

namespace detail {
void count_messages(std::int64_t messages, std::int64_t bytes) {
  totals.messages += messages;
  totals.bytes += bytes;
}
void count_exchange() { ++totals.exchanges; }
void count_reduction() { ++totals.reductions; }

WaitTimer::WaitTimer()
    : cpu0_(seconds(CLOCK_PROCESS_CPUTIME_ID)), wall0_(seconds(CLOCK_MONOTONIC)) {}

WaitTimer::~WaitTimer() {
  totals.wait_cpu_seconds += seconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0_;
  totals.wait_wall_seconds += seconds(CLOCK_MONOTONIC) - wall0_;
}
}  // namespace detail

}  // namespace rfmems

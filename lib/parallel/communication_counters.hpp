// What this process has sent through lib/parallel since it started: point-to-point messages
// and their bytes (ghost exchanges), and collective reductions (norms, masses, forces). The
// scaling benchmark's communication model (docs/mpi.md) reads the difference
// of two snapshots around a solve, so the figures are measured by the exchange layer itself,
// not estimated. Counting is a few integer additions per message, and two clock reads around
// each wait (Waitall of an exchange, a reduction): always on. The time in waits is what
// communication and load imbalance cost a rank; Open MPI polls while it waits, so the CPU
// seconds of a waiting rank grow as its wall seconds do (on a machine shared with other
// processes, also while its partner is descheduled).
#pragma once
#include <cstdint>

namespace rfmems {

struct CommunicationCounters {
  std::int64_t messages = 0;     // point-to-point sends (Isend)
  std::int64_t bytes = 0;        // their payload
  std::int64_t exchanges = 0;    // ghost exchanges (each: one message per neighbouring rank)
  std::int64_t reductions = 0;   // Allreduce / Exscan calls
  double wait_cpu_seconds = 0;   // CPU seconds of this process inside those waits
  double wait_wall_seconds = 0;  // wall seconds inside them

  CommunicationCounters operator-(const CommunicationCounters& o) const {
    return {messages - o.messages,
            bytes - o.bytes,
            exchanges - o.exchanges,
            reductions - o.reductions,
            wait_cpu_seconds - o.wait_cpu_seconds,
            wait_wall_seconds - o.wait_wall_seconds};
  }
};

// This process's running totals (a snapshot).
CommunicationCounters communication_counters();

namespace detail {
// Called by the exchange layer (communicator.cpp, ghost_exchange.cpp) only.
void count_messages(std::int64_t messages, std::int64_t bytes);
void count_exchange();
void count_reduction();
// Adds the time of its lifetime to the wait times (one wait of the exchange layer).
class WaitTimer {
 public:
  WaitTimer();
  ~WaitTimer();
  WaitTimer(const WaitTimer&) = delete;
  WaitTimer& operator=(const WaitTimer&) = delete;

 private:
  double cpu0_, wall0_;
};
}  // namespace detail

}  // namespace rfmems

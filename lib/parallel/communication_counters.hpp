// What this process has sent through lib/parallel since it started: point-to-point messages
// and their bytes (ghost exchanges), and collective reductions (norms, masses, forces). The
// scaling benchmark's communication model (docs/BENCHMARKS.md, issue 7) reads the difference
// of two snapshots around a solve, so the figures are measured by the exchange layer itself,
// not estimated. Counting is a few integer additions per message: always on.
#pragma once
#include <cstdint>

namespace rfmems {

struct CommunicationCounters {
  std::int64_t messages = 0;    // point-to-point sends (Isend)
  std::int64_t bytes = 0;       // their payload
  std::int64_t exchanges = 0;   // ghost exchanges (each: one message per neighbouring rank)
  std::int64_t reductions = 0;  // Allreduce / Exscan calls

  CommunicationCounters operator-(const CommunicationCounters& o) const {
    return {messages - o.messages, bytes - o.bytes, exchanges - o.exchanges,
            reductions - o.reductions};
  }
};

// This process's running totals (a snapshot).
CommunicationCounters communication_counters();

namespace detail {
// Called by the exchange layer (communicator.cpp, ghost_exchange.cpp) only.
void count_messages(std::int64_t messages, std::int64_t bytes);
void count_exchange();
void count_reduction();
}  // namespace detail

}  // namespace rfmems

// What a run is checked against before it allocates or writes anything: the memory it may use
// and the result file it will write (which must not be one of its inputs). The driver sets both
// (driver_main: --max-memory, -o); the readers of a case check against them.
#pragma once
#include <cstdint>
#include <string>

#include "io/case_file.hpp"

namespace rfmems {

// The memory a run may use, in bytes: the value set by set_memory_limit, else MemAvailable from
// /proc/meminfo; 0 if neither is known (no limit).
std::uint64_t memory_limit();
// 0: back to MemAvailable.
void set_memory_limit(std::uint64_t bytes);
// Where memory_limit() comes from, for messages: "--max-memory" or "MemAvailable".
std::string memory_limit_source();

// "1.5 GiB", "512 MiB", "3.7e+03 TiB" (%.3g of the largest binary unit, up to TiB).
std::string format_bytes(double bytes);

// If `estimate` bytes exceed memory_limit(): InputError through node.fail(key, ...) with the
// estimate, what it is an estimate of and the limit.
void check_memory_estimate(const CaseNode& node, const std::string& key, double estimate,
                           const std::string& what);

// The result file of this run ("" if unset): set by the driver before the case is read.
void set_result_path(const std::string& path);
const std::string& result_path();
// True if `input` and the result file are the same file (the same path once both are made
// absolute and normal, or the same inode if both exist).
bool is_result_path(const std::string& input);

}  // namespace rfmems

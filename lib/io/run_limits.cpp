// The run's memory limit and result path (run_limits.hpp).
#include "io/run_limits.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace rfmems {

namespace {

std::uint64_t g_memory_limit = 0;
std::string g_result_path;

// MemAvailable from /proc/meminfo ("MemAvailable:   21474836 kB"), in bytes; 0 if absent.
std::uint64_t mem_available() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string name, unit;
    std::uint64_t kib = 0;
    if (fields >> name >> kib >> unit && name == "MemAvailable:") return kib * 1024;
  }
  return 0;
}

}  // namespace

std::uint64_t memory_limit() { return g_memory_limit > 0 ? g_memory_limit : mem_available(); }

void set_memory_limit(std::uint64_t bytes) { g_memory_limit = bytes; }

std::string memory_limit_source() { return g_memory_limit > 0 ? "--max-memory" : "MemAvailable"; }

std::string format_bytes(double bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  int k = 0;
  while (k < 4 && bytes >= 1024) {
    bytes /= 1024;
    ++k;
  }
  return fmt::format("{:.3g} {}", bytes, units[k]);
}

void check_memory_estimate(const CaseNode& node, const std::string& key, double estimate,
                           const std::string& what) {
  const std::uint64_t limit = memory_limit();
  if (limit == 0 || estimate <= static_cast<double>(limit)) return;
  node.fail(key, fmt::format("{} needs an estimated {}, more than the {} the run may use ({})",
                             what, format_bytes(estimate), format_bytes(static_cast<double>(limit)),
                             memory_limit_source()));
}

void set_result_path(const std::string& path) { g_result_path = path; }

const std::string& result_path() { return g_result_path; }

bool is_result_path(const std::string& input) {
  namespace fs = std::filesystem;
  if (g_result_path.empty() || input.empty()) return false;
  std::error_code ec;
  if (fs::equivalent(input, g_result_path, ec) && !ec) return true;
  const fs::path a = fs::weakly_canonical(fs::absolute(input, ec), ec);
  const fs::path b = fs::weakly_canonical(fs::absolute(g_result_path, ec), ec);
  return !a.empty() && a == b;
}

}  // namespace rfmems

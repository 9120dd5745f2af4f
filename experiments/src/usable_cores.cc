#include "cogmap/experiments/usable_cores.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#if defined(__linux__)
#include <sched.h>
#endif

namespace cogmap::experiments {
namespace {

// A whole positive number with nothing around it but blanks, or 0.
long long positive_number(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) {
    text.remove_prefix(1);
  }
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) {
    text.remove_suffix(1);
  }
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value <= 0) return 0;
  return value;
}

std::string read_small_file(const char* path) {
  std::ifstream in(path);
  std::string text;
  if (in) std::getline(in, text);
  return text;
}

// The cores the cgroup's CPU quota allows, 0 for none: cgroup v2, then v1 (inside a container
// the cgroup file system's root is the container's own group).
unsigned cores_of_own_cpu_quota() {
  const std::string v2 = read_small_file("/sys/fs/cgroup/cpu.max");
  if (!v2.empty()) {
    std::istringstream fields(v2);
    std::string quota, period;
    fields >> quota >> period;
    return cores_of_cpu_quota(quota, period);
  }
  return cores_of_cpu_quota(read_small_file("/sys/fs/cgroup/cpu/cpu.cfs_quota_us"),
                            read_small_file("/sys/fs/cgroup/cpu/cpu.cfs_period_us"));
}

}  // namespace

unsigned cores_of_cpu_quota(std::string_view quota, std::string_view period) {
  const long long q = positive_number(quota), p = positive_number(period);
  if (q == 0 || p == 0) return 0;
  const long long cores = (q + p - 1) / p;
  return static_cast<unsigned>(std::min<long long>(cores, 1 << 20));
}

unsigned usable_cores() {
  unsigned cores = std::max(1u, std::thread::hardware_concurrency());
#if defined(__linux__)
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) {
    const int count = CPU_COUNT(&set);
    if (count > 0) cores = static_cast<unsigned>(count);
  }
  if (const unsigned quota = cores_of_own_cpu_quota(); quota > 0) cores = std::min(cores, quota);
#endif
  return std::max(1u, cores);
}

}  // namespace cogmap::experiments

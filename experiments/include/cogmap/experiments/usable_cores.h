#pragma once
/// How many cores this process may run on, for the defaults of `run --threads` and
/// `sweep --jobs`.

#include <string_view>

namespace cogmap::experiments {

/// The CPUs of the process's affinity mask (taskset, cpusets, a container's CPU set), which
/// std::thread::hardware_concurrency() ignores (it counts the machine's), capped by a CPU quota
/// of its cgroup (a container's `--cpus`: quota / period, rounded up); the machine's count where
/// the mask cannot be read; at least 1.
unsigned usable_cores();

/// The cores a CFS quota allows, ceil(quota / period), from the text of cgroup v2's `cpu.max`
/// ("150000 100000") or of cgroup v1's `cpu.cfs_quota_us` and `cpu.cfs_period_us` ("150000",
/// "100000"); 0 when there is no quota ("max", "-1") or the text is not one.
unsigned cores_of_cpu_quota(std::string_view quota, std::string_view period);

}  // namespace cogmap::experiments

#pragma once
/// How many cores this process may run on, for the defaults of `run --threads` and
/// `sweep --jobs`.

namespace cogmap::experiments {

/// The CPUs of the process's affinity mask (taskset, cpusets, a container's CPU set), which
/// std::thread::hardware_concurrency() ignores (it counts the machine's); that count where the
/// mask cannot be read; at least 1.
unsigned usable_cores();

}  // namespace cogmap::experiments

#pragma once
/// Sweeps (experiments/*.sweep.yaml, docs/sweeps.md): a base experiment, a list of seeds and
/// lists of values for some keys; every combination is one run. Expansion order is stable, so
/// `--shard K/N` partitions the same list on every machine.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace cogmap::experiments {

/// One varied key and its values: each value as the results and run directories show it, and
/// as the YAML text of its `--set` assignment, which reads back as the sweep file wrote it (a
/// quoted '007' stays a quoted string, so a numeric key refuses it as it would in the
/// experiment file; docs/experiment-format.md "Numbers").
struct SweepAxis {
  std::string key;                  ///< dotted experiment key, e.g. "mapper.cell_scale_mm"
  std::vector<std::string> values;  ///< each value shown: a scalar's text ("007"), else flow YAML
  std::vector<std::string> set_texts;  ///< each value's --set text ("\"007\"", "55", "[1, 2]")
};

/// A parsed sweep file.
struct SweepSpec {
  std::filesystem::path file;
  std::filesystem::path base;  ///< the base experiment, resolved against the sweep's folder
  std::vector<std::uint64_t> seeds;
  std::vector<SweepAxis> vary;  ///< in file order; the first is the x axis of the plots
};

/// One run of a sweep.
struct SweepRun {
  std::size_t index = 0;  ///< position in the stable expansion order
  std::vector<std::pair<std::string, std::string>> values;  ///< (key, value shown), vary order
  /// The --set text of each value (SweepAxis::set_texts); when empty, the values as shown.
  std::vector<std::string> set_texts;
  std::uint64_t seed = 0;
  /// Directory name under runs/: "key=value,...,seed=N", each part through
  /// safe_path_component (run_directory.h): '/', spaces and the like become '_'.
  std::string dir_name() const;
  /// The --set assignments of this run ("key=value"), seed excluded.
  std::vector<std::string> overrides() const;
};

/// Bounds on a sweep (docs/reliability.md "Limits").
struct SweepLimits {
  /// Most runs in the whole sweep (every shard together), `cogmap sweep --max-runs`. 10 000
  /// runs of the largest shipped experiment take about 14 CPU-hours; a product of 10^7 ran out
  /// of memory while being listed.
  std::size_t max_runs = 10000;
};

/// Parses a sweep file strictly (keys: base, seeds, vary, description); throws
/// yaml::ConfigError naming file, line and key. Refused as well: a seed or a value given twice
/// (`[1, 1]`, or two values whose run directory names would be equal, which two threads would
/// then write at once: `[55, "55"]`, `["a b", a_b]`), and more runs than `limits.max_runs`.
SweepSpec load_sweep(const std::filesystem::path& path, const SweepLimits& limits = {});

/// The cartesian product of the axes (first axis slowest, last fastest), then seeds innermost.
std::vector<SweepRun> expand_sweep(const SweepSpec& spec);

/// A shard "K/N" (1-based K): runs whose index i satisfies i % N == K − 1.
struct Shard {
  std::size_t k = 1;
  std::size_t n = 1;
};

/// Parses "K/N" with 1 <= K <= N; throws std::invalid_argument with a readable message.
Shard parse_shard(const std::string& text);

/// The runs of one shard, in expansion order.
std::vector<SweepRun> shard_runs(const std::vector<SweepRun>& runs, Shard shard);

}  // namespace cogmap::experiments

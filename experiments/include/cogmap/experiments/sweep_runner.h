#pragma once
/// Runs a sweep: every run (or one shard of them) in parallel threads, each run
/// single-threaded and deterministic, each in out/runs/<key=value,...,seed=N>/. A run whose
/// metrics.json exists is finished and skipped, so an interrupted sweep resumes.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/experiments/results_table.h"
#include "cogmap/experiments/sweep.h"
#include "cogmap/mapper/io/asr_json.h"

namespace cogmap::experiments {

/// How to run a sweep.
struct SweepOptions {
  std::filesystem::path out_dir;  ///< runs/ and the results file go here
  unsigned jobs = 1;              ///< worker threads
  Shard shard;                    ///< which part of the runs this process does
  bool progress = false;          ///< progress bar on stderr
};

/// One run as the sweep sees it.
struct PlannedRun {
  SweepRun run;
  Experiment experiment;      ///< base + the run's overrides + its seed, validated
  std::filesystem::path dir;  ///< out/runs/<dir_name>
};

/// Loads the base experiment once per run of the shard with its overrides and seed, so every
/// bad key or value is reported (yaml::ConfigError) before anything runs.
std::vector<PlannedRun> plan_sweep(const SweepSpec& spec, const SweepOptions& options);

/// What happened.
struct SweepOutcome {
  std::size_t runs = 0;               ///< runs in this shard
  std::size_t skipped = 0;            ///< already finished before this call
  std::size_t finished = 0;           ///< run now
  std::vector<std::string> failures;  ///< "<dir>: <error>" per failed run
  std::filesystem::path results_csv;  ///< written even when some runs failed
  ResultsTable results;
};

/// Executes one run; throws on failure. (The CLI passes run_experiment; tests pass fakes.)
using RunFunction = std::function<void(const PlannedRun& run)>;

/// Runs `planned` with `options.jobs` threads, then writes results.csv (or, for a shard of
/// N > 1, results_shard_K_of_N.csv) over every finished run of the shard.
SweepOutcome run_sweep(const SweepSpec& spec, const std::vector<PlannedRun>& planned,
                       const SweepOptions& options, const RunFunction& run_one);

/// The results file name for a shard: results.csv for 1/1, else results_shard_K_of_N.csv.
std::string results_file_name(Shard shard);

/// The marker every `cogmap sweep` writes into its output directory before its first run: with
/// it, the directory's results files and plots/ are a sweep's to replace on the next call.
inline constexpr const char* kSweepMarkerName = ".cogmap-sweep";
inline constexpr const char* kSweepMarkerText =
    "cogmap sweep output directory: its results files and plots/ are replaced by the next sweep "
    "or --merge\n";

/// An output directory a sweep or a merge must not write: not a directory, or it holds a
/// results file or plots no sweep wrote. The message names the path and what to do instead.
class SweepDirectoryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What a sweep or a merge is about to write into its output directory.
struct SweepOutputs {
  std::string results_file;  ///< results.csv or results_shard_K_of_N.csv
  std::string header;        ///< the results file's header line, or its start (run,keys,seed)
  bool plots = false;        ///< plots/ too
};

/// The start of the header line `run_sweep` writes for `spec`: run, the varied keys, seed (the
/// metric columns follow). Recognises a results file of this sweep made before the marker.
std::string results_header_start(const SweepSpec& spec);

/// Throws SweepDirectoryError unless `dir` may take `outputs` (docs/reliability.md): `dir` is a
/// directory or can be made one (no file where a folder must be), the results file is not a
/// directory or a device, and then either none of the outputs exists, or `dir` carries
/// kSweepMarkerName, or the existing results file's first line starts with `outputs.header` (the
/// same sweep, run before the marker), or `force`. A user's results.csv or plots/ in `--out` (or,
/// for --merge, the current directory) used to be replaced silently.
void check_sweep_directory(const std::filesystem::path& dir, const SweepOutputs& outputs,
                           bool force);

/// Creates `dir` and writes kSweepMarkerName into it, atomically: shards sharing a directory may
/// write it side by side.
void mark_sweep_directory(const std::filesystem::path& dir,
                          mapper::io::Durability durability = mapper::io::Durability::kSynced);

/// The results files to merge from command-line arguments: a file is taken as is; a directory
/// gives its results.csv and results_shard_*.csv (sorted). Throws std::runtime_error when an
/// argument holds none or is neither a file nor a directory (a device, a pipe).
std::vector<std::filesystem::path> results_files(const std::vector<std::filesystem::path>& args);

}  // namespace cogmap::experiments

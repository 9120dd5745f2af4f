#pragma once
/// Runs a sweep: every run (or one shard of them) in parallel threads, each run
/// single-threaded and deterministic, each in out/runs/<key=value,...,seed=N>/. A run whose
/// metrics.json exists is finished and skipped, so an interrupted sweep resumes.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/experiments/results_table.h"
#include "cogmap/experiments/sweep.h"

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

/// The results files to merge from command-line arguments: a file is taken as is; a directory
/// gives its results.csv and results_shard_*.csv (sorted). Throws std::runtime_error when an
/// argument holds none.
std::vector<std::filesystem::path> results_files(const std::vector<std::filesystem::path>& args);

}  // namespace cogmap::experiments

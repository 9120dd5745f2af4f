#pragma once
/// The run directory as a resource that must never hurt the user's files (docs/reliability.md):
/// which directories may take a run, the lock that keeps two writers out of one directory,
/// the clean-up of an interrupted run, and the experiment.yaml that makes a run re-runnable.

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/mapper/io/asr_json.h"

namespace cogmap::experiments {

/// A directory that cannot take a run: it holds an input, foreign files, or another process
/// is writing it. The message names the directory and what to do instead.
class RunDirectoryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The marker file every run directory gets first: a regular file holding kRunMarkerText makes a
/// directory ours (an empty one made by hand did too, and let a run write over a user's
/// grid_000.pgm there: fuzzing, session 56).
inline constexpr const char* kRunMarkerName = ".cogmap-run";
inline constexpr const char* kRunMarkerText = "cogmap run directory (docs/reliability.md)\n";

/// Whether `dir` holds marker file `name` as a cogmap command writes it: a regular file with
/// exactly `text` (a marker made by hand, empty or not, makes nothing ours).
bool holds_marker(const std::filesystem::path& dir, const char* name, std::string_view text);
/// The lock file (flock) of a run directory.
inline constexpr const char* kRunLockName = ".cogmap-lock";

/// `name` as one safe path component: letters, digits and `._-+=,` kept, everything else
/// (slashes, spaces, newlines, colons) becomes `_`; a leading dot becomes `_` (no hidden or
/// `..` names); empty becomes `_`; at most 100 bytes. Used for every default output path.
std::string safe_path_component(std::string_view name);

/// Whether a finished run (DIR/metrics.json) may be replaced: only when the user said so
/// (`--force`).
enum class FinishedRun { kKeep, kReplace };

/// Throws RunDirectoryError unless `dir` may take a run: it does not exist, is empty, carries
/// the run marker, or holds only files a run writes (docs/cli.md) with the run's own
/// experiment.yaml or metrics.json among them; it is not the folder of any of `inputs` (the
/// experiment file, a log), which a run would overwrite; its asrs/ and figures/ are not
/// symbolic links (a run writes and clears them); and with kKeep it holds no finished run.
void check_run_directory(const std::filesystem::path& dir,
                         const std::vector<std::filesystem::path>& inputs,
                         FinishedRun finished = FinishedRun::kKeep);

/// The nearest of `folder` and its ancestors that exists, when that one is not a directory (a
/// file in the way: the writers create missing folders, but cannot turn a file into one);
/// nullopt when the folder exists or can be created.
std::optional<std::filesystem::path> file_in_the_way(const std::filesystem::path& folder);

/// An exclusive lock on a run directory for the object's lifetime (flock on DIR/.cogmap-lock,
/// released by the kernel even after kill -9). Two threads or processes never write one
/// directory.
class RunDirectoryLock {
 public:
  /// Creates `dir` if needed and takes the lock; throws RunDirectoryError when another
  /// writer holds it or the directory cannot be made.
  explicit RunDirectoryLock(const std::filesystem::path& dir);
  ~RunDirectoryLock();
  RunDirectoryLock(const RunDirectoryLock&) = delete;
  RunDirectoryLock& operator=(const RunDirectoryLock&) = delete;

 private:
  int fd_ = -1;
};

/// Removes the products of an earlier (possibly interrupted) run from `dir`, and only those:
/// metrics.json, trajectory.csv, map*.csv, map.svg, asr_graph.json, experiment.yaml,
/// nav_trace.csv, explore_map.{pgm,yaml}, grid_NNN.{pgm,yaml}, asrs/NNN.json and the figures a
/// run draws (figures/room_NNN_stages.png, map_before_after.png, map_error.png, graph.png);
/// never through a symbolic link.
void clear_run_outputs(const std::filesystem::path& dir);

/// Makes `dir` ready for a run, under its lock: checks it (check_run_directory), writes the
/// marker, removes temp files an interrupted writer left (DIR, DIR/asrs, DIR/figures) and the
/// products of an earlier run (clear_run_outputs), then writes experiment.yaml
/// (run_experiment_yaml); both files fsynced per `durability`. Throws RunDirectoryError or
/// std::runtime_error.
void prepare_run_directory(const std::filesystem::path& dir, const Experiment& experiment,
                           mapper::io::Durability durability = mapper::io::Durability::kSynced);

/// experiment.yaml as saved in run directory `dir`: the resolved experiment, with a relative
/// `world:` rewritten relative to `dir`, so `cogmap run DIR/experiment.yaml` finds the world.
std::string run_experiment_yaml(const Experiment& experiment, const std::filesystem::path& dir);

}  // namespace cogmap::experiments

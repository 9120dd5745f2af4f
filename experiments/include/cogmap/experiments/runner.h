#pragma once
/// Runs one experiment: drives a Robot (simulated, real or replayed) through the mapper and a
/// controller, then writes the run directory of docs/formats.md (metrics.json last, so its
/// presence marks a finished run).

#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/experiments/run_metrics.h"
#include "cogmap/mapper/io/asr_json.h"
#include "cogmap/mapper/seam/robot.h"

namespace cogmap::experiments {

/// What only a simulator knows: the true surfaces and the true start pose. (True poses arrive
/// with every frame, SensorFrame::true_pose.)
struct GroundTruth {
  std::vector<mapper::Segment> surfaces;  ///< world frame
  mapper::Pose2 start_pose;               ///< world frame
};

/// How to run (as opposed to what: that is the Experiment).
struct RunOptions {
  std::filesystem::path out_dir;  ///< the run directory (created)
  std::optional<bool> figures;    ///< overrides output.figures (--no-figures)
  mapper::Pose2 start_pose;       ///< used when there is no ground truth
  /// Whether every finished room and result file is fsynced as it is written. Synced by
  /// default (drive, replay: what is lost cannot be redone); `run` and `sweep` choose kAtomic
  /// unless --fsync (docs/performance.md "Durability").
  mapper::io::Durability durability = mapper::io::Durability::kSynced;
  /// Threads that trace a simulated frame's sonar pings: 1 or 2 (a helper thread; outputs are
  /// bit-identical either way). `run` takes 2 when the process may use two cores or more; `sweep`
  /// keeps 1, as its runs already share the cores (docs/performance.md "Pings on two threads").
  int sonar_threads = 1;
  /// Called about once a simulated second with the time reached (progress bars); may be empty.
  std::function<void(double time_s, double duration_s)> on_progress;
  /// Called before the run starts with a warning about its input that does not stop it, as
  /// "FILE[:LINE]: warning: ..." (a start the walls do not enclose: docs/worlds.md); may be
  /// empty. The run and its outputs are the same either way.
  std::function<void(const std::string& warning)> on_warning;
};

/// The outcome of a finished run.
struct RunSummary {
  std::filesystem::path out_dir;
  RunMetrics metrics;
};

/// A run that started but could not finish (the robot source or a writer failed).
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Checks what only the simulator can check without running: the world file loads and the
/// `robot` block parses for robot.source `sim`. Throws yaml::ConfigError (file, line, key).
void validate_experiment(const Experiment& experiment);

/// Builds the simulated world and SimRobot from the experiment and runs it (robot.source must
/// be `sim`). Throws yaml::ConfigError for a bad world or robot block (bad input) and
/// RunError when the run itself fails.
RunSummary run_experiment(const Experiment& experiment, const RunOptions& options);

/// The loop for any Robot: each frame -> mapper -> controller -> robot.command, until
/// duration_s, the end of the robot's frames, or a finished route; then writes every output.
/// `truth` is null for real robots: the metrics that need it are then omitted.
/// Throws RunDirectoryError (run_directory.h) when options.out_dir cannot take a run, and
/// RunError when the run fails.
RunSummary run_robot_session(mapper::Robot& robot, const Experiment& experiment,
                             const GroundTruth* truth, const RunOptions& options);

}  // namespace cogmap::experiments
